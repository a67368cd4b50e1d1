// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/variable_data.h"

namespace contact_app {

/// Non-historical values of an entity (Kratos DataValueContainer): a small flat map from
/// variable to value, searched linearly (entities hold a handful of values).
/// A missing variable reads as its zero value. Component variables (DISPLACEMENT_X) read and
/// write one component of their 3-vector.
class DataValueContainer {
public:
    using Value = std::variant<bool, int, double, Array3, Vector, Matrix, std::string, std::shared_ptr<void>>;

    template <class T>
    bool Has(const Variable<T>& variable) const {
        return Find(variable.IsComponent() ? *variable.SourceVariable() : variable) != nullptr;
    }
    bool Has(const VariableData& variable) const {
        return Find(variable.IsComponent() ? *variable.SourceVariable() : variable) != nullptr;
    }

    /// The stored value, or the variable's zero if absent.
    template <class T>
    T GetValue(const Variable<T>& variable) const {
        if constexpr (std::is_same_v<T, double>) {
            if (variable.IsComponent()) {
                const Value* value = Find(*variable.SourceVariable());
                if (value == nullptr) return 0.0;
                return std::get<Array3>(*value)[variable.ComponentIndex()];
            }
        }
        const Value* value = Find(variable);
        if (value == nullptr) return variable.Zero();
        if constexpr (VariableTypeOf<T>::value == VariableType::Pointer) {
            return std::static_pointer_cast<typename T::element_type>(std::get<std::shared_ptr<void>>(*value));
        } else {
            return std::get<T>(*value);
        }
    }

    /// Reference to the stored value, inserting the zero value first if absent.
    template <class T>
    T& GetOrCreate(const Variable<T>& variable) {
        static_assert(VariableTypeOf<T>::value != VariableType::Pointer, "use GetValue for pointers");
        if (variable.IsComponent()) {
            if constexpr (std::is_same_v<T, double>) {
                const auto& source = static_cast<const Variable<Array3>&>(*variable.SourceVariable());
                return GetOrCreate(source)[variable.ComponentIndex()];
            }
        }
        Value* value = Find(variable);
        if (value == nullptr) {
            mData.emplace_back(&variable, Value(variable.Zero()));
            value = &mData.back().second;
        }
        return std::get<T>(*value);
    }

    template <class T>
    void SetValue(const Variable<T>& variable, const T& new_value) {
        if constexpr (VariableTypeOf<T>::value == VariableType::Pointer) {
            Value* value = Find(variable);
            if (value == nullptr) mData.emplace_back(&variable, Value(std::shared_ptr<void>(new_value)));
            else *value = std::shared_ptr<void>(new_value);
        } else {
            GetOrCreate(variable) = new_value;
        }
    }

    /// Removes the value (a component erases its whole 3-vector).
    void Erase(const VariableData& variable);
    void Clear() { mData.clear(); }
    std::size_t Size() const { return mData.size(); }
    /// The stored (variable, value) pairs in insertion order.
    const std::vector<std::pair<const VariableData*, Value>>& Data() const { return mData; }

private:
    const Value* Find(const VariableData& variable) const;
    Value* Find(const VariableData& variable);

    std::vector<std::pair<const VariableData*, Value>> mData;
};

}  // namespace contact_app
