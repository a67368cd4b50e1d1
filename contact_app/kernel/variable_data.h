// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "contact_app/kernel/types.h"

namespace contact_app {

/// Value kinds a variable can hold; the names are the Kratos Python type strings.
enum class VariableType { Bool, Integer, Double, Array, Vector, Matrix, String, Component, Pointer };

/// Kratos-style type name ("Double", "Array", ...) of a variable kind.
const char* VariableTypeName(VariableType type);

/// Type-erased part of a variable: name, key, kind and, for components, the source 3-vector.
/// Every variable registers itself at construction in the VariableRegistry; keys are dense
/// (0, 1, 2, ...) so offset tables can be plain arrays indexed by key.
class VariableData {
public:
    VariableData(const VariableData&) = delete;
    VariableData& operator=(const VariableData&) = delete;
    virtual ~VariableData() = default;

    const std::string& Name() const { return mName; }
    std::size_t Key() const { return mKey; }
    VariableType Type() const { return mType; }
    /// True for DISPLACEMENT_X-like variables that view one component of a 3-vector variable.
    bool IsComponent() const { return mSource != nullptr; }
    /// The 3-vector a component belongs to (nullptr if not a component).
    const VariableData* SourceVariable() const { return mSource; }
    /// Component index 0..2 (0 if not a component).
    int ComponentIndex() const { return mComponent; }
    /// Number of doubles the variable occupies in historical storage (0: not storable there).
    std::size_t HistoricalSize() const;

    bool operator==(const VariableData& other) const { return mKey == other.mKey; }
    bool operator!=(const VariableData& other) const { return mKey != other.mKey; }

protected:
    VariableData(std::string name, VariableType type, const VariableData* source, int component);

private:
    std::string mName;
    std::size_t mKey;
    VariableType mType;
    const VariableData* mSource;
    int mComponent;
};

template <class T>
struct VariableTypeOf;
template <> struct VariableTypeOf<bool> { static constexpr VariableType value = VariableType::Bool; };
template <> struct VariableTypeOf<int> { static constexpr VariableType value = VariableType::Integer; };
template <> struct VariableTypeOf<double> { static constexpr VariableType value = VariableType::Double; };
template <> struct VariableTypeOf<Array3> { static constexpr VariableType value = VariableType::Array; };
template <> struct VariableTypeOf<Vector> { static constexpr VariableType value = VariableType::Vector; };
template <> struct VariableTypeOf<Matrix> { static constexpr VariableType value = VariableType::Matrix; };
template <> struct VariableTypeOf<std::string> { static constexpr VariableType value = VariableType::String; };
template <class U>
struct VariableTypeOf<std::shared_ptr<U>> { static constexpr VariableType value = VariableType::Pointer; };

/// A named, typed quantity (Kratos Variable<T>): DISPLACEMENT, YOUNG_MODULUS, WEIGHTED_GAP, ...
/// Instances are global constants created once; they are compared by key.
template <class T>
class Variable : public VariableData {
public:
    using ValueType = T;

    /// Creates and registers a variable. @throws InternalError if the name is already taken.
    explicit Variable(std::string name)
        : VariableData(std::move(name), VariableTypeOf<T>::value, nullptr, 0) {}

    /// Creates a component variable (only for T = double): component @p component of @p source.
    Variable(std::string name, const Variable<Array3>& source, int component)
        : VariableData(std::move(name), VariableType::Component, &source, component) {
        static_assert(std::is_same_v<T, double>, "only double variables can be components");
    }

    /// The value a missing entry reads as (zero, empty, false or null).
    const T& Zero() const {
        static const T zero = MakeZero();
        return zero;
    }

private:
    static T MakeZero() {
        if constexpr (std::is_same_v<T, Array3>) return Array3::Zero();
        else if constexpr (std::is_arithmetic_v<T>) return T(0);
        else return T();
    }
};

}  // namespace contact_app
