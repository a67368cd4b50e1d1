// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/structural/conditions/base_load_condition.h"

namespace contact_app {

/// Distributed load and follower pressure on a 3D surface, on the current configuration (docs/theory/structural.md §3):
/// f_i = Σ_g w_g N_i (|a| s + p a),  a = t_ξ × t_η (the geometry normal, right-hand rule on node order),
/// s = SURFACE_LOAD (condition + historical nodal, per unit current area), p = Σ N_k p_k
/// (BaseLoadCondition::NodalPressures): NEGATIVE_FACE_PRESSURE > 0 pushes along +a.
/// LHS = −∂f/∂u, the consistent load stiffness of both terms. Gauss order DefaultIntegrationOrder() + 1.
/// Registers SurfaceLoadCondition3D3N (Triangle3D3) and SurfaceLoadCondition3D4N (Quadrilateral3D4).
class SurfaceLoadCondition3D : public BaseLoadCondition {
public:
    using BaseLoadCondition::BaseLoadCondition;
    using BaseLoadCondition::Create;

    /// A SurfaceLoadCondition3D on @p geometry (shared), with @p properties (may be null).
    Pointer Create(IndexType new_id, Geometry::Pointer geometry, Properties::Pointer properties) const override;

protected:
    int DofsPerNode() const override { return 3; }
    void CalculateAll(Matrix* pLhs, Vector* pRhs, const ProcessInfo& rCurrentProcessInfo) const override;
};

}  // namespace contact_app
