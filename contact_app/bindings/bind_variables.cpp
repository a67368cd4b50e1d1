// SPDX-License-Identifier: BSD-3-Clause
#include <memory>
#include <string>

#include "contact_app/bindings/binding_helpers.h"
#include "contact_app/bindings/bindings.h"
#include "contact_app/kernel/constitutive_law.h"
#include "contact_app/kernel/variables.h"
#include "contact_app/kernel/variable_registry.h"

namespace contact_app::bindings {

namespace {

template <class T>
using NoDelete = std::unique_ptr<T, py::nodelete>;

template <class T>
void BindVariableClass(py::module_& m, const char* name, const char* doc) {
    py::class_<Variable<T>, VariableData, NoDelete<Variable<T>>>(m, name, doc)
        .def(
            "Zero", [](const Variable<T>& self) { return self.Zero(); }, "The value an unset entry reads as.");
}

template <class T>
py::object Typed(const VariableData& variable) {
    return py::cast(static_cast<const Variable<T>*>(&variable), py::return_value_policy::reference);
}

}  // namespace

py::object VariableObject(const VariableData& variable) {
    switch (variable.Type()) {
        case VariableType::Bool:
            return Typed<bool>(variable);
        case VariableType::Integer:
            return Typed<int>(variable);
        case VariableType::Double:
        case VariableType::Component:
            return Typed<double>(variable);
        case VariableType::Array:
            return Typed<Array3>(variable);
        case VariableType::Vector:
            return Typed<Vector>(variable);
        case VariableType::Matrix:
            return Typed<Matrix>(variable);
        case VariableType::String:
            return Typed<std::string>(variable);
        case VariableType::Pointer:
            if (variable == CONSTITUTIVE_LAW) return Typed<std::shared_ptr<ConstitutiveLaw>>(variable);
            break;
    }
    // Pointer variables: the polymorphic cast falls back to the registered base, VariableData.
    return py::cast(&variable, py::return_value_policy::reference);
}

void ThrowNotConvertible(const VariableData& variable) {
    CONTACT_THROW(InputError, "variable ", variable.Name(), " of type ", VariableTypeName(variable.Type()),
                  " holds a C++ object and cannot be read or written from Python",
                  "\n  expected: a Bool, Integer, Double, Component, Array, Vector, Matrix or String variable");
}

void BindVariables(py::module_& m) {
    py::class_<VariableData, NoDelete<VariableData>>(m, "VariableData", "Type-erased part of a variable.")
        .def("Name", &VariableData::Name, "The Kratos name, e.g. \"DISPLACEMENT_X\".")
        .def("Key", &VariableData::Key, "Dense registry key (0, 1, 2, ...).")
        .def(
            "Type", [](const VariableData& self) { return VariableTypeName(self.Type()); },
            "Kratos type string: Bool, Integer, Double, Component, Array, Vector, Matrix, String, Pointer.")
        .def("IsComponent", &VariableData::IsComponent, "True for DISPLACEMENT_X-like component variables.")
        .def(
            "GetSourceVariable",
            [](const VariableData& self) {
                return self.IsComponent() ? VariableObject(*self.SourceVariable()) : py::none();
            },
            "The 3-vector variable of a component (None otherwise).")
        .def("GetComponentIndex", &VariableData::ComponentIndex, "Component index 0..2 (0 if not a component).")
        .def(
            "__eq__", [](const VariableData& self, const VariableData& other) { return self == other; },
            py::is_operator(), "Variables compare by key.")
        .def(
            "__hash__", [](const VariableData& self) { return self.Key(); }, "Hash of the key.")
        .def("__str__", &VariableData::Name, "The name.")
        .def(
            "__repr__",
            [](py::handle self) {
                return py::str("<{} {}>").format(py::type::of(self).attr("__name__"),
                                                 self.cast<const VariableData&>().Name());
            },
            "<DoubleVariable YOUNG_MODULUS>.");
    BindVariableClass<bool>(m, "BoolVariable", "A bool variable (Kratos Variable<bool>).");
    BindVariableClass<int>(m, "IntegerVariable", "An int variable (Kratos Variable<int>).");
    BindVariableClass<double>(m, "DoubleVariable", "A double variable or a component (DISPLACEMENT_X).");
    BindVariableClass<Array3>(m, "Array1DVariable3", "A 3-vector variable (Kratos Variable<array_1d<double,3>>).");
    BindVariableClass<Vector>(m, "VectorVariable", "A vector variable (Kratos Variable<Vector>).");
    BindVariableClass<Matrix>(m, "MatrixVariable", "A matrix variable (Kratos Variable<Matrix>).");
    BindVariableClass<std::string>(m, "StringVariable", "A string variable (Kratos Variable<std::string>).");
    py::class_<Variable<std::shared_ptr<ConstitutiveLaw>>, VariableData,
               NoDelete<Variable<std::shared_ptr<ConstitutiveLaw>>>>(
        m, "ConstitutiveLawVariable", "The CONSTITUTIVE_LAW variable (holds a law object in Properties).");

    const VariableRegistry& registry = VariableRegistry::Instance();
    for (std::size_t key = 0; key < registry.Size(); ++key) {
        const VariableData& variable = registry.ByKey(key);
        m.attr(variable.Name().c_str()) = VariableObject(variable);
    }
    m.def(
        "get_variable",
        [](const std::string& name) {
            try {
                return VariableObject(VariableRegistry::Instance().Get(name));
            } catch (const InputError& error) {
                throw py::key_error(error.what());
            }
        },
        py::arg("name"), "The variable called name; KeyError (with a suggestion) for an unknown name.");
    m.def(
        "registered_variables", [] { return VariableRegistry::Instance().Names(); },
        "Sorted names of every registered variable.");
}

}  // namespace contact_app::bindings
