// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <map>
#include <memory>
#include <utility>

#include "contact_app/kernel/data_value_holder.h"
#include "contact_app/kernel/table.h"

namespace contact_app {

/// Material and condition parameters shared by entities (Kratos Properties): values by
/// variable plus tables keyed by (input variable, output variable).
class Properties : public DataValueHolder {
public:
    using Pointer = std::shared_ptr<Properties>;

    explicit Properties(IndexType id) : mId(id) {}

    IndexType Id() const { return mId; }

    /// The value, or an InputError saying which property set lacks which variable.
    template <class T>
    T GetChecked(const Variable<T>& variable) const {
        if (!Has(variable)) ThrowMissing(variable);
        return GetValue(variable);
    }

    void SetTable(const VariableData& input, const VariableData& output, Table table);
    bool HasTable(const VariableData& input, const VariableData& output) const;
    /// @throws InputError if there is no such table.
    const Table& GetTable(const VariableData& input, const VariableData& output) const;
    std::size_t NumberOfTables() const { return mTables.size(); }

private:
    [[noreturn]] void ThrowMissing(const VariableData& variable) const;

    IndexType mId;
    std::map<std::pair<std::size_t, std::size_t>, Table> mTables;
};

}  // namespace contact_app
