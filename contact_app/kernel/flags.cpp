// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/flags.h"

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/string_utilities.h"

namespace contact_app {

const std::vector<NamedFlag>& RegisteredFlags() {
#define CONTACT_APP_NAMED_FLAG(name, bit) NamedFlag{#name, name},
    static const std::vector<NamedFlag> flags{CONTACT_APP_FLAGS(CONTACT_APP_NAMED_FLAG)};
#undef CONTACT_APP_NAMED_FLAG
    return flags;
}

Flags GetFlag(const std::string& name) {
    std::vector<std::string> names;
    for (const NamedFlag& entry : RegisteredFlags()) {
        if (name == entry.name) return entry.flag;
        names.emplace_back(entry.name);
    }
    CONTACT_THROW(InputError, "unknown flag \"", name, "\"", DidYouMean(name, names),
                  "\n  expected: a Kratos flag name such as ACTIVE, SLIP, SLAVE or MASTER");
}

}  // namespace contact_app
