// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>

#include "automatic_differentiation/dual.h"

namespace contact_app {

/// @brief Seeds a matrix of independent variables: entry (r, c) becomes variable offset + r·C + c
///        (row-major; with one node per row this is the "node·d + component" DOF index).
/// @param[in] values R×C values
/// @param[in] offset index of the first variable; offset + R·C ≤ N
/// @return the seeded R×C matrix of Dual<N>
template <int N, int R, int C>
Eigen::Matrix<Dual<N>, R, C> Seed(const Eigen::Matrix<double, R, C>& values, int offset = 0) {
    Eigen::Matrix<Dual<N>, R, C> result;
    for (int r = 0; r < R; ++r)
        for (int c = 0; c < C; ++c) result(r, c) = Dual<N>::Variable(values(r, c), offset + r * C + c);
    return result;
}

/// @brief Values of a matrix (or matrix expression) of scalars (identity for double).
template <class TDerived>
Eigen::Matrix<double, TDerived::RowsAtCompileTime, TDerived::ColsAtCompileTime> Values(
    const Eigen::MatrixBase<TDerived>& m) {
    Eigen::Matrix<double, TDerived::RowsAtCompileTime, TDerived::ColsAtCompileTime> result(m.rows(), m.cols());
    for (Eigen::Index r = 0; r < m.rows(); ++r)
        for (Eigen::Index c = 0; c < m.cols(); ++c) result(r, c) = Value(m(r, c));
    return result;
}

/// @brief ∂m/∂x_q for one independent variable q: the R×C matrix of partial derivatives.
template <int N, int R, int C>
Eigen::Matrix<double, R, C> Derivative(const Eigen::Matrix<Dual<N>, R, C>& m, int q) {
    Eigen::Matrix<double, R, C> result;
    for (int r = 0; r < R; ++r)
        for (int c = 0; c < C; ++c) result(r, c) = m(r, c).Derivatives()[q];
    return result;
}

/// @brief Jacobian of a matrix of Duals flattened row-major: (R·C) × N, row r·C + c = ∇m(r, c).
template <int N, int R, int C>
Eigen::Matrix<double, R * C, N> Jacobian(const Eigen::Matrix<Dual<N>, R, C>& m) {
    Eigen::Matrix<double, R * C, N> result;
    for (int r = 0; r < R; ++r)
        for (int c = 0; c < C; ++c) result.row(r * C + c) = m(r, c).Derivatives().transpose();
    return result;
}

/// @brief Re-embeds a Dual<N> into a larger Dual<M>: ∂/∂x_q moves to ∂/∂y_{offset+q}. Lets a condition
///        with M unknowns (displacements + multipliers) reuse mortar operators derived for N coordinates.
template <int M, int N>
Dual<M> Embed(const Dual<N>& x, int offset = 0) {
    static_assert(M >= N, "the target AD size must hold the source derivatives");
    typename Dual<M>::Gradient gradient = Dual<M>::Gradient::Zero();
    gradient.template segment<N>(offset) = x.Derivatives();
    return Dual<M>(x.Value(), gradient);
}

}  // namespace contact_app
