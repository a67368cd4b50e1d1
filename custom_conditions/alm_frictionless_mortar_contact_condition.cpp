// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/mortar_contact_families.h"
#include "custom_conditions/mortar_contact_family_condition_impl.h"

#include "custom_conditions/frictionless_mortar_contact_common.h"

namespace contact_app {
namespace {

using namespace frictionless_detail;

/// RHS of docs/theory/contact_residuals.md §3 for one pair, q = [u2 (d·n_m), u1 (d·n_s), λ (n_s)].
template <class T, int TDim, int TNS, int TNM, class TState, class TVector>
void AddFrictionlessResidual(const TState& s, double k, const NodalParameters<TNS>& p, TVector& rhs) {
    constexpr int lambda_offset = TDim * (TNS + TNM);
    for (int j = 0; j < TNS; ++j) {
        const double eps = p.penalty[j];
        if (!p.active[j]) {
            rhs[lambda_offset + j] += -(k * k / eps) * s.multipliers[j];
            continue;
        }
        const T gap = PairGap<T, TDim>(s, j);
        SpreadNormalForce<T, TDim, TNS, TNM>(s, j, T(p.dynamic_factor[j] * (k * s.multipliers[j] + eps * gap)), rhs);
        rhs[lambda_offset + j] += k * gap;
    }
}

}  // namespace

/// The ALM frictionless family's residual (mortar_contact_families.h).
template <int TDim, int TNS, bool TNV, int TNM, class TState, class TVector>
void AddFamilyResidual(
    const MortarContactFamilyCondition<TDim, TNS, FrictionalCase::FRICTIONLESS, TNV, TNM>& rCondition,
    const TState& state, const ProcessInfo& rCurrentProcessInfo, TVector& rhs) {
    using T = typename TVector::Scalar;
    const auto [k, p] =
        ReadALMParameters<TNS>(rCondition.GetParentGeometry(), rCurrentProcessInfo, rCondition.Id());
    AddFrictionlessResidual<T, TDim, TNS, TNM>(state, k, p, rhs);
}

CONTACT_APP_INSTANTIATE_CONTACT_FAMILY(FRICTIONLESS)
CONTACT_APP_INSTANTIATE_AXISYM_FAMILY(FRICTIONLESS)

}  // namespace contact_app
