// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// Pieces shared by the frictionless families (ALM, ALM components and penalty): the displacement DoF blocks, the Σ 2^i
/// state encoding, the nodal constants k / ε_j / δ_j, the pair gap g̃_j, the spread of a nodal normal force and the
/// explicit pass (WEIGHTED_GAP, NODAL_AREA and the pair's share of them, pair_nodal_share.h). Internal to custom_conditions/.

#include <array>
#include <utility>

#include <Eigen/Core>

#include "automatic_differentiation/ad_helpers.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "custom_conditions/mortar_contact_condition.h"
#include "custom_utilities/mortar_explicit_contribution.h"
#include "custom_utilities/mortar_geometry_adapters.h"

namespace contact_app::frictionless_detail {

inline const Variable<double>* const kDisplacementComponents[] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};

/// Appends [master DISPLACEMENT_*, slave DISPLACEMENT_*] (the first d(n_s + n_m) entries of q).
template <int TDim, int TNS, int TNM>
void AppendDisplacementDofs(const Geometry& slave, const Geometry& master, DofsVectorType& dofs) {
    for (int l = 0; l < TNM; ++l)
        for (int c = 0; c < TDim; ++c) dofs.push_back(&master[l].GetDof(*kDisplacementComponents[c]));
    for (int j = 0; j < TNS; ++j)
        for (int c = 0; c < TDim; ++c) dofs.push_back(&slave[j].GetDof(*kDisplacementComponents[c]));
}

inline const Variable<double>* const kVectorMultiplierComponents[] = {
    &VECTOR_LAGRANGE_MULTIPLIER_X, &VECTOR_LAGRANGE_MULTIPLIER_Y, &VECTOR_LAGRANGE_MULTIPLIER_Z};

/// Appends the slave VECTOR_LAGRANGE_MULTIPLIER_* DoFs, node by node (the λ block of the vector-multiplier families).
template <int TDim, int TNS>
void AppendVectorMultiplierDofs(const Geometry& slave, DofsVectorType& dofs) {
    for (int j = 0; j < TNS; ++j)
        for (int c = 0; c < TDim; ++c) dofs.push_back(&slave[j].GetDof(*kVectorMultiplierComponents[c]));
}

/// The λ block of q for the vector-multiplier families: VECTOR_LAGRANGE_MULTIPLIER of each slave node.
template <int TDim, int TNS, class TVector>
TVector VectorMultiplierValues(const Geometry& slave) {
    TVector lambda;
    for (int j = 0; j < TNS; ++j)
        lambda.template segment<TDim>(j * TDim) =
            slave[j].FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER).template head<TDim>();
    return lambda;
}

/// @throws InputError naming the node and @p mortar_type if a slave node lacks VECTOR_LAGRANGE_MULTIPLIER (historical)
///         or its DoFs
template <int TDim, int TNS>
void CheckVectorMultiplier(const Geometry& slave, IndexType id, const char* mortar_type) {
    for (int j = 0; j < TNS; ++j) {
        bool has = slave[j].SolutionStepsDataHas(VECTOR_LAGRANGE_MULTIPLIER);
        for (int c = 0; c < TDim; ++c) has = has && slave[j].HasDofFor(*kVectorMultiplierComponents[c]);
        CONTACT_CHECK(has, InputError, "condition ", id, ": slave node ", slave[j].Id(),
                      " lacks VECTOR_LAGRANGE_MULTIPLIER (historical variable and _X/_Y", TDim == 3 ? "/_Z" : "",
                      " DoFs)\n  fix: use mortar_type \"", mortar_type, "\" so the solver adds them");
    }
}

/// Σ_i 2^i over the ACTIVE slave nodes.
template <int TNS>
int ActiveNodesValue(const Geometry& slave) {
    int value = 0;
    for (int j = 0; j < TNS; ++j)
        if (slave[j].Is(ACTIVE)) value += 1 << j;
    return value;
}

/// Per-node constants of a frictionless residual (held constant by the tangent).
template <int TNumNodes>
struct NodalParameters {
    Eigen::Matrix<double, TNumNodes, 1> penalty, dynamic_factor;
    std::array<bool, TNumNodes> active{};
};

/// ε_j = INITIAL_PENALTY, δ_j = DYNAMIC_FACTOR (1 when absent), ACTIVE. @p penalty_required_on(active) tells
/// which nodes must carry a positive ε (ALM: the inactive ones divide by it; penalty: the active ones use it).
/// @throws InputError naming @p method and the node
template <int TNumNodes, class TRequired>
NodalParameters<TNumNodes> ReadNodalParameters(const Geometry& slave, IndexType id, const char* method,
                                               TRequired&& penalty_required_on) {
    NodalParameters<TNumNodes> p;
    for (int j = 0; j < TNumNodes; ++j) {
        const Node& node = slave[j];
        p.active[j] = node.Is(ACTIVE);
        p.penalty[j] = node.GetValue(INITIAL_PENALTY);
        p.dynamic_factor[j] = node.Has(DYNAMIC_FACTOR) ? node.GetValue(DYNAMIC_FACTOR) : 1.0;
        CONTACT_CHECK(!penalty_required_on(p.active[j]) || p.penalty[j] > 0.0, InputError, method,
                      " contact condition ", id, ": ", p.active[j] ? "active" : "inactive", " slave node ", node.Id(),
                      " has INITIAL_PENALTY ", p.penalty[j], "\n  expected: a positive nodal penalty",
                      "\n  fix: run the contact initialisation (ALMFastInit) before assembling");
    }
    return p;
}

/// a_j = Σ_k D_jk, the pair's share of NODAL_AREA (= ∫ N_j over the overlap, for the dual and the standard basis).
template <class T, class TState>
T PairArea(const TState& s, int j) {
    return s.operators.D.row(j).sum();
}

/// d x1 − m x2 for a row d of D (or of D − D_old) and the matching row m of M, taken about the slave face's first node.
/// Σ_k d_k = Σ_l m_l (Σ N1 = Σ N2 = 1 at every Gauss point), so the value is the same, with round-off of ε·h rather
/// than ε·|x|: in a model far from the origin the weighted gap's round-off, times the penalty, set the floor of the
/// multiplier residual (docs/theory/mortar.md §2). The origin is a constant: the derivatives are unchanged.
template <class T, int TDim, class TState, class TRowD, class TRowM>
Eigen::Matrix<T, 1, TDim> MortarDifference(const TState& s, const TRowD& d, const TRowM& m) {
    const Eigen::Matrix<T, 1, TDim> origin = Values(Eigen::Matrix<T, 1, TDim>(s.x1.row(0))).template cast<T>();
    return d * (s.x1.rowwise() - origin) - m * (s.x2.rowwise() - origin);
}

/// g̃_j = −n_j·(D x1 − M x2)_j of the pair (positive = open).
template <class T, int TDim, class TState>
T PairGap(const TState& s, int j) {
    const Eigen::Matrix<T, 1, TDim> r = MortarDifference<T, TDim>(s, s.operators.D.row(j), s.operators.M.row(j));
    return -r.dot(s.normals.row(j));
}

/// S_j[f]: RHS_u1,a += D_ja f, RHS_u2,l −= M_jl f for a nodal force vector f (q = [u2, u1, ...]).
template <class T, int TDim, int TNS, int TNM, class TState, class TVector>
void SpreadForce(const TState& s, int j, const Eigen::Matrix<T, TDim, 1>& force, TVector& rhs) {
    constexpr int slave_offset = TDim * TNM;
    for (int c = 0; c < TDim; ++c) {
        for (int a = 0; a < TNS; ++a) rhs[slave_offset + a * TDim + c] += s.operators.D(j, a) * force[c];
        for (int l = 0; l < TNM; ++l) rhs[l * TDim + c] -= s.operators.M(j, l) * force[c];
    }
}

/// S_j[force n_j].
template <class T, int TDim, int TNS, int TNM, class TState, class TVector>
void SpreadNormalForce(const TState& s, int j, const T& force, TVector& rhs) {
    const Eigen::Matrix<T, TDim, 1> f = force * s.normals.row(j).transpose();
    SpreadForce<T, TDim, TNS, TNM>(s, j, f, rhs);
}

/// S_j[f] in values, one column per column of @p f (a nodal force per unit of a nodal quantity): out(r, k) is local RHS
/// row r of S_j[f.col(k)], with D and M at their values (q = [u2, u1]).
template <int TDim, int TNS, int TNM, class TState, class TForce, class TOut>
void SpreadForceValues(const TState& s, int j, const TForce& f, TOut& out) {
    constexpr int slave_offset = TDim * TNM;
    out.setZero();
    for (Eigen::Index k = 0; k < f.cols(); ++k)
        for (int c = 0; c < TDim; ++c) {
            for (int a = 0; a < TNS; ++a) out(slave_offset + a * TDim + c, k) += Value(s.operators.D(j, a)) * f(c, k);
            for (int l = 0; l < TNM; ++l) out(l * TDim + c, k) -= Value(s.operators.M(j, l)) * f(c, k);
        }
}

/// Records at slave node j of a penalty pair (AD pass) what the other pairs of the node need for their coupling
/// blocks (nodal_gap_coupling.h): b_j = S_j[@p force_per_gap] in values and the gradient of @p penalty_gap, this
/// pair's part of ∂(ηG)_j/∂q.
template <class T, int TDim, int TNS, int TNM, class TState, class TRecord>
void RecordNodalGapCoupling(const TState& s, int j, const Eigen::Matrix<double, TDim, 1>& force_per_gap,
                            const T& penalty_gap, TRecord& record) {
    SpreadForceValues<TDim, TNS, TNM>(s, j, force_per_gap, record.force_per_gap[j]);
    record.SetGapGradient(j, penalty_gap.Derivatives());
    record.coupled[j] = true;
}

/// k = SCALE_FACTOR (ProcessInfo) of the ALM pair @p id, which @p what names in the error.
/// @throws InputError without SCALE_FACTOR
inline double ReadScaleFactor(const ProcessInfo& process_info, IndexType id, const char* what) {
    CONTACT_CHECK(process_info.Has(SCALE_FACTOR), InputError, what, " ", id,
                  ": SCALE_FACTOR is not set in the ProcessInfo\n  fix: run the ALM initialisation (ALMFastInit)",
                  " or set ProcessInfo[SCALE_FACTOR]");
    return process_info.GetValue(SCALE_FACTOR);
}

/// The ALM constants of a frictionless pair: k = SCALE_FACTOR (ProcessInfo) and the nodal ε_j (positive on the
/// inactive nodes, which divide by it), δ_j. @throws InputError without SCALE_FACTOR or with a non-positive ε on an
/// inactive node
template <int TNumNodes, class TCondition>
std::pair<double, NodalParameters<TNumNodes>> ReadALMParameters(const TCondition& condition,
                                                                const ProcessInfo& process_info) {
    const double k = ReadScaleFactor(process_info, condition.Id(), "ALM contact condition");
    return {k, ReadNodalParameters<TNumNodes>(condition.GetParentGeometry(), condition.Id(), "ALM",
                                              [](bool active) { return !active; })};
}

/// The pair integrated in its current configuration for an explicit pass, and the state the residuals see there.
/// Every pass decides ISOLATED afresh from this configuration: a pair is reused from step to step while its slave
/// face slides, so a pair that did not overlap its master when the search made it may overlap it later (a flag kept
/// from an earlier pass left such pairs out of NODAL_AREA and of the residual: docs/theory/mortar.md §1).
/// @return false (and ISOLATED set, share invalid) when the pair does not overlap now
template <int TDim, int TNS, int TNM, class TCondition>
bool IntegrateForExplicitPass(TCondition& condition, const ProcessInfo& process_info,
                              typename TCondition::template State<double>& state) {
    PairNodalShare<TDim, TNS>& share = condition.MutableNodalShare();
    share = PairNodalShare<TDim, TNS>{};
    const Geometry& slave = condition.GetParentGeometry();
    const MortarIntegrator<TDim, TNS, TNM, double> integrator(condition.IntegrationSettings(),
                                                              condition.SegmentationSettingsFrom(process_info));
    const Geometry& master = condition.GetPairedGeometry();
    bool slave_follows = true, master_follows = true;
    state.x1 = CurrentCoordinates<TDim, TNS>(slave, &slave_follows);
    state.x2 = CurrentCoordinates<TDim, TNM>(master, &master_follows);
    state.normals = NodalNormals<TDim, TNS>(slave);
    // The operators on the mesh coordinates, as the residual (MortarContactCondition::CalculateConditionSystem).
    const bool finite_sliding = slave_follows && master_follows;
    const auto pair = IntegrateMortarPair<TDim, TNS, TNM>(
        integrator, finite_sliding ? state.x1 : MeshCoordinates<TDim, TNS>(slave),
        ToSpatialVector<TDim>(condition.GetValue(NORMAL)),
        finite_sliding ? state.x2 : MeshCoordinates<TDim, TNM>(master), state.normals, true);
    condition.Set(ISOLATED, !pair.used);
    if (!pair.used) return false;
    state.operators = pair.operators;
    share.valid = true;
    return true;
}

/// Explicit pass of a frictionless pair: adds g̃_j to the historical WEIGHTED_GAP, a_j = Σ_k D_jk (= ∫ N_j over the
/// overlap, for the dual and the standard basis alike) to the non-historical NODAL_AREA and a_j g̃_j to
/// AREA_WEIGHTED_PAIR_GAP of the slave nodes, and keeps g̃, a as the pair's share; flags ISOLATED instead when the pair
/// does not overlap.
template <int TDim, int TNS, int TNM, class TCondition>
void AddFrictionlessExplicitContribution(TCondition& condition, const ProcessInfo& process_info) {
    typename TCondition::template State<double> state;
    if (!IntegrateForExplicitPass<TDim, TNS, TNM>(condition, process_info, state)) return;
    PairNodalShare<TDim, TNS>& share = condition.MutableNodalShare();
    Geometry& slave = *condition.pGetParentGeometry();
    for (int j = 0; j < TNS; ++j) {
        share.area[j] = PairArea<double>(state, j);
        share.gap[j] = PairGap<double, TDim>(state, j);
        AddPairShareToNode(slave[j], share.area[j], share.gap[j]);
    }
}

}  // namespace contact_app::frictionless_detail
