// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <algorithm>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/string_utilities.h"

namespace contact_app {

/// Prototypes by registered name (Kratos KratosComponents<T>): elements, conditions,
/// constraints and constitutive laws are created by cloning the prototype of their name.
/// @tparam T Element, Condition, MasterSlaveConstraint or ConstitutiveLaw.
template <class T>
class Registry {
public:
    static Registry& Instance() {
        static Registry registry;
        return registry;
    }

    /// Registers @p prototype under @p name. @throws InternalError if the name is taken.
    void Add(const std::string& name, std::shared_ptr<const T> prototype) {
        CONTACT_CHECK(mPrototypes.count(name) == 0, InternalError, KindName(), " ", name, " is registered twice");
        mPrototypes.emplace(name, std::move(prototype));
    }
    bool Has(const std::string& name) const { return mPrototypes.count(name) != 0; }
    /// @throws InputError naming the unknown name and the closest registered ones.
    const T& Get(const std::string& name) const {
        const auto found = mPrototypes.find(name);
        if (found == mPrototypes.end()) {
            CONTACT_THROW(InputError, "unknown ", KindName(), " \"", name, "\"", DidYouMean(name, Names()),
                          "\n  expected: one of the ", mPrototypes.size(), " registered ", KindName(),
                          " names (contact_app.registered_", KindName(), "s() lists them)");
        }
        return *found->second;
    }
    /// All registered names, sorted.
    std::vector<std::string> Names() const {
        std::vector<std::string> names;
        names.reserve(mPrototypes.size());
        for (const auto& entry : mPrototypes) names.push_back(entry.first);
        return names;
    }
private:
    Registry() = default;
    static const char* KindName();

    std::map<std::string, std::shared_ptr<const T>> mPrototypes;
};

class Element;
class Condition;
class MasterSlaveConstraint;
class ConstitutiveLaw;
template <> inline const char* Registry<Element>::KindName() { return "element"; }
template <> inline const char* Registry<Condition>::KindName() { return "condition"; }
template <> inline const char* Registry<MasterSlaveConstraint>::KindName() { return "constraint"; }
template <> inline const char* Registry<ConstitutiveLaw>::KindName() { return "constitutive_law"; }

/// Registers the kernel's geometry-only elements and conditions (Element2D3N, LineCondition2D2N, ...)
/// and LinearMasterSlaveConstraint. Idempotent.
void RegisterKernelEntities();

}  // namespace contact_app
