// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/frictionless_mortar_contact_common.h"
#include "custom_conditions/mortar_contact_axisym_condition.h"
#include "custom_conditions/mortar_contact_family_condition_impl.h"

#include <type_traits>

namespace contact_app {

/// Kratos PenaltyMethodFrictionlessMortarContactCondition: MortarContactFamilyCondition with FRICTIONLESS_PENALTY.
/// Penalty frictionless mortar contact, displacement DoFs only (docs/theory/contact_residuals.md §6). With
/// G_j = Σ_c g̃^c_j the node's weighted gap over all its pairs (g̃ = −n_j·(D x1 − M x2)_j per pair) and
/// η_j = Σ_c a_c² / A_j², the augmented pressure of an active node is λ̄_j = ε_j η_j G_j and
/// RHS_u1,k += δ_j λ̄_j D_jk n_j, RHS_u2,l −= δ_j λ̄_j M_jl n_j; an inactive node contributes nothing (its rows
/// and columns stay zero). On a uniform gap this is the reference's pair-wise ε g̃^c; unlike it, the partial gaps
/// of a node's pairs (of either sign on a curved non-matching face) do not push and pull it separately
/// (docs/theory/mortar.md §7 "Nodal penalty"). The blocks coupling two pairs of a node are added by
/// NodalPenaltyCoupling from GetNodalGapCoupling. ε_j = INITIAL_PENALTY and δ_j = DYNAMIC_FACTOR (nodal,
/// non-historical; δ = 1 when the node has none). LHS = −∂RHS/∂q by AD. Registers
/// Penalty[NV]FrictionlessMortarContactCondition{2D2N,3D3N,3D4N,3D3N4N,3D4N3N}; local system [master u, slave u] of
/// size d(n_s + n_m).
/// Its 2D axisymmetric variant MortarContactAxisymCondition<...<2, 2, NV>> weights every Gauss weight by
/// 2π r / THICKNESS, r = x-coordinate of the point (differentiated exactly by the AD tangent); registers
/// Penalty[NV]FrictionlessAxisymMortarContactCondition2D2N.
/// q = [u2 (d·n_m), u1 (d·n_s)]; G_j varies with this pair's part and η_j with this pair's area
/// (NodalInterfaceMap::PenaltyGap). ε_j must be positive on the active nodes (an active node without INITIAL_PENALTY
/// would transmit nothing). In the AD pass the coupling record keeps b_j = S_j[δ ε n_j] and this pair's ∂(ηG)_j/∂q
/// for the other pairs' tangent blocks (nodal_gap_coupling.h).
template <int TDim, int TNS, bool TNV, int TNM, class TState, class T, int TSize>
void AddFamilyResidual(
    const MortarContactFamilyCondition<TDim, TNS, FrictionalCase::FRICTIONLESS_PENALTY, TNV, TNM>& rCondition,
    const TState& s, const ProcessInfo&, Eigen::Matrix<T, TSize, 1>& rhs) {
    using namespace frictionless_detail;
    const Geometry& slave = rCondition.GetParentGeometry();
    const auto nodal = MakeNodalInterfaceMap<TDim, TNS>(slave, rCondition.NodalShare(), false);
    const auto p = ReadNodalParameters<TNS>(slave, rCondition.Id(), "Penalty", [](bool active) { return active; });
    [[maybe_unused]] auto* const record = rCondition.MutableCouplingRecord();
    for (int j = 0; j < TNS; ++j) {
        if (!p.active[j]) continue;
        const T gap = nodal.PenaltyGap(j, PairGap<T, TDim>(s, j), PairArea<T>(s, j));
        const double stiffness = p.dynamic_factor[j] * p.penalty[j];
        SpreadNormalForce<T, TDim, TNS, TNM>(s, j, T(stiffness * gap), rhs);
        if constexpr (!std::is_same_v<T, double>) {
            if (record == nullptr) continue;
            RecordNodalGapCoupling<T, TDim, TNS, TNM>(
                s, j, Eigen::Matrix<double, TDim, 1>(Values(s.normals.row(j).transpose()) * stiffness), gap, *record);
        }
    }
}

CONTACT_APP_INSTANTIATE_CONTACT_FAMILY(FRICTIONLESS_PENALTY)
CONTACT_APP_INSTANTIATE_AXISYM_FAMILY(FRICTIONLESS_PENALTY)

}  // namespace contact_app
