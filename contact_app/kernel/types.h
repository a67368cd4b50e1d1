// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include <Eigen/Core>

namespace contact_app {

using IndexType = std::size_t;
/// A 3-component vector (Kratos array_1d<double,3>); 2D problems leave the z component at zero.
using Array3 = Eigen::Matrix<double, 3, 1>;
using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;

}  // namespace contact_app
