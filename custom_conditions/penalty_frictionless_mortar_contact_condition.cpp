// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/mortar_contact_families.h"
#include "custom_conditions/mortar_contact_family_condition_impl.h"

#include <type_traits>

#include "custom_conditions/frictionless_mortar_contact_common.h"

namespace contact_app {
namespace {

using namespace frictionless_detail;

/// RHS of one pair, q = [u2 (d·n_m), u1 (d·n_s)]: S_j[δ_j ε_j η_j G_j n_j] on the active nodes, nothing on the
/// inactive ones; G_j is the node's weighted gap over all its pairs (this pair's part varying) and η_j = Σ_c a_c² / A_j²
/// (this pair's area varying: NodalInterfaceMap::PenaltyGap, docs/theory/mortar.md §7 "Nodal penalty"). In the AD pass
/// @p record keeps b_j = S_j[δ ε n_j] and this pair's ∂(ηG)_j/∂q for the other pairs' tangent blocks
/// (nodal_gap_coupling.h).
template <class T, int TDim, int TNS, int TNM, class TState, class TVector, class TRecord>
void AddPenaltyFrictionlessResidual(const TState& s, const NodalParameters<TNS>& p,
                                    const NodalInterfaceMap<TDim, TNS>& nodal, TVector& rhs, TRecord* record) {
    for (int j = 0; j < TNS; ++j) {
        if (!p.active[j]) continue;
        const T gap = nodal.PenaltyGap(j, PairGap<T, TDim>(s, j), PairArea<T>(s, j));
        const double stiffness = p.dynamic_factor[j] * p.penalty[j];
        SpreadNormalForce<T, TDim, TNS, TNM>(s, j, T(stiffness * gap), rhs);
        if constexpr (!std::is_same_v<T, double>) {
            if (record == nullptr) continue;
            RecordNodalGapCoupling<T, TDim, TNS, TNM>(
                s, j, Eigen::Matrix<double, TDim, 1>(Values(s.normals.row(j).transpose()) * stiffness), gap, *record);
        } else {
            (void)record;
        }
    }
}

/// ε_j must be positive on the active nodes (an active node without INITIAL_PENALTY would transmit nothing).
template <int TNumNodes>
NodalParameters<TNumNodes> ReadParameters(const Geometry& slave, IndexType id) {
    return ReadNodalParameters<TNumNodes>(slave, id, "Penalty", [](bool active) { return active; });
}

}  // namespace

/// The penalty frictionless family's residual (mortar_contact_families.h).
template <int TDim, int TNS, bool TNV, int TNM, class TState, class TVector>
void AddFamilyResidual(
    const MortarContactFamilyCondition<TDim, TNS, FrictionalCase::FRICTIONLESS_PENALTY, TNV, TNM>& rCondition,
    const TState& state, const ProcessInfo& rCurrentProcessInfo, TVector& rhs) {
    using T = typename TVector::Scalar;
    const Geometry& slave = rCondition.GetParentGeometry();
    const auto nodal = MakeNodalInterfaceMap<TDim, TNS>(slave, rCondition.NodalShare(), false);
    AddPenaltyFrictionlessResidual<T, TDim, TNS, TNM>(state, ReadParameters<TNS>(slave, rCondition.Id()), nodal, rhs,
                                                      rCondition.MutableCouplingRecord());
}

CONTACT_APP_INSTANTIATE_CONTACT_FAMILY(FRICTIONLESS_PENALTY)
CONTACT_APP_INSTANTIATE_AXISYM_FAMILY(FRICTIONLESS_PENALTY)

}  // namespace contact_app
