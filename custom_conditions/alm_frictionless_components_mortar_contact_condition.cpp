// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/mortar_contact_families.h"
#include "custom_conditions/mortar_contact_family_condition_impl.h"

#include "custom_conditions/frictionless_mortar_contact_common.h"

namespace contact_app {
namespace {

using namespace frictionless_detail;

/// RHS of docs/theory/contact_residuals.md §4 for one pair, q = [u2 (d·n_m), u1 (d·n_s), λ (d·n_s)].
template <class T, int TDim, int TNS, int TNM, class TState, class TVector>
void AddFrictionlessComponentsResidual(const TState& s, double k, const NodalParameters<TNS>& p, TVector& rhs) {
    using Vec = Eigen::Matrix<T, TDim, 1>;
    constexpr int lambda_offset = TDim * (TNS + TNM);
    for (int j = 0; j < TNS; ++j) {
        const double eps = p.penalty[j];
        const double k2_eps = k * k / eps;
        const int row = lambda_offset + j * TDim;
        if (!p.active[j]) {
            for (int c = 0; c < TDim; ++c) rhs[row + c] += -k2_eps * s.multipliers[j * TDim + c];
            continue;
        }
        const T gap = PairGap<T, TDim>(s, j);
        T lambda_n = T(0.0);  // n·λ
        for (int c = 0; c < TDim; ++c) lambda_n += s.normals(j, c) * s.multipliers[j * TDim + c];
        Vec force, p_lambda;  // δ (k λ + ε g̃ n), P λ
        for (int c = 0; c < TDim; ++c) {
            force[c] = p.dynamic_factor[j] * (k * s.multipliers[j * TDim + c] + eps * gap * s.normals(j, c));
            p_lambda[c] = s.multipliers[j * TDim + c] - s.normals(j, c) * lambda_n;
        }
        SpreadForce<T, TDim, TNS, TNM>(s, j, force, rhs);
        T n_p_lambda = T(0.0);  // n·(P λ): Pᵀ P λ = P λ − n (n·P λ), kept as in the generated code
        for (int c = 0; c < TDim; ++c) n_p_lambda += s.normals(j, c) * p_lambda[c];
        for (int c = 0; c < TDim; ++c)
            rhs[row + c] += k * gap * s.normals(j, c) - k2_eps * (p_lambda[c] - s.normals(j, c) * n_p_lambda);
    }
}

}  // namespace

/// The ALM frictionless components family's residual (mortar_contact_families.h).
template <int TDim, int TNS, bool TNV, int TNM, class TState, class TVector>
void AddFamilyResidual(
    const MortarContactFamilyCondition<TDim, TNS, FrictionalCase::FRICTIONLESS_COMPONENTS, TNV, TNM>& rCondition,
    const TState& state, const ProcessInfo& rCurrentProcessInfo, TVector& rhs) {
    using T = typename TVector::Scalar;
    const auto [k, p] =
        ReadALMParameters<TNS>(rCondition.GetParentGeometry(), rCurrentProcessInfo, rCondition.Id());
    AddFrictionlessComponentsResidual<T, TDim, TNS, TNM>(state, k, p, rhs);
}

CONTACT_APP_INSTANTIATE_CONTACT_FAMILY(FRICTIONLESS_COMPONENTS)

}  // namespace contact_app
