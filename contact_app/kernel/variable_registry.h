// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/variable_data.h"

namespace contact_app {

/// Every variable by name (Kratos KratosComponents<VariableData>). Filled by the variable
/// constructors, so it is complete once the kernel and the application are linked in.
class VariableRegistry {
public:
    static VariableRegistry& Instance();

    /// Assigns the next key to @p variable. @throws InternalError on a duplicate name.
    std::size_t Add(const VariableData& variable);

    bool Has(const std::string& name) const;
    /// @throws InputError naming the unknown variable with the closest registered names.
    const VariableData& Get(const std::string& name) const;
    /// As Get, also checking the kind. @throws InputError if the variable is not a Variable<T>.
    template <class T>
    const Variable<T>& GetTyped(const std::string& name) const {
        const VariableData& data = Get(name);
        const bool match = data.Type() == VariableTypeOf<T>::value ||
                           (std::is_same_v<T, double> && data.Type() == VariableType::Component);
        CONTACT_CHECK(match, InputError, "variable ", name, " is of type ", VariableTypeName(data.Type()),
                      ", expected type ", VariableTypeName(VariableTypeOf<T>::value));
        return static_cast<const Variable<T>&>(data);
    }
    /// The variable with key @p key (keys run 0..Size()-1).
    const VariableData& ByKey(std::size_t key) const { return *mByKey[key]; }
    std::size_t Size() const { return mByKey.size(); }
    /// All names, sorted.
    std::vector<std::string> Names() const;

private:
    VariableRegistry() = default;
    std::unordered_map<std::string, const VariableData*> mByName;
    std::vector<const VariableData*> mByKey;
};

}  // namespace contact_app
