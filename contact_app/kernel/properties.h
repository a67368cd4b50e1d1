// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <map>
#include <memory>
#include <utility>

#include "contact_app/kernel/data_value_container.h"
#include "contact_app/kernel/table.h"

namespace contact_app {

/// Material and condition parameters shared by entities (Kratos Properties): values by
/// variable plus tables keyed by (input variable, output variable).
class Properties {
public:
    using Pointer = std::shared_ptr<Properties>;

    explicit Properties(IndexType id) : mId(id) {}

    IndexType Id() const { return mId; }

    template <class T>
    T GetValue(const Variable<T>& variable) const { return mData.GetValue(variable); }
    template <class T>
    void SetValue(const Variable<T>& variable, const T& value) { mData.SetValue(variable, value); }
    bool Has(const VariableData& variable) const { return mData.Has(variable); }
    /// The value, or an InputError saying which property set lacks which variable.
    template <class T>
    T GetChecked(const Variable<T>& variable) const {
        if (!mData.Has(variable)) ThrowMissing(variable);
        return mData.GetValue(variable);
    }
    DataValueContainer& Data() { return mData; }
    const DataValueContainer& Data() const { return mData; }

    void SetTable(const VariableData& input, const VariableData& output, Table table);
    bool HasTable(const VariableData& input, const VariableData& output) const;
    /// @throws InputError if there is no such table.
    const Table& GetTable(const VariableData& input, const VariableData& output) const;
    std::size_t NumberOfTables() const { return mTables.size(); }

private:
    [[noreturn]] void ThrowMissing(const VariableData& variable) const;

    IndexType mId;
    DataValueContainer mData;
    std::map<std::pair<std::size_t, std::size_t>, Table> mTables;
};

}  // namespace contact_app
