// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/mortar_contact_families.h"
#include "custom_conditions/mortar_contact_family_condition_impl.h"
#include "custom_utilities/active_set_utilities.h"

namespace contact_app {
namespace {

using namespace frictional_detail;

/// RHS of docs/theory/contact_residuals.md §5 for one pair, q = [u2 (d·n_m), u1 (d·n_s), λ (d·n_s)]. The slip law is
/// nodal (docs/theory/mortar.md §7-8): k Pλ = −μ (kλ_n + ε Q̂) τ̄/|τ̄| with Q̂ the gap the pairs transmit and the
/// direction of the trial traction τ̄ = kPλ + f ε Ŝ (Ŝ the nodal weighted slip, f the node's SLIP_TRIAL_FACTOR)
/// instead of the reference's frozen t = Pλ/|Pλ|, which never turns in 3D; each pair adds its share ω_j of the law.
template <class T, int TDim, int TNS, int TNM, class TState, class TVector>
void AddALMFrictionalResidual(const TState& s, double k, const FrictionalParameters<TDim, TNS>& p,
                              const SlipData<TDim, TNS, TNM>& slip, const NodalInterfaceMap<TDim, TNS>& nodal,
                              TVector& rhs) {
    using Vec = Eigen::Matrix<T, TDim, 1>;
    constexpr int lambda_offset = TDim * (TNS + TNM);
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

}  // namespace

/// The ALM frictional family's residual (mortar_contact_families.h).
template <int TDim, int TNS, bool TNV, int TNM, class TState, class TVector>
void AddFamilyResidual(const MortarContactFamilyCondition<TDim, TNS, FrictionalCase::FRICTIONAL, TNV, TNM>& rCondition,
                       const TState& state, const ProcessInfo& rCurrentProcessInfo, TVector& rhs) {
    using T = typename TVector::Scalar;
    const Geometry& slave = rCondition.GetParentGeometry();
    CONTACT_CHECK(rCurrentProcessInfo.Has(SCALE_FACTOR), InputError, "ALM frictional contact condition ",
                  rCondition.Id(), ": SCALE_FACTOR is not set in the ProcessInfo\n  fix: run the ALM initialisation",
                  " (ALMFastInit) or set ProcessInfo[SCALE_FACTOR]");
    const double k = rCurrentProcessInfo.GetValue(SCALE_FACTOR);
    // Every node divides by ε (inactive and slip rows) and uses κ (inactive rows, stick penalty, slip trial traction).
    const auto p = frictional_detail::ReadFrictionalParameters<TDim, TNS>(
        slave, rCurrentProcessInfo, rCondition.Id(), "ALM", [](bool) { return true; }, [](bool, bool) { return true; });
    const auto slip = rCondition.SlipOfStep(frictional_detail::AnyActive(p));
    AddALMFrictionalResidual<T, TDim, TNS, TNM>(
        state, k, p, slip, MakeNodalInterfaceMap<TDim, TNS>(slave, rCondition.NodalShare(), true),
        rhs);
}

CONTACT_APP_INSTANTIATE_CONTACT_FAMILY(FRICTIONAL)
CONTACT_APP_INSTANTIATE_AXISYM_FAMILY(FRICTIONAL)

}  // namespace contact_app
