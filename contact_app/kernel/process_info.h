// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>

#include "contact_app/kernel/data_value_container.h"
#include "contact_app/kernel/flags.h"

namespace contact_app {

/// Global values of an analysis (Kratos ProcessInfo): TIME, DELTA_TIME, STEP, solver switches.
/// One instance per root model part, shared by its sub model parts.
class ProcessInfo : public Flags {
public:
    using Pointer = std::shared_ptr<ProcessInfo>;

    template <class T>
    T GetValue(const Variable<T>& variable) const { return mData.GetValue(variable); }
    template <class T>
    T& GetOrCreateValue(const Variable<T>& variable) { return mData.GetOrCreate(variable); }
    template <class T>
    void SetValue(const Variable<T>& variable, const T& value) { mData.SetValue(variable, value); }
    bool Has(const VariableData& variable) const { return mData.Has(variable); }
    DataValueContainer& Data() { return mData; }
    const DataValueContainer& Data() const { return mData; }

private:
    DataValueContainer mData;
};

}  // namespace contact_app
