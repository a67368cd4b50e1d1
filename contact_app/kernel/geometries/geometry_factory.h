// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "contact_app/kernel/geometries/geometry.h"

namespace contact_app {

/// @brief Builds a geometry from its Kratos name (one table: Point3D, Line2D2, Line3D2, Line2D3, Triangle2D3,
///        Triangle3D3, Triangle2D6, Quadrilateral2D4, Quadrilateral3D4, Tetrahedra3D4, Tetrahedra3D10,
///        Hexahedra3D8, Prism3D6).
/// @param[in] name Kratos geometry name, case-sensitive
/// @param[in] points the nodes in Kratos/GiD order (shared ownership)
/// @return a new geometry owning shares of @p points
/// @throws InputError for an unknown name (lists the valid names and suggests the closest) or a wrong
///         node count
Geometry::Pointer CreateGeometry(const std::string& name, Geometry::PointsArrayType points);

/// @brief Every name CreateGeometry() accepts, in table order.
std::vector<std::string> RegisteredGeometryNames();

}  // namespace contact_app
