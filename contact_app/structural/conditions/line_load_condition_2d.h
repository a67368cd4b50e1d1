// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/structural/conditions/base_load_condition.h"

namespace contact_app {

/// Distributed load and follower pressure on a 2D line, on the current configuration (docs/theory/structural.md §3):
/// f_i = Σ_g w_g c N_i (|t| q − p n),  t = ∂x/∂ξ, n = (t_y, −t_x) (outward for a counter-clockwise boundary),
/// q = LINE_LOAD (condition + nodal, per unit current length), p = Σ N_k p_k (BaseLoadCondition::NodalPressures),
/// c = 1 (CircumferenceFactor). LHS = −∂f/∂u, the consistent load stiffness of both terms.
/// Integration: Gauss order DefaultIntegrationOrder() + 1 (2 points). No THICKNESS factor.
/// Registers LineLoadCondition2D2N (Line2D2); base of AxisymLineLoadCondition2D.
class LineLoadCondition2D : public BaseLoadCondition {
public:
    using BaseLoadCondition::BaseLoadCondition;
    using BaseLoadCondition::Create;

    /// A LineLoadCondition2D on @p geometry (shared), with @p properties (may be null).
    Pointer Create(IndexType new_id, Geometry::Pointer geometry, Properties::Pointer properties) const override;

protected:
    int DofsPerNode() const override { return 2; }
    void CalculateAll(Matrix* pLhs, Vector* pRhs, const ProcessInfo& rCurrentProcessInfo) const override;
    /// @brief Factor c(ξ) on the integration weight and ∂c/∂x_k (x-component of node k; c depends on no y).
    /// @param[in] N shape functions at the point; @param[out] rDerivative n values, resized here
    virtual double CircumferenceFactor(const Vector& N, Vector& rDerivative) const;
};

}  // namespace contact_app
