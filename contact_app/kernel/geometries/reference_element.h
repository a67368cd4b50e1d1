// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "contact_app/kernel/geometries/geometry.h"
#include "contact_app/kernel/geometries/shape_functions.h"

namespace contact_app {

/// The shape functions of a reference element on its local coordinates, shared by the 2D and 3D variants of a type.
struct ShapeFunctionSet {
    /// N at local coordinates (resizes its output to the node count)
    void (*values)(Vector& rN, const Array3& local);
    /// ∂N/∂ξ at local coordinates, nodes × local dimension
    void (*gradients)(Matrix& rDN, const Array3& local);
    /// Local coordinates of the nodes, nodes × local dimension
    Matrix (*nodes)();
    /// Local node indices of each face (boundary entity of dimension local dimension − 1)
    detail::Connectivity (*faces)();
};

/// What makes one Kratos geometry type: its reference element (node count, dimensions, shape functions on the
/// reference coordinates, node positions, faces) and the Gauss orders it integrates with. One row of
/// ReferenceElements() per type; ReferenceGeometry maps a row onto nodes (docs/architecture.md, "Data model").
struct ReferenceElement {
    const char* name;  ///< Kratos name (Line2D2, Tetrahedra3D4, ...)
    GeometryFamily family;
    std::size_t num_points;   ///< nodes, Kratos/GiD order
    int working_dimension;    ///< 2 or 3
    int local_dimension;      ///< 0 (point) to 3
    int default_integration;  ///< Gauss order of the elements' integration
    int measure_integration;  ///< Gauss order of Length/Area/Volume (exact for the type's Jacobian)
    const ShapeFunctionSet& shape_functions;
};

/// @brief Every geometry type, in the order RegisteredGeometryNames() lists them.
const std::vector<ReferenceElement>& ReferenceElements();

/// @param[in] name Kratos geometry name, case-sensitive
/// @return its row of ReferenceElements(), or nullptr when there is none
const ReferenceElement* FindReferenceElement(const std::string& name);

}  // namespace contact_app
