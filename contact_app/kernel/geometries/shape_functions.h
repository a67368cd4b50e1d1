// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <vector>

#include "contact_app/kernel/types.h"

/// Shape functions shared by the 2D and 3D variants of one reference element (Line2D2/Line3D2,
/// Triangle2D3/Triangle3D3, Quadrilateral2D4/Quadrilateral3D4). Kratos/GiD node order.
namespace contact_app::detail {

using Connectivity = std::vector<std::vector<std::size_t>>;

/// @brief 2-node line on ξ∈[-1,1]: N = ((1−ξ)/2, (1+ξ)/2); rN resized to 2.
void LinearLineValues(Vector& rN, const Array3& local);
/// @param[out] rDN 2 × 1
/// @param[in] local local coordinates (ξ, unused, unused)
void LinearLineGradients(Matrix& rDN, const Array3& local);
/// @brief Nodes at ξ = −1, +1 (2 × 1).
Matrix LinearLineNodes();
/// @brief End points {0}, {1}.
Connectivity LinearLineFaces();

/// @brief 3-node triangle: N = (1−ξ−η, ξ, η); rN resized to 3.
void LinearTriangleValues(Vector& rN, const Array3& local);
/// @param[out] rDN 3 × 2
/// @param[in] local local coordinates (ξ, η, unused)
void LinearTriangleGradients(Matrix& rDN, const Array3& local);
/// @brief Nodes (0,0), (1,0), (0,1) (3 × 2).
Matrix LinearTriangleNodes();
/// @brief Edge i opposite node i, counter-clockwise: {1,2}, {2,0}, {0,1}.
Connectivity LinearTriangleEdges();

/// @brief 4-node quadrilateral on [-1,1]²: N_k = (1+ξ_k ξ)(1+η_k η)/4; rN resized to 4.
void BilinearQuadrilateralValues(Vector& rN, const Array3& local);
/// @param[out] rDN 4 × 2
/// @param[in] local local coordinates (ξ, η, unused)
void BilinearQuadrilateralGradients(Matrix& rDN, const Array3& local);
/// @brief Nodes (−1,−1), (1,−1), (1,1), (−1,1) (4 × 2).
Matrix BilinearQuadrilateralNodes();
/// @brief Edges counter-clockwise: {0,1}, {1,2}, {2,3}, {3,0}.
Connectivity BilinearQuadrilateralEdges();

/// @brief Quadratic simplex (Triangle2D6, Tetrahedra3D10) from barycentric coordinates L: corner k has
///        N_k = L_k(2L_k − 1), mid-side node of edge (a,b) has N = 4 L_a L_b; rN resized.
/// @param[out] rN one value per node, corners then mid-side nodes, resized here
/// @param[in] barycentric L, one entry per corner
/// @param[in] edges (a,b) of each mid-side node, in order
void QuadraticSimplexValues(Vector& rN, const Vector& barycentric, const Connectivity& edges);
/// @param[out] rDN n_nodes × local_dim, resized here
/// @param[in] barycentric L, one entry per corner
/// @param[in] barycentric_gradients n_corners × local_dim, ∂L_k/∂ξ_j
/// @param[in] edges (a,b) of each mid-side node, in order
void QuadraticSimplexGradients(Matrix& rDN, const Vector& barycentric, const Matrix& barycentric_gradients,
                               const Connectivity& edges);

}  // namespace contact_app::detail
