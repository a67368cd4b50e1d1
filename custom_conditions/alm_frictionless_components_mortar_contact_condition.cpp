// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/frictionless_mortar_contact_common.h"
#include "custom_conditions/mortar_contact_family_condition_impl.h"

namespace contact_app {

/// Kratos AugmentedLagrangianMethodFrictionlessComponentsMortarContactCondition: MortarContactFamilyCondition with
/// FRICTIONLESS_COMPONENTS.
/// ALM frictionless mortar contact with a vector multiplier λ_j = VECTOR_LAGRANGE_MULTIPLIER per slave node
/// (docs/theory/contact_residuals.md §4). With g̃_j = −n_j·(D x1 − M x2)_j and P_j = I − n_j n_jᵀ:
/// active node: S_j[δ_j (k λ_j + ε_j g̃_j n_j)] on the displacement rows (the full vector k λ_j, tangential
/// part included), RHS_λj += k g̃_j n_j − k²/ε_j P_jᵀ P_j λ_j (the tangential part is regularised to zero);
/// inactive node: RHS_λj += −k²/ε_j λ_j. k = SCALE_FACTOR (ProcessInfo), ε_j = INITIAL_PENALTY and
/// δ_j = DYNAMIC_FACTOR (nodal, non-historical; δ = 1 when absent; δ only scales the displacement rows).
/// LHS = −∂RHS/∂q by AD. Registers ALM[NV]FrictionlessComponentsMortarContactCondition{2D2N,3D3N,3D4N,3D3N4N,
/// 3D4N3N} (no axisymmetric variant); local system [master u, slave u, slave λ (d per node)] of size d(2n_s + n_m).
/// q = [u2 (d·n_m), u1 (d·n_s), λ (d·n_s)].
template <int TDim, int TNS, bool TNV, int TNM, class TState, class T, int TSize>
void AddFamilyResidual(
    const MortarContactFamilyCondition<TDim, TNS, FrictionalCase::FRICTIONLESS_COMPONENTS, TNV, TNM>& rCondition,
    const TState& s, const ProcessInfo& rCurrentProcessInfo, Eigen::Matrix<T, TSize, 1>& rhs) {
    using Vec = Eigen::Matrix<T, TDim, 1>;
    constexpr int lambda_offset = TDim * (TNS + TNM);
    const auto [k, p] = frictionless_detail::ReadALMParameters<TNS>(rCondition, rCurrentProcessInfo);
    for (int j = 0; j < TNS; ++j) {
        const double eps = p.penalty[j];
        const double k2_eps = k * k / eps;
        const int row = lambda_offset + j * TDim;
        if (!p.active[j]) {
            for (int c = 0; c < TDim; ++c) rhs[row + c] += -k2_eps * s.multipliers[j * TDim + c];
            continue;
        }
        const T gap = frictionless_detail::PairGap<T, TDim>(s, j);
        T lambda_n = T(0.0);  // n·λ
        for (int c = 0; c < TDim; ++c) lambda_n += s.normals(j, c) * s.multipliers[j * TDim + c];
        Vec force, p_lambda;  // δ (k λ + ε g̃ n), P λ
        for (int c = 0; c < TDim; ++c) {
            force[c] = p.dynamic_factor[j] * (k * s.multipliers[j * TDim + c] + eps * gap * s.normals(j, c));
            p_lambda[c] = s.multipliers[j * TDim + c] - s.normals(j, c) * lambda_n;
        }
        frictionless_detail::SpreadForce<T, TDim, TNS, TNM>(s, j, force, rhs);
        T n_p_lambda = T(0.0);  // n·(P λ): Pᵀ P λ = P λ − n (n·P λ), kept as in the generated code
        for (int c = 0; c < TDim; ++c) n_p_lambda += s.normals(j, c) * p_lambda[c];
        for (int c = 0; c < TDim; ++c)
            rhs[row + c] += k * gap * s.normals(j, c) - k2_eps * (p_lambda[c] - s.normals(j, c) * n_p_lambda);
    }
}

CONTACT_APP_INSTANTIATE_CONTACT_FAMILY(FRICTIONLESS_COMPONENTS)

}  // namespace contact_app
