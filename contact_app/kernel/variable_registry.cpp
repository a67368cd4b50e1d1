// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/variable_registry.h"

#include <algorithm>

#include "contact_app/kernel/string_utilities.h"

namespace contact_app {

VariableRegistry& VariableRegistry::Instance() {
    static VariableRegistry registry;
    return registry;
}

std::size_t VariableRegistry::Add(const VariableData& variable) {
    CONTACT_CHECK(mByName.count(variable.Name()) == 0, InternalError, "variable ", variable.Name(),
                  " is defined twice");
    mByName.emplace(variable.Name(), &variable);
    mByKey.push_back(&variable);
    return mByKey.size() - 1;
}

bool VariableRegistry::Has(const std::string& name) const { return mByName.count(name) != 0; }

const VariableData& VariableRegistry::Get(const std::string& name) const {
    const auto found = mByName.find(name);
    if (found == mByName.end()) {
        CONTACT_THROW(InputError, "unknown variable \"", name, "\"", DidYouMean(name, Names()),
                      "\n  expected: a registered Kratos variable name such as DISPLACEMENT or WEIGHTED_GAP");
    }
    return *found->second;
}

std::vector<std::string> VariableRegistry::Names() const {
    std::vector<std::string> names;
    names.reserve(mByName.size());
    for (const auto& entry : mByName) names.push_back(entry.first);
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace contact_app
