// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/bindings/binding_helpers.h"
#include "contact_app/bindings/bindings.h"
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
            "Sets flag to value on every node / element / condition of the iterable.");
}

}  // namespace contact_app::bindings
