// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/mortar_contact_axisym_condition.h"
#include "custom_conditions/mortar_contact_family_condition_impl.h"

#include <type_traits>

namespace contact_app {
namespace {

/// TANGENT_SLIP of the slave nodes (zero where never set).
template <int TDim, int TNS>
Eigen::Matrix<double, TNS, TDim> ElasticSlips(const Geometry& slave) {
    Eigen::Matrix<double, TNS, TDim> e;
    for (int j = 0; j < TNS; ++j) e.row(j) = slave[j].GetValue(TANGENT_SLIP).template head<TDim>().transpose();
    return e;
}

}  // namespace

/// Kratos PenaltyMethodFrictionalMortarContactCondition: MortarContactFamilyCondition with FRICTIONAL_PENALTY.
/// Penalty frictional (Coulomb) mortar contact, displacement DoFs only (docs/theory/contact_residuals.md §7). With the
/// nodal penalty pressure λ̄_j = ε_j η_j G_j (G_j = Σ_c g̃^c_j over the node's pairs, η_j = Σ_c a_c² / A_j²; the
/// reference pushes each pair with its own ε g̃^c: docs/theory/mortar.md §7 "Nodal penalty"), an active node adds
/// S_j[δ_j(λ̄_j n_j + τ_j)], τ_j = −μ_j λ̄_j t_j (SLIP) or κ ε_j (P e_j + T̂_j) (stick), T̂_j the node's slip of the
/// step transmitted by all its pairs (objective or non-objective slip, switch on OPERATOR_THRESHOLD recorded in
/// MODIFIED, as the ALM family); inactive nodes add nothing. ε = INITIAL_PENALTY, δ = DYNAMIC_FACTOR,
/// μ = FRICTION_COEFFICIENT, t = TANGENT_XI (constant), κ = TANGENT_FACTOR. LHS = −∂RHS/∂q by AD. Deviations from
/// the reference (B2): the tangential traction is spread with D, M like the normal one (the reference weights it
/// with D − D_old, M − M_old, so it vanishes for small sliding), and the reference always uses the objective slip.
/// Registers Penalty[NV]FrictionalMortarContactCondition{2D2N,3D3N,3D4N,3D3N4N,3D4N3N}; size d(n_s + n_m).
/// Its 2D axisymmetric variant MortarContactAxisymCondition<...<2, 2, NV>> weights every Gauss weight (current and
/// start-of-step operators, explicit gap and slip) by 2π r / THICKNESS; registers
/// Penalty[NV]FrictionalAxisymMortarContactCondition2D2N.
/// q = [u2 (d·n_m), u1 (d·n_s)]; ε and κ are read on the active nodes only. The tangential traction is a return map
/// (docs/theory/mortar.md §8) on the elastic slip e_j = TANGENT_SLIP carried over from the previous steps plus the slip
/// of the step: stick τ = κε(P e_j + T̂_j), slip τ = −μ λ̄_j t_j along the nodal trial t = (P e + T̂)/|P e + T̂|, T̂ the
/// transmitted slip Σ_c a^c s^c / A, so that every pair of a node pushes with the node's traction. In the AD pass the
/// coupling record keeps, for the other pairs' tangent blocks (nodal_gap_coupling.h), b_j = ∂RHS/∂(ηG)_j =
/// S_j[δ ε (n − μ t)] (slip) or S_j[δ ε n] (stick) with this pair's ∂(ηG)_j/∂q, and B_j = ∂RHS/∂T_j =
/// S_j[−δ μ λ̄ ∂t/∂T] (slip) or S_j[δ κε I] (stick) with this pair's ∂T_j/∂q.
template <int TDim, int TNS, bool TNV, int TNM, class TState, class T, int TSize>
void AddFamilyResidual(
    const MortarContactFamilyCondition<TDim, TNS, FrictionalCase::FRICTIONAL_PENALTY, TNV, TNM>& rCondition,
    const TState& s, const ProcessInfo& rCurrentProcessInfo, Eigen::Matrix<T, TSize, 1>& rhs) {
    using namespace frictional_detail;
    using Vec = Eigen::Matrix<T, TDim, 1>;
    constexpr bool kDifferentiated = !std::is_same_v<T, double>;
    const Geometry& slave = rCondition.GetParentGeometry();
    const auto p = ReadFrictionalParameters<TDim, TNS>(
        slave, rCurrentProcessInfo, rCondition.Id(), "Penalty", [](bool active) { return active; },
        [](bool active, bool) { return active; });
    const auto slip = rCondition.SlipOfStep(AnyActive(p));
    const auto nodal = MakeNodalInterfaceMap<TDim, TNS>(slave, rCondition.NodalShare(), true);
    const Eigen::Matrix<double, TNS, TDim> elastic_slip = ElasticSlips<TDim, TNS>(slave);
    [[maybe_unused]] auto* const record = rCondition.MutableCouplingRecord();
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
        // Both laws read the slip all the node's pairs transmit, T̂ (nodal laws: every pair of the node pushes with the
        // same traction; a stick force κε(e + s^c) per pair spread unequal forces to the masters at an edge node,
        // whose stick state then left the cone and its slip state reversed: docs/theory/mortar.md §8 "Nodal stick").
        const Vec transmitted = nodal.TransmittedSlip(j, PairArea<T>(s, j), pair_slip);
        const double trial_factor = p.tangent_factor * eps;
        const Vec trial = (carried + transmitted) * trial_factor;
        [[maybe_unused]] Eigen::Matrix<double, TDim, TDim> force_per_slip;  // ∂τ_j/∂T̂_j
        if (p.slip[j]) {  // Coulomb: |τ| = μ |λ̄| along the nodal trial
            const double scale = std::abs(Value(pressure)) + 1e-300;
            const Vec direction = SlipDirection<T, TDim, TNS>(trial, p, j, scale);
            force -= direction * (p.mu[j] * pressure);
            force_per_pressure -= p.mu[j] * Values(direction);
            if constexpr (kDifferentiated) {
                if (record != nullptr)  // ∂t/∂T = κε ∂t/∂trial: the direction function differentiated in the trial
                    force_per_slip = Jacobian(SlipDirection<Dual<TDim>, TDim, TNS>(
                                         Seed<TDim>(Eigen::Matrix<double, TDim, 1>(Values(trial))), p, j, scale)) *
                                     (-p.mu[j] * Value(pressure) * trial_factor);
            }
        } else {  // stick: τ = κε(e + T̂)
            force += trial;
            force_per_slip = Eigen::Matrix<double, TDim, TDim>::Identity() * trial_factor;
        }
        SpreadForce<T, TDim, TNS, TNM>(s, j, Vec(force * dynamic_factor), rhs);
        if constexpr (kDifferentiated) {
            if (record == nullptr) continue;
            SpreadForceValues<TDim, TNS, TNM>(s, j, Eigen::Matrix<double, TDim, TDim>(force_per_slip * dynamic_factor),
                                              record->force_per_slip[j]);
            for (int c = 0; c < TDim; ++c) record->SetSlipGradientRow(j, c, transmitted[c].Derivatives());
            record->reads_slip[j] = true;
            RecordNodalGapCoupling<T, TDim, TNS, TNM>(
                s, j, Eigen::Matrix<double, TDim, 1>(force_per_pressure * (eps * dynamic_factor)), gap, *record);
        }
    }
}

CONTACT_APP_INSTANTIATE_CONTACT_FAMILY(FRICTIONAL_PENALTY)
CONTACT_APP_INSTANTIATE_AXISYM_FAMILY(FRICTIONAL_PENALTY)

}  // namespace contact_app
