// SPDX-License-Identifier: BSD-3-Clause
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "contact_app/bindings/binding_helpers.h"
#include "contact_app/bindings/bindings.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/node.h"

namespace contact_app::bindings {

namespace {

using NodeClass = py::class_<Node, Flags, std::shared_ptr<Node>>;

/// @p value if finite; InputError naming the node and the coordinate otherwise (a NaN coordinate
/// would surface much later as a zero normal or a singular system).
double FiniteCoordinate(double value, IndexType id, const char* which) {
    CONTACT_CHECK(std::isfinite(value), InputError, "coordinate ", which, " of node ", id, " set to ", value,
                  "\n  expected: a finite number\n  fix:      check how the coordinate was computed");
    return value;
}

Array3 FiniteCoordinates(const Array3& value, IndexType id, const char* which) {
    CONTACT_CHECK(value.allFinite(), InputError, which, " of node ", id, " set to (", value[0], ", ", value[1], ", ",
                  value[2], ")\n  expected: finite numbers\n  fix:      check how the coordinates were computed");
    return value;
}

/// Historical get/set for a variable class the step buffer stores (double, component, 3-vector).
template <class T>
void DefSolutionStepAccess(NodeClass& cls) {
    cls.def(
        "GetSolutionStepValue",
        [](Node& self, const Variable<T>& variable, std::size_t step) -> T {
            return self.GetSolutionStepValue(variable, step);
        },
        py::arg("variable"), py::arg("step") = 0, "Historical value at buffer step (0: current step).");
    cls.def(
        "SetSolutionStepValue",
        [](Node& self, const Variable<T>& variable, std::size_t step, const T& value) {
            self.GetSolutionStepValue(variable, step) = value;
        },
        py::arg("variable"), py::arg("step"), py::arg("value"), "Sets the historical value at buffer step.");
    cls.def(
        "SetSolutionStepValue",
        [](Node& self, const Variable<T>& variable, const T& value) { self.GetSolutionStepValue(variable) = value; },
        py::arg("variable"), py::arg("value"), "Sets the historical value of the current step.");
}

[[noreturn]] void ThrowNotHistorical(const VariableData& variable) {
    CONTACT_THROW(InputError, "variable ", variable.Name(), " of type ", VariableTypeName(variable.Type()),
                  " cannot be stored as a solution-step (historical) value",
                  "\n  expected: a Double, Component or Array variable",
                  "\n  fix:      use GetValue/SetValue (non-historical) for it");
}

/// Fallback of SetSolutionStepValue, reached when no typed overload matched without conversion:
/// converts the value for the variable's kind (list -> 3-vector, int -> float) or raises.
void SetHistoricalConverted(Node& node, const VariableData& variable, std::size_t step, py::handle value) {
    try {
        switch (variable.Type()) {
            case VariableType::Double:
            case VariableType::Component:
                node.GetSolutionStepValue(static_cast<const Variable<double>&>(variable), step) = value.cast<double>();
                return;
            case VariableType::Array:
                node.GetSolutionStepValue(static_cast<const Variable<Array3>&>(variable), step) = value.cast<Array3>();
                return;
            default:
                ThrowNotHistorical(variable);
        }
    } catch (const py::cast_error&) {
        throw py::type_error(py::str("variable {} of type {} cannot take the value {!r}")
                                 .format(variable.Name(), VariableTypeName(variable.Type()), value));
    }
}

std::string NodeRepr(const Node& node) {
    return py::str("<Node {} at ({}, {}, {})>").format(node.Id(), node.X(), node.Y(), node.Z());
}

void BindDof(py::module_& m) {
    py::class_<Dof, std::unique_ptr<Dof, py::nodelete>>(m, "Dof", "A degree of freedom of a node (owned by it).")
        .def("Id", &Dof::Id, "Id of the owning node.")
        .def("GetVariable", &Dof::GetVariable, py::return_value_policy::reference, "The unknown (DISPLACEMENT_X).")
        .def("HasReaction", &Dof::HasReaction, "True if a reaction variable is set.")
        .def("GetReaction", &Dof::GetReaction, py::return_value_policy::reference,
             "The reaction variable (REACTION_X).")
        .def_property("EquationId", &Dof::EquationId, &Dof::SetEquationId, "Row of the DoF in the global system.")
        .def("IsFixed", &Dof::IsFixed, "True if fixed.")
        .def("IsFree", &Dof::IsFree, "True if free.")
        .def("Fix", &Dof::FixDof, "Fixes the DoF.")
        .def("Free", &Dof::FreeDof, "Frees the DoF.")
        .def(
            "GetSolutionStepValue", [](const Dof& self, std::size_t step) { return self.GetSolutionStepValue(step); },
            py::arg("step") = 0, "Value of the unknown at buffer step.")
        .def(
            "GetSolutionStepReactionValue",
            [](Dof& self, std::size_t step) { return self.GetSolutionStepReactionValue(step); }, py::arg("step") = 0,
            "Value of the reaction at buffer step.")
        .def(
            "__repr__",
            [](const Dof& self) {
                return py::str("<Dof {} of node {}{}>")
                    .format(self.GetVariable().Name(), self.Id(), self.IsFixed() ? " (fixed)" : "");
            },
            "<Dof DISPLACEMENT_X of node 3 (fixed)>.");
}

}  // namespace

void BindNode(py::module_& m) {
    BindDof(m);
    NodeClass node(m, "Node",
                   "A mesh node (Kratos Node): coordinates, flags, historical and non-historical data, DoFs.",
                   py::multiple_inheritance());
    node.def(py::init([](IndexType id, double x, double y, double z) {
                 return std::make_shared<Node>(id, FiniteCoordinate(x, id, "x"), FiniteCoordinate(y, id, "y"),
                                               FiniteCoordinate(z, id, "z"));
             }),
             py::arg("id"), py::arg("x"), py::arg("y"), py::arg("z"),
             "A free node without historical data (use ModelPart.CreateNewNode for a mesh node).")
        .def_property_readonly("Id", &Node::Id, "Node id.")
        .def_property(
            "X", &Node::X, [](Node& self, double value) { self.Coordinates()[0] = FiniteCoordinate(value, self.Id(), "x"); }, "Current x.")
        .def_property(
            "Y", &Node::Y, [](Node& self, double value) { self.Coordinates()[1] = FiniteCoordinate(value, self.Id(), "y"); }, "Current y.")
        .def_property(
            "Z", &Node::Z, [](Node& self, double value) { self.Coordinates()[2] = FiniteCoordinate(value, self.Id(), "z"); }, "Current z.")
        .def_property(
            "X0", &Node::X0, [](Node& self, double value) { self.InitialCoordinates()[0] = FiniteCoordinate(value, self.Id(), "x0"); }, "Initial x.")
        .def_property(
            "Y0", &Node::Y0, [](Node& self, double value) { self.InitialCoordinates()[1] = FiniteCoordinate(value, self.Id(), "y0"); }, "Initial y.")
        .def_property(
            "Z0", &Node::Z0, [](Node& self, double value) { self.InitialCoordinates()[2] = FiniteCoordinate(value, self.Id(), "z0"); }, "Initial z.")
        .def(
            "Coordinates", [](const Node& self) -> Array3 { return self.Coordinates(); },
            "Copy of the current coordinates.")
        .def(
            "InitialCoordinates", [](const Node& self) -> Array3 { return self.InitialCoordinates(); },
            "Copy of the initial coordinates.")
        .def(
            "SetCoordinates", [](Node& self, const Array3& value) { self.Coordinates() = FiniteCoordinates(value, self.Id(), "coordinates"); },
            py::arg("coordinates"), "Sets the current coordinates.")
        .def(
            "SetInitialCoordinates", [](Node& self, const Array3& value) {
                self.InitialCoordinates() = FiniteCoordinates(value, self.Id(), "initial coordinates");
            },
            py::arg("coordinates"), "Sets the initial coordinates.");

    DefSolutionStepAccess<double>(node);
    DefSolutionStepAccess<Array3>(node);
    // Fallbacks, tried last: other variable kinds, or a value of the wrong type.
    node.def(
            "GetSolutionStepValue",
            [](Node&, const VariableData& variable, std::size_t) { ThrowNotHistorical(variable); }, py::arg("variable"),
            py::arg("step") = 0, "Other variable kinds are not historical.")
        .def("SetSolutionStepValue", &SetHistoricalConverted, py::arg("variable"), py::arg("step"), py::arg("value"),
             "Sets the historical value at buffer step, converting the value.")
        .def(
            "SetSolutionStepValue",
            [](Node& self, const VariableData& variable, py::handle value) {
                SetHistoricalConverted(self, variable, 0, value);
            },
            py::arg("variable"), py::arg("value"),
            "Sets the historical value of the current step, converting the value.")
        .def("SolutionStepsDataHas", &Node::SolutionStepsDataHas, py::arg("variable"),
             "True if the variable is a historical variable of the node.")
        .def("GetBufferSize", &Node::GetBufferSize, "Number of buffer steps.")
        .def("CloneSolutionStep", &Node::CloneSolutionStep, "Shifts the buffer: step 0 is copied into a new step 0.");
    DefValueAccess(node);

    node.def(
            "AddDof",
            [](Node& self, const Variable<double>& variable, const Variable<double>& reaction) -> Dof& {
                return self.AddDof(variable, reaction);
            },
            py::arg("variable"), py::arg("reaction"), py::return_value_policy::reference_internal,
            "Adds (or returns) the DoF of variable with its reaction variable.")
        .def(
            "AddDof", [](Node& self, const Variable<double>& variable) -> Dof& { return self.AddDof(variable); },
            py::arg("variable"), py::return_value_policy::reference_internal, "Adds (or returns) the DoF of variable.")
        .def("HasDofFor", &Node::HasDofFor, py::arg("variable"), "True if the node has a DoF for variable.")
        .def("GetDof", &Node::GetDof, py::arg("variable"), py::return_value_policy::reference_internal,
             "The DoF of variable; InputError if there is none.")
        .def(
            "GetDofs",
            [](py::object self) {
                std::vector<Dof*> dofs;
                for (const auto& dof : self.cast<const Node&>().GetDofs()) dofs.push_back(dof.get());
                return ReferenceList(dofs, self);
            },
            "Every DoF of the node, in insertion order.")
        .def("Fix", &Node::Fix, py::arg("variable"), "Fixes the DoF of variable (adding it if needed).")
        .def("Free", &Node::Free, py::arg("variable"), "Frees the DoF of variable; InputError if there is none.")
        .def("IsFixed", &Node::IsFixed, py::arg("variable"), "True if the DoF of variable exists and is fixed.")
        .def("__repr__", &NodeRepr, "<Node 3 at (x, y, z)>.");
    DefIdentity(node);
}

}  // namespace contact_app::bindings
