// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/mortar_contact_families.h"
#include "custom_conditions/mortar_contact_family_condition_impl.h"

#include <type_traits>

namespace contact_app {
namespace {

using namespace frictional_detail;

/// RHS of docs/theory/contact_residuals.md §7 with B2 fixed, q = [u2 (d·n_m), u1 (d·n_s)]: S_j[δ_j(λ̄_j n_j + τ_j)] on the
/// active nodes, nothing on the inactive ones, with the nodal penalty pressure λ̄_j = ε_j η_j Ĝ_j (Ĝ the node's
/// weighted gap over all its pairs, η_j = Σ_c a_c² / A_j²: docs/theory/mortar.md §7 "Nodal penalty"). The tangential
/// traction is a return map (docs/theory/mortar.md §8) on the elastic slip e_j = TANGENT_SLIP carried over from the
/// previous steps plus the slip of the step: stick τ = κε(P e_j + s_j), slip τ = −μ λ̄_j t_j along the nodal trial
/// t = (P e + T̂)/|P e + T̂|, T̂ the transmitted slip Σ_c a^c s^c / A (what the stick rows of all pairs transmit), so
/// that every pair transmits |τ| = μ |λ̄|. In the AD pass @p record keeps, for the other pairs' tangent blocks
/// (nodal_gap_coupling.h), b_j = ∂RHS/∂(ηG)_j = S_j[δ ε (n − μ t)] (slip) or S_j[δ ε n] (stick) with this pair's
/// ∂(ηG)_j/∂q, and at a slipping node B_j = ∂RHS/∂T_j = S_j[−δ μ λ̄ ∂t/∂T] with this pair's ∂T_j/∂q.
template <class T, int TDim, int TNS, int TNM, class TState, class TVector, class TRecord>
void AddPenaltyFrictionalResidual(const TState& s, const FrictionalParameters<TDim, TNS>& p,
                                  const SlipData<TDim, TNS, TNM>& slip, const NodalInterfaceMap<TDim, TNS>& nodal,
                                  const Eigen::Matrix<double, TNS, TDim>& elastic_slip, TVector& rhs, TRecord* record) {
    using Vec = Eigen::Matrix<T, TDim, 1>;
    constexpr bool kDifferentiated = !std::is_same_v<T, double>;
    for (int j = 0; j < TNS; ++j) {
        if (!p.nodal.active[j]) continue;
        const double eps = p.nodal.penalty[j];
        const double dynamic_factor = p.nodal.dynamic_factor[j];
        const T gap = nodal.PenaltyGap(j, PairGap<T, TDim>(s, j), PairArea<T>(s, j));
        const T pressure = eps * gap;  // λ̄ < 0 in contact
        const Vec n = s.normals.row(j).transpose();
        const Vec carried = ProjectTangent<T, TDim>(s, j, Vec(elastic_slip.row(j).transpose().template cast<T>()));
        const Vec pair_slip = TangentSlip<T, TDim, TNS, TNM>(s, slip, j);
        Vec force = n * pressure;
        Eigen::Matrix<double, TDim, 1> force_per_pressure = Values(n);
        if (p.slip[j]) {  // Coulomb: |τ| = μ |λ̄| along the nodal trial
            const Vec transmitted = nodal.TransmittedSlip(j, PairArea<T>(s, j), pair_slip);
            const double trial_factor = p.tangent_factor * eps;
            const Vec trial = (carried + transmitted) * trial_factor;
            const double scale = std::abs(Value(pressure)) + 1e-300;
            const Vec direction = SlipDirection<T, TDim, TNS>(trial, p, j, scale);
            force -= direction * (p.mu[j] * pressure);
            force_per_pressure -= p.mu[j] * Values(direction);
            if constexpr (kDifferentiated) {
                if (record != nullptr) {
                    // ∂t/∂T = κε ∂t/∂trial: the same direction function, differentiated in the trial's components.
                    const auto direction_per_trial = Jacobian(SlipDirection<Dual<TDim>, TDim, TNS>(
                        Seed<TDim>(Eigen::Matrix<double, TDim, 1>(Values(trial))), p, j, scale));
                    const Eigen::Matrix<double, TDim, TDim> force_per_slip =
                        direction_per_trial * (-p.mu[j] * Value(pressure) * trial_factor * dynamic_factor);
                    SpreadForceValues<TDim, TNS, TNM>(s, j, force_per_slip, record->force_per_slip[j]);
                    for (int c = 0; c < TDim; ++c) record->slip_gradient[j].row(c) = transmitted[c].Derivatives();
                    record->slipping[j] = true;
                }
            }
        } else {
            force += (carried + pair_slip) * (p.tangent_factor * eps);
        }
        SpreadForce<T, TDim, TNS, TNM>(s, j, Vec(force * dynamic_factor), rhs);
        if constexpr (kDifferentiated) {
            if (record == nullptr) continue;
            RecordNodalGapCoupling<T, TDim, TNS, TNM>(
                s, j, Eigen::Matrix<double, TDim, 1>(force_per_pressure * (eps * dynamic_factor)), gap, *record);
        } else {
            (void)record;
        }
    }
}

/// TANGENT_SLIP of the slave nodes (zero where never set).
template <int TDim, int TNS>
Eigen::Matrix<double, TNS, TDim> ElasticSlips(const Geometry& slave) {
    Eigen::Matrix<double, TNS, TDim> e;
    for (int j = 0; j < TNS; ++j) e.row(j) = slave[j].GetValue(TANGENT_SLIP).template head<TDim>().transpose();
    return e;
}

}  // namespace

/// The penalty frictional family's residual (mortar_contact_families.h): ε and κ on the active nodes (the inactive
/// ones add nothing).
template <int TDim, int TNS, bool TNV, int TNM, class TState, class TVector>
void AddFamilyResidual(
    const MortarContactFamilyCondition<TDim, TNS, FrictionalCase::FRICTIONAL_PENALTY, TNV, TNM>& rCondition,
    const TState& state, const ProcessInfo& rCurrentProcessInfo, TVector& rhs) {
    using T = typename TVector::Scalar;
    const Geometry& slave = rCondition.GetParentGeometry();
    const auto p = frictional_detail::ReadFrictionalParameters<TDim, TNS>(
        slave, rCurrentProcessInfo, rCondition.Id(), "Penalty", [](bool active) { return active; },
        [](bool active, bool) { return active; });
    const auto slip = rCondition.SlipOfStep(frictional_detail::AnyActive(p));
    AddPenaltyFrictionalResidual<T, TDim, TNS, TNM>(
        state, p, slip, MakeNodalInterfaceMap<TDim, TNS>(slave, rCondition.NodalShare(), true),
        ElasticSlips<TDim, TNS>(slave), rhs, rCondition.MutableCouplingRecord());
}

CONTACT_APP_INSTANTIATE_CONTACT_FAMILY(FRICTIONAL_PENALTY)
CONTACT_APP_INSTANTIATE_AXISYM_FAMILY(FRICTIONAL_PENALTY)

}  // namespace contact_app
