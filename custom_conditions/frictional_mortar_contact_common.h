// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// Pieces shared by the two frictional families (ALM frictional and penalty frictional): the Σ s_i 3^i state
/// encoding, the nodal friction data (μ_j, t_j, κ), the two slip measures, the objective switch, the once-per-step
/// computation of the start-of-step operators (`PreviousMortarOperators`, previous_mortar_operators.h, which MPC
/// friction shares), and the explicit WEIGHTED_GAP + WEIGHTED_SLIP contribution. Builds on
/// frictionless_mortar_contact_common.h. Internal to custom_conditions/. Equations: docs/theory/contact_residuals.md
/// §2 (slip measures), §5, §7; docs/theory/active_set.md §3.

#include <array>
#include <cmath>

#include <Eigen/Core>

#include "automatic_differentiation/dual.h"
#include "custom_conditions/frictionless_mortar_contact_common.h"
#include "custom_conditions/previous_mortar_operators.h"
#include "custom_utilities/active_set_utilities.h"

namespace contact_app::frictional_detail {

using namespace frictionless_detail;

/// Default of ProcessInfo[OPERATOR_THRESHOLD] (the reference's compile-time constant, area units).
inline constexpr double kDefaultOperatorThreshold = 1e-3;

/// Σ_i s_i 3^i, s_i = 0 inactive, 1 active-slip, 2 active-stick.
template <int TNS>
int FrictionalStateValue(const Geometry& slave) {
    int value = 0, power = 1;
    for (int j = 0; j < TNS; ++j, power *= 3)
        if (slave[j].Is(ACTIVE)) value += (slave[j].Is(SLIP) ? 1 : 2) * power;
    return value;
}

/// The tangent used when TANGENT_XI is zero: 2D (n_y, −n_x); 3D the first vector of an orthonormal basis of
/// n (the larger of n_x, n_z picks which component is dropped, so the division is never ill-conditioned).
template <int TDim>
Eigen::Matrix<double, TDim, 1> FallbackTangent(const Eigen::Matrix<double, TDim, 1>& n) {
    Eigen::Matrix<double, TDim, 1> t;
    if constexpr (TDim == 2) {
        t << n[1], -n[0];
    } else {
        if (std::abs(n[0]) > std::abs(n[2]))
            t << -n[1], n[0], 0.0;
        else
            t << 0.0, -n[2], n[1];
        t.normalize();
    }
    return t;
}

/// Per-node constants of a frictional residual (none differentiated, docs/theory/contact_residuals.md §8).
template <int TDim, int TNS>
struct FrictionalParameters {
    NodalParameters<TNS> nodal;                ///< ε_j, δ_j, ACTIVE
    std::array<bool, TNS> slip{};              ///< SLIP (active nodes): slip, otherwise stick
    Eigen::Matrix<double, TNS, 1> mu;          ///< FRICTION_COEFFICIENT
    Eigen::Matrix<double, TNS, TDim> tangent;  ///< TANGENT_XI, or the fallback of n_j
    /// 0 where a VECTOR_LAGRANGE_MULTIPLIER component is a fixed DoF (a symmetry plane, docs/theory/mortar.md §8), else
    /// 1: a held component carries no traction, so the slip direction leaves it out.
    Eigen::Matrix<double, TNS, TDim> free_components = Eigen::Matrix<double, TNS, TDim>::Ones();
    double tangent_factor = 0.0;  ///< κ = TANGENT_FACTOR
    /// c_t/ε of the ALM slip trial per node (ActiveSetUtilities::SlipTrialFactor, held constant in the tangent)
    Eigen::Matrix<double, TNS, 1> slip_trial_factor = Eigen::Matrix<double, TNS, 1>::Ones();
};

/// Reads ε, δ, ACTIVE (via ReadNodalParameters, @p penalty_required_on as there), SLIP, μ, t and κ.
/// @throws InputError if κ is needed (@p needs_kappa(active, slip) for some node) but TANGENT_FACTOR is not a
///         positive ProcessInfo value
template <int TDim, int TNS, class TRequired, class TNeedsKappa>
FrictionalParameters<TDim, TNS> ReadFrictionalParameters(const Geometry& slave, const ProcessInfo& process_info,
                                                         IndexType id, const char* method,
                                                         TRequired&& penalty_required_on, TNeedsKappa&& needs_kappa) {
    FrictionalParameters<TDim, TNS> p;
    p.nodal = ReadNodalParameters<TNS>(slave, id, method, penalty_required_on);
    const Node* needs_kappa_node = nullptr;  // the first node whose rows use κ
    for (int j = 0; j < TNS; ++j) {
        const Node& node = slave[j];
        p.slip[j] = node.Is(SLIP);
        p.mu[j] = node.GetValue(FRICTION_COEFFICIENT);
        p.slip_trial_factor[j] = ActiveSetUtilities::SlipTrialFactor(node, process_info);
        Eigen::Matrix<double, TDim, 1> t = node.GetValue(TANGENT_XI).template head<TDim>();
        if (!(t.norm() > 0.0)) t = FallbackTangent<TDim>(ToSpatialVector<TDim>(node.FastGetSolutionStepValue(NORMAL)));
        p.tangent.row(j) = t.transpose();
        for (int c = 0; c < TDim; ++c)
            if (ContactUtilities::IsMultiplierComponentHeld(node, c)) p.free_components(j, c) = 0.0;
        if (!needs_kappa_node && needs_kappa(p.nodal.active[j], p.slip[j])) needs_kappa_node = &node;
    }
    if (process_info.Has(TANGENT_FACTOR)) p.tangent_factor = process_info.GetValue(TANGENT_FACTOR);
    CONTACT_CHECK(!needs_kappa_node || p.tangent_factor > 0.0, InputError, method, " frictional contact condition ", id,
                  ": TANGENT_FACTOR is ", process_info.Has(TANGENT_FACTOR) ? "not positive" : "not set",
                  " in the ProcessInfo, but slave node ", needs_kappa_node ? needs_kappa_node->Id() : 0, " (",
                  !needs_kappa_node || needs_kappa_node->IsNot(ACTIVE) ? "inactive"
                  : needs_kappa_node->Is(SLIP)                          ? "slip"
                                                                        : "stick",
                  ") uses it",
                  "\n  expected: κ > 0, the ratio of the tangential to the normal penalty",
                  "\n  fix: set ProcessInfo[TANGENT_FACTOR] (the contact process sets it from \"tangent_factor\")");
    return p;
}

/// What a stick row needs to measure the slip of the step.
template <int TDim, int TNS, int TNM>
struct SlipData {
    const MortarOperators<double, TNS, TNM>* previous = nullptr;  ///< D_old, M_old (objective)
    NodeCoordinates<double, TDim, TNS> x1_previous = NodeCoordinates<double, TDim, TNS>::Zero();  ///< X0 + d(1)
    NodeCoordinates<double, TDim, TNM> x2_previous = NodeCoordinates<double, TDim, TNM>::Zero();
    bool objective = false;
};

/// P_j v = v − n_j (n_j·v).
template <class T, int TDim, class TState, class TVec>
Eigen::Matrix<T, TDim, 1> ProjectTangent(const TState& s, int j, const TVec& v) {
    const Eigen::Matrix<T, TDim, 1> n = s.normals.row(j).transpose();
    const T normal_part = n.dot(v);
    return v - n * normal_part;
}

/// s_j = P_j[(D − D_old) x1 − (M − M_old) x2]_j (objective) or −P_j[D (x1 − x1^n) − M (x2 − x2^n)]_j with the
/// start-of-step x^n = X0 + d(1): the true increment of the step, as the explicit WEIGHTED_SLIP (fixes B1).
template <class T, int TDim, int TNS, int TNM, class TState>
Eigen::Matrix<T, TDim, 1> TangentSlip(const TState& s, const SlipData<TDim, TNS, TNM>& d, int j) {
    Eigen::Matrix<T, 1, TDim> r;
    if (d.objective) {
        const Eigen::Matrix<T, 1, TNS> dd = s.operators.D.row(j) - d.previous->D.row(j).template cast<T>();
        const Eigen::Matrix<T, 1, TNM> dm = s.operators.M.row(j) - d.previous->M.row(j).template cast<T>();
        r = frictionless_detail::MortarDifference<T, TDim>(s, dd, dm);
    } else {
        const NodeCoordinates<T, TDim, TNS> dx1 = s.x1 - d.x1_previous.template cast<T>();
        const NodeCoordinates<T, TDim, TNM> dx2 = s.x2 - d.x2_previous.template cast<T>();
        r = -(s.operators.D.row(j) * dx1 - s.operators.M.row(j) * dx2);
    }
    return ProjectTangent<T, TDim>(s, j, Eigen::Matrix<T, TDim, 1>(r.transpose()));
}

/// Once per step (guarded by previous.initialized): D, M of the pair in the start-of-step configuration
/// X0 + d(1) (the mesh coordinates when the mesh is not moved), with the condition's integration settings (so axisymmetric pairs carry 2πr/t, unlike the reference).
template <int TDim, int TNS, int TNM, class TCondition>
void ComputePreviousOperatorsOnce(const TCondition& condition, const ProcessInfo& process_info,
                                  PreviousMortarOperators<TNS, TNM>& previous) {
    if (previous.initialized) return;
    const MortarIntegrator<TDim, TNS, TNM, double> integrator(condition.IntegrationSettings(),
                                                              condition.SegmentationSettingsFrom(process_info));
    const Geometry& slave = condition.GetParentGeometry();
    const Geometry& master = condition.GetPairedGeometry();
    // A fixed mesh (geometrically linear contact) keeps its operators: those of the mesh coordinates.
    bool slave_follows = true, master_follows = true;
    CurrentCoordinates<TDim, TNS>(slave, &slave_follows);
    CurrentCoordinates<TDim, TNM>(master, &master_follows);
    const bool finite_sliding = slave_follows && master_follows;
    const auto x1 = finite_sliding ? CoordinatesAtStep<TDim, TNS>(slave, 1) : MeshCoordinates<TDim, TNS>(slave);
    const auto x2 = finite_sliding ? CoordinatesAtStep<TDim, TNM>(master, 1) : MeshCoordinates<TDim, TNM>(master);
    bool dual = false;
    previous.Set(ComputePreviousMortarOperators<TDim, TNS, TNM>(
        integrator, x1, ToSpatialVector<TDim>(condition.GetValue(NORMAL)), x2, NodalNormals<TDim, TNS>(slave), dual));
}

/// Objective iff the pair overlapped at the start of the step and ‖D − D_old‖_F > τ and ‖M − M_old‖_F > τ,
/// τ = OPERATOR_THRESHOLD (default 1e−3).
template <int TNS, int TNM>
bool IsObjective(const MortarOperators<double, TNS, TNM>& current, const PreviousMortarOperators<TNS, TNM>& previous,
                 const ProcessInfo& process_info) {
    const double threshold =
        process_info.Has(OPERATOR_THRESHOLD) ? process_info.GetValue(OPERATOR_THRESHOLD) : kDefaultOperatorThreshold;
    return previous.initialized && previous.overlap && (current.D - previous.operators.D).norm() > threshold &&
           (current.M - previous.operators.M).norm() > threshold;
}

/// The slip data of one evaluation: the start-of-step coordinates are read only when an active node needs the slip
/// and the pair is not objective (buffer ≥ 2).
template <int TDim, int TNS, int TNM, class TCondition>
SlipData<TDim, TNS, TNM> MakeSlipData(const TCondition& condition, const PreviousMortarOperators<TNS, TNM>& previous,
                                      bool needs_slip) {
    SlipData<TDim, TNS, TNM> d;
    d.previous = &previous.operators;
    d.objective = condition.IsNot(MODIFIED) && previous.initialized && previous.overlap;
    if (needs_slip && !d.objective) {
        d.x1_previous = CoordinatesAtStep<TDim, TNS>(condition.GetParentGeometry(), 1);
        d.x2_previous = CoordinatesAtStep<TDim, TNM>(condition.GetPairedGeometry(), 1);
    }
    return d;
}

/// Whether some slave node is active (its residual rows then use the slip of the step).
template <int TDim, int TNS>
bool AnyActive(const FrictionalParameters<TDim, TNS>& p) {
    for (int j = 0; j < TNS; ++j)
        if (p.nodal.active[j]) return true;
    return false;
}

/// Explicit pass of a frictional pair: as AddFrictionlessExplicitContribution, plus the objective switch of this
/// configuration (recorded in MODIFIED, the rule of InitializeResidual) and the pair's slip s_j of the step, added to
/// the historical WEIGHTED_SLIP and kept in the share. The slip is TangentSlip, the very function the residual uses.
template <int TDim, int TNS, int TNM, class TCondition>
void AddFrictionalExplicitContribution(TCondition& condition, const ProcessInfo& process_info,
                                       const PreviousMortarOperators<TNS, TNM>& previous) {
    typename TCondition::template State<double> state;
    if (!IntegrateForExplicitPass<TDim, TNS, TNM>(condition, process_info, state)) return;
    condition.Set(MODIFIED, !IsObjective(state.operators, previous, process_info));
    const auto slip = MakeSlipData<TDim, TNS, TNM>(condition, previous, true);
    PairNodalShare<TDim, TNS>& share = condition.MutableNodalShare();
    Geometry& slave = *condition.pGetParentGeometry();
    for (int j = 0; j < TNS; ++j) {
        share.area[j] = PairArea<double>(state, j);
        share.gap[j] = PairGap<double, TDim>(state, j);
        share.slip.row(j) = TangentSlip<double, TDim, TNS, TNM>(state, slip, j).transpose();
        AddPairShareToNode(slave[j], share.area[j], share.gap[j]);
        slave[j].FastGetSolutionStepValue(WEIGHTED_SLIP).template head<TDim>() += share.slip.row(j).transpose();
        Array3 weighted = slave[j].GetValue(AREA_WEIGHTED_PAIR_SLIP);
        weighted.template head<TDim>() += share.area[j] * share.slip.row(j).transpose();
        slave[j].SetValue(AREA_WEIGHTED_PAIR_SLIP, weighted);
    }
}

/// The Coulomb slip direction of node j: the trial traction τ̄ = kPλ + κεŜ (ALM) or κεŜ (penalty) normalised; the
/// fallback tangent t_j when τ̄ vanishes (no slip and no tangential multiplier yet). docs/theory/mortar.md §8.
template <class T, int TDim, int TNS>
Eigen::Matrix<T, TDim, 1> SlipDirection(const Eigen::Matrix<T, TDim, 1>& trial, const FrictionalParameters<TDim, TNS>& p,
                                        int j, double scale) {
    using std::sqrt;
    const T norm_squared = trial.dot(trial);
    if (!(Value(norm_squared) > 1e-28 * scale * scale)) return p.tangent.row(j).transpose().template cast<T>();
    return trial / sqrt(norm_squared);
}

/// Check() of both families: WEIGHTED_SLIP historical on the slave nodes and a buffer of at least 2 steps
/// (the start-of-step configuration X0 + d(1)).
template <int TDim, int TNS>
void CheckFrictionalVariables(const Geometry& slave, IndexType id) {
    for (int j = 0; j < TNS; ++j) {
        CONTACT_CHECK(slave[j].SolutionStepsDataHas(WEIGHTED_SLIP), InputError, "frictional contact condition ", id,
                      ": slave node ", slave[j].Id(), " does not store WEIGHTED_SLIP as a historical variable",
                      "\n  fix: use a frictional mortar_type (\"ALMContactFrictional\" / \"PenaltyContactFrictional\")",
                      " so the solver adds it");
        CONTACT_CHECK(slave[j].GetBufferSize() >= 2, InputError, "frictional contact condition ", id, ": slave node ",
                      slave[j].Id(), " has a buffer of ", slave[j].GetBufferSize(),
                      " step(s)\n  expected: at least 2 (the slip needs the start-of-step displacement)",
                      "\n  fix: set the model part buffer size to 2 or more");
    }
}

}  // namespace contact_app::frictional_detail
