// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/properties.h"

namespace contact_app {

void Properties::SetTable(const VariableData& input, const VariableData& output, Table table) {
    mTables[{input.Key(), output.Key()}] = std::move(table);
}

bool Properties::HasTable(const VariableData& input, const VariableData& output) const {
    return mTables.count({input.Key(), output.Key()}) != 0;
}

const Table& Properties::GetTable(const VariableData& input, const VariableData& output) const {
    const auto found = mTables.find({input.Key(), output.Key()});
    CONTACT_CHECK(found != mTables.end(), InputError, "properties ", mId, " have no table ", input.Name(), " -> ",
                  output.Name(), "\n  fix: add it in the materials file or in a Begin Table block of the mdpa");
    return found->second;
}

void Properties::ThrowMissing(const VariableData& variable) const {
    CONTACT_THROW(InputError, "properties ", mId, " have no value for ", variable.Name(),
                  "\n  fix: set ", variable.Name(), " in the materials file (\"Variables\" block of this property)");
}

}  // namespace contact_app
