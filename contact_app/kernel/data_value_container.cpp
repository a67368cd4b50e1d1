// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/data_value_container.h"

#include <algorithm>

namespace contact_app {

const DataValueContainer::Value* DataValueContainer::Find(const VariableData& variable) const {
    for (const auto& entry : mData)
        if (entry.first->Key() == variable.Key()) return &entry.second;
    return nullptr;
}

DataValueContainer::Value* DataValueContainer::Find(const VariableData& variable) {
    for (auto& entry : mData)
        if (entry.first->Key() == variable.Key()) return &entry.second;
    return nullptr;
}

void DataValueContainer::Erase(const VariableData& variable) {
    const VariableData& target = variable.IsComponent() ? *variable.SourceVariable() : variable;
    mData.erase(std::remove_if(mData.begin(), mData.end(),
                               [&](const auto& entry) { return entry.first->Key() == target.Key(); }),
                mData.end());
}

}  // namespace contact_app
