// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/index_map.h"

#include <sstream>

namespace contact_app {

IndexType IndexMap::GetEntityId(IndexType master_id) const {
    const auto found = mPairs.find(master_id);
    return found == mPairs.end() ? 0 : found->second;
}

std::string IndexMap::Info() const {
    std::ostringstream out;
    out << "{";
    const char* separator = "";
    for (const auto& [master, condition] : mPairs) {
        out << separator << master << ": " << condition;
        separator = ", ";
    }
    out << "}";
    return out.str();
}

}  // namespace contact_app
