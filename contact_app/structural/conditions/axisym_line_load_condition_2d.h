// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/structural/conditions/line_load_condition_2d.h"

namespace contact_app {

/// Axisymmetric line load (docs/theory/structural.md §3): LineLoadCondition2D with the weight factor c = 2π r,
/// r = Σ N_k x_k the current radius (x = r, y = z); loads are per unit meridian length, integrated over
/// the full circumference. Kratos also divides by THICKNESS (docs/theory/structural.md §8 D2); this class does not.
/// Registers AxisymLineLoadCondition2D2N (Line2D2).
class AxisymLineLoadCondition2D : public LineLoadCondition2D {
public:
    using LineLoadCondition2D::Create;
    using LineLoadCondition2D::LineLoadCondition2D;

    /// An AxisymLineLoadCondition2D on @p geometry (shared), with @p properties (may be null).
    Pointer Create(IndexType new_id, Geometry::Pointer geometry, Properties::Pointer properties) const override;

protected:
    /// c = 2π r, ∂c/∂x_k = 2π N_k.
    double CircumferenceFactor(const Vector& N, Vector& rDerivative) const override;
};

}  // namespace contact_app
