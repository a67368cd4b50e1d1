// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/bindings/binding_helpers.h"
#include "contact_app/bindings/bindings.h"
#include "contact_app/kernel/model_part.h"
#include "contact_app/kernel/node.h"
#include "contact_app/kernel/variables.h"

namespace contact_app::bindings {

namespace {

/// Stateless holder of nodal helpers (Kratos VariableUtils).
struct VariableUtils {};

}  // namespace

void BindUtilities(py::module_& m) {
    py::class_<VariableUtils>(m, "VariableUtils", "Nodal helpers (Kratos VariableUtils).")
        .def(py::init<>(), "The helpers.")
        .def(
            "UpdateCurrentPosition",
            [](const VariableUtils&, py::iterable nodes, const Variable<Array3>& variable, std::size_t step) {
                for (py::handle item : nodes) {
                    Node& node = item.cast<Node&>();
                    node.Coordinates() = node.InitialCoordinates() + node.GetSolutionStepValue(variable, step);
                }
            },
            py::arg("nodes"), py::arg("variable") = VariableObject(DISPLACEMENT), py::arg("buffer_step") = 0,
            "Current coordinates = initial + historical variable (DISPLACEMENT) for every node of the iterable.")
        .def(
            "SetFlag",
            [](const VariableUtils&, const Flags& flag, bool value, py::iterable entities) {
                for (py::handle item : entities) item.cast<Flags&>().Set(flag, value);
            },
            py::arg("flag"), py::arg("value"), py::arg("entities"),
            "Sets flag to value on every node / element / condition of the iterable.")
        .def(
            "CopySolutionStepData",
            [](const VariableUtils&, ModelPart& model_part, std::size_t source, std::size_t destination) {
                // Historical storage holds doubles and 3-vectors only (the kernel refuses other kinds).
                const auto& variables = model_part.GetRootModelPart().pGetNodalSolutionStepVariablesList();
                if (!variables) return;
                for (const auto& node : model_part.Nodes())
                    for (const VariableData* variable : variables->Variables()) {
                        if (const auto* scalar = dynamic_cast<const Variable<double>*>(variable))
                            node->FastGetSolutionStepValue(*scalar, destination) =
                                node->FastGetSolutionStepValue(*scalar, source);
                        else if (const auto* vector = dynamic_cast<const Variable<Array3>*>(variable))
                            node->FastGetSolutionStepValue(*vector, destination) =
                                node->FastGetSolutionStepValue(*vector, source);
                    }
            },
            py::arg("model_part"), py::arg("source"), py::arg("destination"),
            "Copies every historical value of buffer step source into step destination on the nodes of "
            "model_part (restarting a step from the last converged state: source 1, destination 0).");
}

}  // namespace contact_app::bindings
