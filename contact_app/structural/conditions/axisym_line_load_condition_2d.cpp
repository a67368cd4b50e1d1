// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/structural/conditions/axisym_line_load_condition_2d.h"

#include <cmath>
#include <memory>

namespace contact_app {

AxisymLineLoadCondition2D::Pointer AxisymLineLoadCondition2D::Create(IndexType new_id, Geometry::Pointer geometry,
                                                                     Properties::Pointer properties) const {
    return std::make_shared<AxisymLineLoadCondition2D>(new_id, std::move(geometry), std::move(properties));
}

double AxisymLineLoadCondition2D::CircumferenceFactor(const Vector& N, Vector& rDerivative) const {
    constexpr double two_pi = 6.283185307179586476925;  // 2π
    double radius = 0.0;
    for (Eigen::Index k = 0; k < N.size(); ++k) radius += N[k] * GetGeometry()[k].X();
    // docs/theory/structural.md §8 D2: Kratos divides by THICKNESS here; the elements do not, so neither do we.
    rDerivative = two_pi * N;
    return two_pi * radius;
}

}  // namespace contact_app
