// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>

namespace contact_app::detail {

/// Linear faces of the mortar pairs: Line2D2 (ξ ∈ [−1,1]), Triangle3D3 (unit simplex), Quadrilateral3D4
/// ([−1,1]²), Kratos node order. Shape functions and local gradients, templated on the scalar.
template <int TNumNodes>
constexpr int FaceLocalDim = TNumNodes == 2 ? 1 : 2;

template <int TNumNodes, class T>
Eigen::Matrix<T, TNumNodes, 1> FaceShapeFunctions(const Eigen::Matrix<T, FaceLocalDim<TNumNodes>, 1>& xi) {
    Eigen::Matrix<T, TNumNodes, 1> n;
    if constexpr (TNumNodes == 2) {
        n << 0.5 * (1.0 - xi[0]), 0.5 * (1.0 + xi[0]);
    } else if constexpr (TNumNodes == 3) {
        n << 1.0 - xi[0] - xi[1], xi[0], xi[1];
    } else {
        n << 0.25 * (1.0 - xi[0]) * (1.0 - xi[1]), 0.25 * (1.0 + xi[0]) * (1.0 - xi[1]),
            0.25 * (1.0 + xi[0]) * (1.0 + xi[1]), 0.25 * (1.0 - xi[0]) * (1.0 + xi[1]);
    }
    return n;
}

/// ∂N_k/∂ξ_j (TNumNodes × local dim).
template <int TNumNodes, class T>
Eigen::Matrix<T, TNumNodes, FaceLocalDim<TNumNodes>> FaceShapeGradients(
    const Eigen::Matrix<T, FaceLocalDim<TNumNodes>, 1>& xi) {
    Eigen::Matrix<T, TNumNodes, FaceLocalDim<TNumNodes>> g;
    if constexpr (TNumNodes == 2) {
        g << -0.5, 0.5;
    } else if constexpr (TNumNodes == 3) {
        g << -1.0, -1.0, 1.0, 0.0, 0.0, 1.0;
    } else {
        g << -0.25 * (1.0 - xi[1]), -0.25 * (1.0 - xi[0]), 0.25 * (1.0 - xi[1]), -0.25 * (1.0 + xi[0]),
            0.25 * (1.0 + xi[1]), 0.25 * (1.0 + xi[0]), -0.25 * (1.0 + xi[1]), 0.25 * (1.0 - xi[0]);
    }
    return g;
}

/// Parametric inside test with slack @p tol (local units).
template <int TNumNodes>
bool IsInsideFace(const Eigen::Matrix<double, FaceLocalDim<TNumNodes>, 1>& xi, double tol) {
    if constexpr (TNumNodes == 2) {
        return xi[0] >= -1.0 - tol && xi[0] <= 1.0 + tol;
    } else if constexpr (TNumNodes == 3) {
        return xi[0] >= -tol && xi[1] >= -tol && xi[0] + xi[1] <= 1.0 + tol;
    } else {
        return xi[0] >= -1.0 - tol && xi[0] <= 1.0 + tol && xi[1] >= -1.0 - tol && xi[1] <= 1.0 + tol;
    }
}

/// Reference centroid of the face.
template <int TNumNodes>
Eigen::Matrix<double, FaceLocalDim<TNumNodes>, 1> FaceCentroid() {
    Eigen::Matrix<double, FaceLocalDim<TNumNodes>, 1> c;
    c.setConstant(TNumNodes == 3 ? 1.0 / 3.0 : 0.0);
    return c;
}

}  // namespace contact_app::detail
