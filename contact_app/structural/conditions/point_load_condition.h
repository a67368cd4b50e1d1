// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/structural/conditions/base_load_condition.h"

namespace contact_app {

/// Nodal force f = P_cond + P_node (docs/theory/structural.md §3): P_cond the condition's POINT_LOAD, P_node the node's
/// historical POINT_LOAD where stored; first TDim components. No load stiffness (zero LHS).
/// Registers PointLoadCondition2D1N and PointLoadCondition3D1N (Point3D geometry).
/// @tparam TDim 2 or 3: DoFs per node.
template <int TDim>
class PointLoadCondition : public BaseLoadCondition {
public:
    using BaseLoadCondition::BaseLoadCondition;
    using BaseLoadCondition::Create;

    /// A PointLoadCondition on @p geometry (shared), with @p properties (may be null).
    Pointer Create(IndexType new_id, Geometry::Pointer geometry, Properties::Pointer properties) const override;

protected:
    int DofsPerNode() const override { return TDim; }
    void CalculateAll(Matrix* pLhs, Vector* pRhs, const ProcessInfo& rCurrentProcessInfo) const override;
};

using PointLoadCondition2D1N = PointLoadCondition<2>;
using PointLoadCondition3D1N = PointLoadCondition<3>;

}  // namespace contact_app
