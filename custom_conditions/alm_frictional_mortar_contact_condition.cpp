// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/mortar_contact_axisym_condition.h"
#include "custom_conditions/mortar_contact_family_condition_impl.h"
#include "custom_utilities/active_set_utilities.h"

namespace contact_app {

/// Kratos AugmentedLagrangianMethodFrictionalMortarContactCondition: MortarContactFamilyCondition with FRICTIONAL.
/// ALM frictional (Coulomb) mortar contact, vector multiplier λ_j = VECTOR_LAGRANGE_MULTIPLIER
/// (docs/theory/contact_residuals.md §5). With g̃_j = −n_j·(D x1 − M x2)_j, P_j = I − n_j n_jᵀ, λ̄_n = k n·λ + ε g̃:
/// inactive RHS_λ = −k²/ε λ_n n − k²/(κε) PᵀPλ; slip S_j[δ(kλ + εg̃n)], RHS_λ = k g̃ n − k/ε Pᵀ(kPλ + μ λ̄_n t); stick
/// S_j[δ(kλ + εg̃n + κε s)], RHS_λ = k g̃ n + k Pᵀ s, s the objective or non-objective slip (switch on
/// OPERATOR_THRESHOLD, recorded in MODIFIED). k = SCALE_FACTOR, κ = TANGENT_FACTOR, ε = INITIAL_PENALTY, δ =
/// DYNAMIC_FACTOR, μ = FRICTION_COEFFICIENT, t = TANGENT_XI (held constant). LHS = −∂RHS/∂q by AD. Registers
/// ALM[NV]FrictionalMortarContactCondition{2D2N,3D3N,3D4N,3D3N4N,3D4N3N}; local system [master u, slave u, slave λ] of
/// size d(2n_s + n_m). The non-objective slip uses the true step increment x − (X0 + d(1)) (reference bug B1 fixed);
/// buffer size 2 suffices.
/// Its 2D axisymmetric variant MortarContactAxisymCondition<...<2, 2, NV>> weights every Gauss weight (current and
/// start-of-step operators, explicit gap and slip) by 2π r / THICKNESS; registers
/// ALM[NV]FrictionalAxisymMortarContactCondition2D2N.
/// q = [u2 (d·n_m), u1 (d·n_s), λ (d·n_s)]. The slip law is nodal (docs/theory/mortar.md §7-8): k Pλ = −μ (kλ_n + ε Q̂)
/// τ̄/|τ̄| with Q̂ the gap the pairs transmit and the direction of the trial traction τ̄ = kPλ + f ε Ŝ (Ŝ the nodal
/// weighted slip, f the node's SLIP_TRIAL_FACTOR) instead of the reference's frozen t = Pλ/|Pλ|, which never turns in
/// 3D; each pair adds its share ω_j of the law. Every node divides by ε (inactive and slip rows) and uses κ (inactive
/// rows, stick penalty, slip trial traction).
template <int TDim, int TNS, bool TNV, int TNM, class TState, class T, int TSize>
void AddFamilyResidual(const MortarContactFamilyCondition<TDim, TNS, FrictionalCase::FRICTIONAL, TNV, TNM>& rCondition,
                       const TState& s, const ProcessInfo& rCurrentProcessInfo, Eigen::Matrix<T, TSize, 1>& rhs) {
    using namespace frictional_detail;
    using Vec = Eigen::Matrix<T, TDim, 1>;
    constexpr int lambda_offset = TDim * (TNS + TNM);
    const Geometry& slave = rCondition.GetParentGeometry();
    const double k = ReadScaleFactor(rCurrentProcessInfo, rCondition.Id(), "ALM frictional contact condition");
    const auto p = ReadFrictionalParameters<TDim, TNS>(
        slave, rCurrentProcessInfo, rCondition.Id(), "ALM", [](bool) { return true; }, [](bool, bool) { return true; });
    const auto slip = rCondition.SlipOfStep(AnyActive(p));
    const auto nodal = MakeNodalInterfaceMap<TDim, TNS>(slave, rCondition.NodalShare(), true);
    for (int j = 0; j < TNS; ++j) {
        const double eps = p.nodal.penalty[j];
        const int row = lambda_offset + j * TDim;
        const Vec n = s.normals.row(j).transpose();
        const Vec lambda = s.multipliers.template segment<TDim>(j * TDim);
        const T lambda_n = n.dot(lambda);
        const Vec p_lambda = ProjectTangent<T, TDim>(s, j, lambda);
        Vec lambda_row;
        if (!p.nodal.active[j]) {  // −k²/ε λ_n n − k²/(κε) PᵀPλ
            lambda_row = n * (-(k * k / eps) * lambda_n) -
                         ProjectTangent<T, TDim>(s, j, p_lambda) * (k * k / (p.tangent_factor * eps));
            for (int c = 0; c < TDim; ++c) rhs[row + c] += lambda_row[c];
            continue;
        }
        const T gap = PairGap<T, TDim>(s, j);
        const Vec pair_slip = TangentSlip<T, TDim, TNS, TNM>(s, slip, j);
        Vec force = lambda * k + n * (eps * gap);
        lambda_row = n * (k * gap);
        if (p.slip[j]) {  // Coulomb slip, weighted by ω_j so that the pairs assemble the nodal law exactly
            const T augmented_normal = k * lambda_n + eps * nodal.TransmittedGap(j, gap, PairArea<T>(s, j));
            const Vec trial = (p_lambda * k + nodal.Slip(j, pair_slip) * (p.slip_trial_factor[j] * eps))
                                  .cwiseProduct(p.free_components.row(j).transpose().template cast<T>());
            const Vec direction = SlipDirection<T, TDim, TNS>(trial, p, j, std::abs(Value(augmented_normal)) + 1e-300);
            const Vec traction = p_lambda * k + direction * (p.mu[j] * augmented_normal);
            lambda_row -= ProjectTangent<T, TDim>(s, j, traction) * (nodal.weight[j] * k / eps);
        } else {  // zero weighted slip of the step, stick penalty κεs
            force += pair_slip * (p.tangent_factor * eps);
            lambda_row += ProjectTangent<T, TDim>(s, j, pair_slip) * k;
        }
        SpreadForce<T, TDim, TNS, TNM>(s, j, Vec(force * p.nodal.dynamic_factor[j]), rhs);
        for (int c = 0; c < TDim; ++c) rhs[row + c] += lambda_row[c];
    }
}

CONTACT_APP_INSTANTIATE_CONTACT_FAMILY(FRICTIONAL)
CONTACT_APP_INSTANTIATE_AXISYM_FAMILY(FRICTIONAL)

}  // namespace contact_app
