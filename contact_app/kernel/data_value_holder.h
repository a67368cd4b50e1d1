// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/kernel/data_value_container.h"

namespace contact_app {

/// The non-historical value interface shared by nodes, entities, properties, ProcessInfo, model
/// parts and constraints (Kratos GetValue / SetValue / Has): a DataValueContainer and its accessors.
class DataValueHolder {
public:
    /// The stored value, or the variable's zero when absent.
    template <class T>
    T GetValue(const Variable<T>& variable) const {
        return mData.GetValue(variable);
    }
    /// Reference to the stored value, inserted as zero first if absent (invalidated by later insertions).
    template <class T>
    T& GetOrCreateValue(const Variable<T>& variable) {
        return mData.GetOrCreate(variable);
    }
    template <class T>
    void SetValue(const Variable<T>& variable, const T& value) {
        mData.SetValue(variable, value);
    }
    bool Has(const VariableData& variable) const { return mData.Has(variable); }
    DataValueContainer& Data() { return mData; }
    const DataValueContainer& Data() const { return mData; }

private:
    DataValueContainer mData;
};

}  // namespace contact_app
