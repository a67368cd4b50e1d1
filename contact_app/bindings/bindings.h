// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <pybind11/pybind11.h>

namespace contact_app::bindings {

namespace py = pybind11;

// One function per area, each defined in its bind_<area>.cpp and called once by module.cpp in this
// order (base classes first: Flags before Node, Node before Geometry, ...).
void BindExceptions(py::module_& m);
void BindVariables(py::module_& m);
void BindFlags(py::module_& m);
void BindNode(py::module_& m);
void BindProperties(py::module_& m);
void BindGeometries(py::module_& m);
void BindEntities(py::module_& m);
void BindModelPart(py::module_& m);
void BindIO(py::module_& m);
void BindRegistry(py::module_& m);
void BindUtilities(py::module_& m);
void BindSolving(py::module_& m);
void BindContact(py::module_& m);
void BindContactProcesses(py::module_& m);
void BindContactSearch(py::module_& m);
void BindContactStrategies(py::module_& m);
void BindMPCContact(py::module_& m);

}  // namespace contact_app::bindings
