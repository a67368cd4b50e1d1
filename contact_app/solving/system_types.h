// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace contact_app {

/// Global system matrix: compressed sparse column with int indices (the layout UMFPACK, CHOLMOD
/// and KLU take without a copy).
using SparseMatrixType = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
/// Global right-hand side and solution vectors.
using SystemVectorType = Eigen::VectorXd;

}  // namespace contact_app
