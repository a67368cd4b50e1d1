// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/frictionless_mortar_contact_common.h"
#include "custom_conditions/mortar_contact_axisym_condition.h"
#include "custom_conditions/mortar_contact_family_condition_impl.h"

namespace contact_app {

/// Kratos AugmentedLagrangianMethodFrictionlessMortarContactCondition: MortarContactFamilyCondition with FRICTIONLESS.
/// ALM frictionless mortar contact, scalar multiplier λ_j = LAGRANGE_MULTIPLIER_CONTACT_PRESSURE per slave
/// node (docs/theory/contact_residuals.md §3). With g̃_j = −n_j·(D x1 − M x2)_j and λ̄_j = k λ_j + ε_j g̃_j:
/// active node: RHS_u1,k += δ_j λ̄_j D_jk n_j, RHS_u2,l −= δ_j λ̄_j M_jl n_j, RHS_λj += k g̃_j;
/// inactive node: RHS_λj += −k²/ε_j λ_j. k = SCALE_FACTOR (ProcessInfo), ε_j = INITIAL_PENALTY and
/// δ_j = DYNAMIC_FACTOR (nodal, non-historical; δ = 1 when the node has none). LHS = −∂RHS/∂q by AD.
/// Registers ALM[NV]FrictionlessMortarContactCondition{2D2N,3D3N,3D4N,3D3N4N,3D4N3N}; local system
/// [master u, slave u, λ] of size d(n_s + n_m) + n_s.
/// Its 2D axisymmetric variant MortarContactAxisymCondition<...<2, 2, NV>> weights every Gauss weight by
/// 2π r / THICKNESS, r = x-coordinate of the point (differentiated exactly by the AD tangent); registers
/// ALM[NV]FrictionlessAxisymMortarContactCondition2D2N.
/// q = [u2 (d·n_m), u1 (d·n_s), λ (n_s)].
template <int TDim, int TNS, bool TNV, int TNM, class TState, class T, int TSize>
void AddFamilyResidual(
    const MortarContactFamilyCondition<TDim, TNS, FrictionalCase::FRICTIONLESS, TNV, TNM>& rCondition,
    const TState& s, const ProcessInfo& rCurrentProcessInfo, Eigen::Matrix<T, TSize, 1>& rhs) {
    constexpr int lambda_offset = TDim * (TNS + TNM);
    const auto [k, p] = frictionless_detail::ReadALMParameters<TNS>(rCondition, rCurrentProcessInfo);
    for (int j = 0; j < TNS; ++j) {
        const double eps = p.penalty[j];
        if (!p.active[j]) {
            rhs[lambda_offset + j] += -(k * k / eps) * s.multipliers[j];
            continue;
        }
        const T gap = frictionless_detail::PairGap<T, TDim>(s, j);
        frictionless_detail::SpreadNormalForce<T, TDim, TNS, TNM>(
            s, j, T(p.dynamic_factor[j] * (k * s.multipliers[j] + eps * gap)), rhs);
        rhs[lambda_offset + j] += k * gap;
    }
}

CONTACT_APP_INSTANTIATE_CONTACT_FAMILY(FRICTIONLESS)
CONTACT_APP_INSTANTIATE_AXISYM_FAMILY(FRICTIONLESS)

}  // namespace contact_app
