// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// The part of a pair's tangent that comes from nodal normals following the iterate (docs/theory/mortar.md §7 "Normals
/// that follow the iterate"). With CONSIDER_NORMAL_VARIATION ≠ 0 on a moving mesh the criteria recompute the mean
/// nodal NORMAL n_j = s_j/|s_j|, s_j = Σ_f ν_f(j) (the unit normals at j of every face f of the contact surface through
/// j), before every build, so the residual the Newton loop drives to zero is RHS^c(q, n(x)). n_j reads the slave faces
/// on both sides of the node, outside pair c's unknowns, so the pair records B^c_j = ∂RHS^c/∂n_j and
/// NodalNormalCoupling (custom_strategies/) adds B^c_j ∂n_j/∂x_k for every node k of those faces.
#include "contact_app/kernel/condition.h"
#include "custom_utilities/contact_variables.h"

namespace contact_app {

/// Whether this build's tangent differentiates the normals that follow the iterate: only once the last set update
/// changed neither the active nor the slip set (ACTIVE_SET_CONVERGED, SLIP_SET_CONVERGED; unset counts as unchanged).
/// While the sets move, the normals are held (the reference holds them always): with the rotation terms from the first
/// iterate the 2D ironing penalty run cut 8 sliding steps on inverted elements and the frictional cylinders stopped at
/// t = 0.04, where holding them converges (docs/theory/mortar.md §7 "Normals that follow the iterate").
inline bool NormalsInTangent(const ProcessInfo& rProcessInfo) {
    const auto unchanged = [&](const Variable<bool>& flag) {
        return !rProcessInfo.Has(flag) || rProcessInfo.GetValue(flag);
    };
    return unchanged(ACTIVE_SET_CONVERGED) && unchanged(SLIP_SET_CONVERGED);
}

/// A pair condition whose residual reads the nodal NORMAL of its slave nodes.
class NodalNormalCouplingSource {
public:
    virtual ~NodalNormalCouplingSource() = default;
    /// Whether the pair records ∂RHS/∂n in its tangent evaluations under @p rProcessInfo (normals follow the
    /// iterate and the pair does not differentiate them itself).
    virtual bool CouplesNodalNormals(const ProcessInfo& rProcessInfo) const = 0;
    /// @param[in] j local index of a slave node
    /// @param[out] rForcePerNormal ∂RHS/∂n_j, local DoF order (EquationIdVector) × d
    /// @return false when the last tangent evaluation recorded nothing (normals held, NormalsInTangent false, pair
    ///         isolated)
    virtual bool GetNodalNormalCoupling(int j, Matrix& rForcePerNormal) const = 0;
};

}  // namespace contact_app
