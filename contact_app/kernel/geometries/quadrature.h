// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "contact_app/kernel/types.h"

namespace contact_app {

/// One quadrature point on a reference element: local coordinates (unused components are 0) and weight.
struct IntegrationPoint {
    Array3 local;
    double weight;
};

/// Reference-element families (Kratos GeometryData::KratosGeometryFamily, the ones we implement).
/// Reference elements: Linear ξ∈[-1,1]; Quadrilateral [-1,1]²; Hexahedra [-1,1]³;
/// Triangle {ξ,η ≥ 0, ξ+η ≤ 1}; Tetrahedra the unit simplex; Prism = triangle(ξ,η) × ζ∈[0,1].
enum class GeometryFamily { Point, Linear, Triangle, Quadrilateral, Tetrahedra, Hexahedra, Prism };

/// @brief Name of a family as written in messages ("Triangle", "Hexahedra", ...).
std::string FamilyName(GeometryFamily family);

/// @brief Measure of the reference element: Point 1, Linear 2, Triangle 1/2, Quadrilateral 4,
///        Tetrahedra 1/6, Hexahedra 8, Prism 1/2. Every rule's weights sum to it.
double ReferenceMeasure(GeometryFamily family);

/// @brief Kratos GAUSS_<order> rule of a family (cached, immutable, built once on first use).
///
/// Point counts per order 1..5: Point 1,1,1,1,1; Linear n; Quadrilateral n²; Hexahedra n³;
/// Triangle 1,3,4,6,7 (centroid, 3-point, Strang–Fix 4-point, 6-point, Radon 7-point);
/// Tetrahedra 1,4,5,11,14 (centroid, 4-point, Keast 5-point, Keast 11-point, positive 14-point);
/// Prism = Triangle GAUSS_n × n-point Gauss–Legendre on ζ∈[0,1]: 1,6,12,24,35.
/// @param[in] family reference element
/// @param[in] order Kratos integration order, 1..5
/// @return the points and weights; the reference stays valid for the life of the program
/// @throws InputError if @p order is outside 1..5
const std::vector<IntegrationPoint>& GaussRule(GeometryFamily family, int order);

/// @brief Total polynomial degree integrated exactly by GaussRule(@p family, @p order).
///
/// Linear/Quadrilateral/Hexahedra: 2·order−1 (also per direction); Triangle, Tetrahedra, Prism: order
/// (the prism's line factor is exact to 2·order−1 ≥ order in ζ). Point: every degree (returns INT_MAX).
/// @throws InputError if @p order is outside 1..5
int GaussRuleDegree(GeometryFamily family, int order);

}  // namespace contact_app
