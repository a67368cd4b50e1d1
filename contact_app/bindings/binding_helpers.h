// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "contact_app/kernel/entity_container.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/variable_data.h"

namespace contact_app::bindings {

namespace py = pybind11;

/// The Python object of a registered variable: its typed class (DoubleVariable, ...) or, for
/// pointer variables, the VariableData base. Variables are static globals: no ownership.
py::object VariableObject(const VariableData& variable);

/// @throws InputError: @p variable holds a C++ object (pointer variables) that Python cannot read or write.
[[noreturn]] void ThrowNotConvertible(const VariableData& variable);

/// Read-only view of a model part container (mp.Nodes, ...); the property keeps the model part alive. Functions
/// that take one directly (VariableUtils.SetFlag) loop in C++ instead of over a Python iterable.
template <class T>
struct ContainerView {
    const EntityContainer<T>* container;
};

/// Python list of non-owned references, each keeping @p parent (their owner) alive.
template <class T>
py::list ReferenceList(const std::vector<T*>& items, py::handle parent) {
    py::list result;
    for (T* item : items) result.append(py::cast(item, py::return_value_policy::reference_internal, parent));
    return result;
}

/// Identity comparison for entities (overrides the value comparison inherited from Flags).
template <class TPyClass>
void DefIdentity(TPyClass& cls) {
    using Owner = typename TPyClass::type;
    cls.def(
        "__eq__", [](const Owner& self, const Owner& other) { return &self == &other; }, py::is_operator(),
        "Same C++ object.");
    cls.def(
        "__hash__", [](const Owner& self) { return std::hash<const void*>()(&self); }, "Hash of the address.");
}

/// GetValue / SetValue (and, with @p with_items, `obj[var]` / `obj[var] = value`) for Variable<T>.
template <class T, class TPyClass>
void DefTypedValueAccess(TPyClass& cls, bool with_items) {
    using Owner = typename TPyClass::type;
    auto get = [](const Owner& self, const Variable<T>& variable) -> T { return self.GetValue(variable); };
    auto set = [](Owner& self, const Variable<T>& variable, const T& value) { self.SetValue(variable, value); };
    cls.def("GetValue", get, py::arg("variable"), "Stored value of the variable (its zero when unset).");
    cls.def("SetValue", set, py::arg("variable"), py::arg("value"), "Stores a value for the variable.");
    if (with_items) {
        cls.def("__getitem__", get, py::arg("variable"), "Same as GetValue(variable).");
        cls.def("__setitem__", set, py::arg("variable"), py::arg("value"), "Same as SetValue(variable, value).");
    }
}

/// Typed non-historical value access for every variable class, plus Has(var), on a class whose C++
/// type has templated GetValue/SetValue/Has (Node, Properties, ProcessInfo, Element, ModelPart, ...).
/// One overload per variable class; pointer variables raise InputError.
template <class TPyClass>
void DefValueAccess(TPyClass& cls, bool with_items = false) {
    using Owner = typename TPyClass::type;
    DefTypedValueAccess<bool>(cls, with_items);
    DefTypedValueAccess<int>(cls, with_items);
    DefTypedValueAccess<double>(cls, with_items);
    DefTypedValueAccess<Array3>(cls, with_items);
    DefTypedValueAccess<Vector>(cls, with_items);
    DefTypedValueAccess<Matrix>(cls, with_items);
    DefTypedValueAccess<std::string>(cls, with_items);
    auto unsupported = [](const Owner&, const VariableData& variable) { ThrowNotConvertible(variable); };
    cls.def("GetValue", unsupported, py::arg("variable"), "Pointer variables cannot be read from Python.");
    cls.def(
        "Has", [](const Owner& self, const VariableData& variable) { return self.Has(variable); }, py::arg("variable"),
        "True if a value is stored for the variable.");
    if (with_items) {
        cls.def("__getitem__", unsupported, py::arg("variable"), "Pointer variables cannot be read from Python.");
        cls.def(
            "__contains__", [](const Owner& self, const VariableData& variable) { return self.Has(variable); },
            py::arg("variable"), "Same as Has(variable).");
    }
}

}  // namespace contact_app::bindings
