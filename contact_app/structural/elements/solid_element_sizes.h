// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The one table of solid-element sizes. Each row X(TDim, TNumNodes, Geometry, Suffix) generates the explicit
// template instantiations (in each element's .cpp) and the registered names (element_registration.cpp):
// "<Family>Element" #Suffix on geometry #Geometry.

// clang-format off
/// Plane (strain size 3) and 3D (strain size 6) sizes of SmallDisplacement, TotalLagrangian, UpdatedLagrangian.
#define CONTACT_APP_SOLID_ELEMENT_SIZES(X)                                                          \
    X(2, 3, Triangle2D3, 2D3N) X(2, 4, Quadrilateral2D4, 2D4N) X(2, 6, Triangle2D6, 2D6N)           \
    X(3, 4, Tetrahedra3D4, 3D4N) X(3, 8, Hexahedra3D8, 3D8N) X(3, 10, Tetrahedra3D10, 3D10N)

/// Axisymmetric (strain size 4, x = r, y = z) sizes of AxisymSmallDisplacement and AxisymTotalLagrangian.
#define CONTACT_APP_AXISYM_SOLID_ELEMENT_SIZES(X) X(2, 3, Triangle2D3, 2D3N) X(2, 4, Quadrilateral2D4, 2D4N)
// clang-format on
