// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/mpc_mortar_contact_condition.h"

#include <limits>
#include <utility>

#include <Eigen/LU>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/master_slave_constraint.h"
#include "contact_app/kernel/serializer.h"
#include "custom_conditions/mortar_pair_settings.h"
#include "custom_utilities/mortar_explicit_contribution.h"
#include "custom_utilities/mortar_geometry_adapters.h"

namespace contact_app {
namespace {

const Variable<double>* const kDisplacementComponents[] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};

/// Kratos IsActive(): a node whose ACTIVE flag was never set counts as active.
bool IsActiveNode(const Node& node) { return node.IsNotDefined(ACTIVE) || node.Is(ACTIVE); }

/// Historical DISPLACEMENT at buffer @p index (0: the current iterate, 1: the previous converged step); 0 for a buffer
/// the node does not keep.
template <int TDim>
Eigen::Matrix<double, TDim, 1> DisplacementAt(const Node& node, std::size_t index) {
    if (node.GetBufferSize() <= index) return Eigen::Matrix<double, TDim, 1>::Zero();
    return node.FastGetSolutionStepValue(DISPLACEMENT, index).head<TDim>();
}

/// This pair's share of slave node @p i: a_i / A_i with a_i = Σ_k D_ik = ∫N_i over the pair's overlap and A_i =
/// NODAL_AREA, the sum over every pair of the node (explicit pass), so that the pairs' rows Q = D⁻¹M assemble to the
/// node's mortar row (Σ_c M^c / Σ_c D^c_ii with dual multipliers) however many master faces a slave face overlaps. The
/// reference weights each pair by 1/NODAL_PAUX (slave faces at the node), which counts a face overlapping two master
/// faces twice (a sliver left by sliding is enough); that weight is kept only where the node has no area yet
/// (docs/theory/mortar.md §9).
template <int TNS, int TNM>
double PairShare(const Node& node, const MortarOperators<double, TNS, TNM>& operators, int i) {
    const double total = node.Has(NODAL_AREA) ? node.GetValue(NODAL_AREA) : 0.0;
    if (total > 0.0) return operators.D.row(i).sum() / total;
    const double paux = node.Has(NODAL_PAUX) ? node.GetValue(NODAL_PAUX) : 0.0;
    return paux > 0.0 ? 1.0 / paux : 0.0;
}

/// The Coulomb data of a slave node that slips with friction: μ and the unit slip direction e (TANGENT_XI made
/// tangent to @p n). Empty (mu = 0) for a stick, frictionless, inactive or direction-less node.
template <int TDim>
struct SlipFriction {
    double mu = 0.0;
    Eigen::Matrix<double, TDim, 1> direction = Eigen::Matrix<double, TDim, 1>::Zero();
    bool Applies() const { return mu > 0.0; }
};

template <int TDim>
SlipFriction<TDim> SlipFrictionOf(const Node& node, const Eigen::Matrix<double, TDim, 1>& n) {
    SlipFriction<TDim> result;
    if (!IsActiveNode(node) || !node.Is(SLIP) || !node.Has(FRICTION_COEFFICIENT) || !node.Has(TANGENT_XI))
        return result;
    Eigen::Matrix<double, TDim, 1> e = node.GetValue(TANGENT_XI).head<TDim>();
    e -= e.dot(n) * n;
    const double mu = node.GetValue(FRICTION_COEFFICIENT);
    if (!(mu > 0.0) || !(e.norm() > 0.0)) return result;
    result.mu = mu;
    result.direction = e.normalized();
    return result;
}

/// The slave component a normal-only row is solved for: the largest |n_a|, or with friction the largest
/// min(|n_a|, |v_a|), v = n − μe, because the test row divides by v_a (only different on a steep interface with a
/// large μ: with μ < 1/√2 in 3D, 1 in 2D, argmax |n_a| has v_a ≠ 0).
template <int TDim>
Eigen::Index PivotComponent(const Eigen::Matrix<double, TDim, 1>& n, const Eigen::Matrix<double, TDim, 1>& v) {
    Eigen::Index pivot = 0;
    n.cwiseAbs().cwiseMin(v.cwiseAbs()).maxCoeff(&pivot);
    return pivot;
}

/// Row @p row (slave node @p i, component @p pivot) of n·u_s = n·(Q u_m) + c with @p w in place of n, solved for
/// u_s,pivot: (w_b / w_pivot) Q_ij on the master columns, −w_b / w_pivot on the node's other components.
template <int TDim, class TRow>
void WriteNormalRow(int i, int row, Eigen::Index pivot, double weight, const TRow& q,
                    const Eigen::Matrix<double, TDim, 1>& w, Matrix& relation, Matrix& slave_coupling) {
    for (Eigen::Index j = 0; j < q.size(); ++j)
        for (int b = 0; b < TDim; ++b) {
            const double value = w[b] * q[j] / w[pivot];
            if (std::abs(value) > 1.0e-12) relation(row, j * TDim + b) = weight * value;
        }
    for (int b = 0; b < TDim; ++b)
        if (b != pivot && std::abs(w[b]) > 1.0e-12) slave_coupling(row, i * TDim + b) = -weight * w[b] / w[pivot];
}

/// Below this cosine between the slip of the step and the kept direction, the direction is not the slip's (it is
/// the stick force's of a node that has just started to slip) and the direction's tangent is left out.
constexpr double kDirectionFromSlip = 0.9;

}  // namespace

#define MPC_TEMPLATE template <int TDim, int TNS, int TNM>
#define MPC_CLASS MPCMortarContactCondition<TDim, TNS, TNM>

MPC_TEMPLATE
Condition::Pointer MPC_CLASS::Create(IndexType new_id, Geometry::Pointer slave, Properties::Pointer properties,
                                     Geometry::Pointer master) const {
    return std::make_shared<MPC_CLASS>(new_id, std::move(slave), std::move(properties), std::move(master));
}

MPC_TEMPLATE
typename MPC_CLASS::Operators MPC_CLASS::CurrentOperators(const ProcessInfo& rCurrentProcessInfo, bool& dual) const {
    const Geometry& slave = GetParentGeometry();
    const MortarIntegrator<TDim, TNS, TNM, double> integrator(
        pair_settings::IntegrationSettingsFrom(pGetProperties()),
        pair_settings::PairSegmentationSettings<TDim, TNS, TNM>(rCurrentProcessInfo, pGetProperties(),
                                                                GetParentGeometry(), GetPairedGeometry()));
    return ComputePreviousMortarOperators<TDim, TNS, TNM>(
        integrator, CurrentCoordinates<TDim, TNS>(slave), ToSpatialVector<TDim>(GetValue(NORMAL)),
        CurrentCoordinates<TDim, TNM>(GetPairedGeometry()), NodalNormals<TDim, TNS>(slave), dual);
}

MPC_TEMPLATE
void MPC_CLASS::ComputePreviousOperators(const ProcessInfo& rCurrentProcessInfo) {
    bool dual = false;
    mPreviousMortarOperators.Set(CurrentOperators(rCurrentProcessInfo, dual));
}

MPC_TEMPLATE
void MPC_CLASS::Initialize(const ProcessInfo& rCurrentProcessInfo) {
    // A restarted run initializes every entity again: recomputing here would rebuild the constraint on the
    // restart-time coordinates, while the saving run went on with the one it held (BLOCKED after its step).
    if (std::exchange(mRestored, false)) return;
    PairedCondition::Initialize(rCurrentProcessInfo);
    mPreviousMortarOperators.Reset();
    const ProcessInfo empty;  // as the reference: the first update ignores the ProcessInfo settings
    if (Is(SLIP)) ComputePreviousOperators(empty);
    UpdateConstraint(empty);
}

MPC_TEMPLATE
void MPC_CLASS::InitializeSolutionStep(const ProcessInfo& rCurrentProcessInfo) {
    PairedCondition::InitializeSolutionStep(rCurrentProcessInfo);
    if (Is(BLOCKED)) return;
    if (Is(SLIP)) ComputePreviousOperators(rCurrentProcessInfo);
    UpdateConstraint(rCurrentProcessInfo);
}

MPC_TEMPLATE
void MPC_CLASS::InitializeNonLinearIteration(const ProcessInfo& rCurrentProcessInfo) {
    PairedCondition::InitializeNonLinearIteration(rCurrentProcessInfo);
    if (Is(INTERACTION)) UpdateConstraint(rCurrentProcessInfo);
}

MPC_TEMPLATE
void MPC_CLASS::FinalizeSolutionStep(const ProcessInfo& rCurrentProcessInfo) {
    PairedCondition::FinalizeSolutionStep(rCurrentProcessInfo);
    if (Is(SLIP)) ComputePreviousOperators(rCurrentProcessInfo);
}

MPC_TEMPLATE
Eigen::Matrix<double, TNS, TNM> MPC_CLASS::ComputeQ(const Operators& operators, bool dual) {
    Eigen::Matrix<double, TNS, TNM> Q = Eigen::Matrix<double, TNS, TNM>::Zero();
    if (dual) {  // D is diagonal with dual multipliers
        for (int i = 0; i < TNS; ++i)
            if (std::abs(operators.D(i, i)) > std::numeric_limits<double>::min())
                Q.row(i) = operators.M.row(i) / operators.D(i, i);
    } else {
        const Eigen::FullPivLU<Eigen::Matrix<double, TNS, TNS>> lu(operators.D);
        if (!lu.isInvertible()) return Q;  // isolated pair (zero operators): no constraint
        Q = lu.solve(operators.M);
    }
    return Q;
}

MPC_TEMPLATE
MPCConstraintRelation MPC_CLASS::ComputeConstraintRelation(const ProcessInfo& rCurrentProcessInfo) const {
    bool dual = false;
    const Operators operators = CurrentOperators(rCurrentProcessInfo, dual);
    const Eigen::Matrix<double, TNS, TNM> Q = ComputeQ(operators, dual);
    const Geometry& slave = GetParentGeometry();
    const Geometry& master = GetPairedGeometry();
    const auto normals = NodalNormals<TDim, TNS>(slave);
    // WEIGHTED_GAP is the gap of the configuration the constraint is built at: the start of the step for the step's
    // first build (buffer 1), the current iterate for a rebuild inside the step (INTERACTION; the criteria computed
    // the gaps of the iterate). A stick row keeps the tangential offset of the start of the step in either case.
    const bool rebuild = Is(INTERACTION);
    Eigen::Matrix<double, TNM, TDim> u2_previous, u2_current;  // B7 done right: n_m master rows
    for (int j = 0; j < TNM; ++j) {
        u2_previous.row(j) = DisplacementAt<TDim>(master[j], 1).transpose();
        if (rebuild) u2_current.row(j) = DisplacementAt<TDim>(master[j], 0).transpose();
    }

    struct SlipRow {
        int node, row;
        Eigen::Index pivot;
        double weight;
        Eigen::Matrix<double, TDim, 1> v;
    };
    std::vector<SlipRow> slip_rows;
    MPCConstraintRelation result;
    result.relation.setZero(TDim * TNS, TDim * TNM);
    result.constant.setZero(TDim * TNS);
    result.slave_coupling.setZero(TDim * TNS, TDim * TNS);
    for (int i = 0; i < TNS; ++i) {
        const Node& node = slave[i];
        const bool active = IsActiveNode(node);
        const double paux = node.Has(NODAL_PAUX) ? node.GetValue(NODAL_PAUX) : 0.0;
        CONTACT_CHECK(!active || paux > 0.0, InputError, "MPCMortarContactCondition ", Id(), ": active slave node ",
                      node.Id(), " has NODAL_PAUX ", paux,
                      "\n  expected: the (positive) number of slave conditions containing the node",
                      "\n  fix: compute the nodal weights (the MPC contact strategy does) before updating the constraint");
        const double weight = paux > 0.0 ? PairShare(node, operators, i) : 0.0;
        const Eigen::Matrix<double, TDim, 1> n = normals.row(i).transpose();
        // Gap carried by the constant: closing it needs n·(Δu1 − Q Δu2) = g̃/A from the displacements of the gap.
        const double area = node.Has(NODAL_AREA) && node.GetValue(NODAL_AREA) > 0.0 ? node.GetValue(NODAL_AREA) : 1.0;
        const double gap = node.FastGetSolutionStepValue(WEIGHTED_GAP);
        // u_s − Q u_m at the start of the step, and where the gap was computed.
        const Eigen::Matrix<double, TDim, 1> start =
            DisplacementAt<TDim>(node, 1) - (Q.row(i) * u2_previous).transpose();
        const Eigen::Matrix<double, TDim, 1> relative =
            rebuild ? Eigen::Matrix<double, TDim, 1>(DisplacementAt<TDim>(node, 0) - (Q.row(i) * u2_current).transpose())
                    : start;
        const double normal_constant = weight * (gap / area + n.dot(relative));
        // SLIP condition: slip nodes normal-only, stick nodes full; RIGID (tying): full; else frictionless.
        const bool normal_only = Is(SLIP) ? node.Is(SLIP) : !Is(RIGID);
        if (!normal_only || !active) {
            // Full tie (or an inactive node, whose rows are pruned): u_s = Q u_m + c n.
            if (active)
                for (int j = 0; j < TNM; ++j)
                    if (std::abs(Q(i, j)) > 1.0e-12)
                        for (int a = 0; a < TDim; ++a) result.relation(i * TDim + a, j * TDim + a) = weight * Q(i, j);
            for (int a = 0; a < TDim; ++a) result.constant[i * TDim + a] = normal_constant * n[a];
            if (active && Is(SLIP)) {
                // Stick is no slip in the step (as the ALM stick rows, docs/theory/mortar.md §9): P(u_s − Q u_m) keeps
                // its start-of-step value. Tying it to zero instead pulled a node back over the tangential motion it
                // made before it touched (a stick force above the cone on every newly touching node).
                const Eigen::Matrix<double, TDim, 1> offset = start - n.dot(start) * n;
                for (int a = 0; a < TDim; ++a) result.constant[i * TDim + a] += weight * offset[a];
            }
            continue;
        }
        // Normal only: the one scalar row n·u_s = n·(Q u_m) + c, solved for the component a* with the largest |n_a|;
        // the other slave components stay free DoFs (the tangential motion a slip or frictionless node needs). The
        // reference's rows n nᵀ(Q u_m) on every component tie the tangential slave motion to zero on a tilted
        // interface ([BUG?] B6).
        const SlipFriction<TDim> friction = Is(SLIP) ? SlipFrictionOf<TDim>(node, n) : SlipFriction<TDim>();
        const Eigen::Matrix<double, TDim, 1> v = n - friction.mu * friction.direction;
        const Eigen::Index pivot = PivotComponent<TDim>(n, v);
        const int row = i * TDim + static_cast<int>(pivot);
        WriteNormalRow<TDim>(i, row, pivot, weight, Q.row(i), n, result.relation, result.slave_coupling);
        result.constant[row] = normal_constant / n[pivot];
        if (friction.Applies()) slip_rows.push_back({i, row, pivot, weight, v});
    }
    // The test rows of the slipping nodes: v = n − μe in place of n. The slave's residual r (its constraint force
    // −r) then reaches the free components and the masters as λv = λn − μλe: the normal force λ and the Coulomb
    // force μ|λ| along e, with λ the constraint force of the current iterate, linearised with it (docs/theory/mortar.md
    // §9).
    if (!slip_rows.empty()) {
        result.test_relation = result.relation;
        result.test_slave_coupling = result.slave_coupling;
        for (const SlipRow& s : slip_rows) {
            result.test_relation.row(s.row).setZero();
            result.test_slave_coupling.row(s.row).setZero();
            WriteNormalRow<TDim>(s.node, s.row, s.pivot, s.weight, Q.row(s.node), s.v, result.test_relation,
                           result.test_slave_coupling);
        }
    }
    return result;
}

MPC_TEMPLATE
void MPC_CLASS::UpdateConstraint(const ProcessInfo& rCurrentProcessInfo) {
    if (!Has(CONSTRAINT_POINTER)) return;
    const std::shared_ptr<MasterSlaveConstraint> constraint = GetValue(CONSTRAINT_POINTER);
    if (!constraint) return;
    const MPCConstraintRelation full = ComputeConstraintRelation(rCurrentProcessInfo);
    const Geometry& slave = GetParentGeometry();
    const Geometry& master = GetPairedGeometry();
    // Columns: the master components, then the slave components a normal-only row depends on.
    Matrix columns(full.relation.rows(), full.relation.cols() + full.slave_coupling.cols());
    columns << full.relation, full.slave_coupling;
    const bool tested = full.test_relation.size() > 0;
    Matrix test_columns;
    if (tested) {
        test_columns.resize(columns.rows(), columns.cols());
        test_columns << full.test_relation, full.test_slave_coupling;
    }
    std::vector<Eigen::Index> rows, cols;
    DofsVectorType slave_dofs, master_dofs;
    for (Eigen::Index r = 0; r < columns.rows(); ++r)
        if (full.relation.row(r).cwiseAbs().sum() > PruneTolerance) {
            rows.push_back(r);
            slave_dofs.push_back(&slave[r / TDim].GetDof(*kDisplacementComponents[r % TDim]));
        }
    for (Eigen::Index c = 0; c < columns.cols(); ++c) {
        double sum = 0.0;
        for (Eigen::Index r : rows) sum += std::abs(columns(r, c)) + (tested ? std::abs(test_columns(r, c)) : 0.0);
        if (!(sum > PruneTolerance)) continue;
        cols.push_back(c);
        const bool on_master = c < full.relation.cols();
        const Eigen::Index k = on_master ? c : c - full.relation.cols();
        master_dofs.push_back(on_master ? &master[k / TDim].GetDof(*kDisplacementComponents[k % TDim])
                                        : &slave[k / TDim].GetDof(*kDisplacementComponents[k % TDim]));
    }
    Matrix relation(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(cols.size()));
    Vector constant(static_cast<Eigen::Index>(rows.size()));
    for (std::size_t r = 0; r < rows.size(); ++r) {
        constant[r] = full.constant[rows[r]];
        for (std::size_t c = 0; c < cols.size(); ++c) relation(r, c) = columns(rows[r], cols[c]);
    }
    constraint->SetDofList(slave_dofs, master_dofs, rCurrentProcessInfo);
    constraint->SetLocalSystem(relation, constant, rCurrentProcessInfo);
    if (!tested) return;
    Matrix test(relation.rows(), relation.cols());
    for (std::size_t r = 0; r < rows.size(); ++r)
        for (std::size_t c = 0; c < cols.size(); ++c) test(r, c) = test_columns(rows[r], cols[c]);
    constraint->SetTestRelation(test, rCurrentProcessInfo);
}

MPC_TEMPLATE
void MPC_CLASS::CalculateConditionSystem(Matrix* pLhs, Vector* pRhs, const ProcessInfo& rCurrentProcessInfo) {
    if (pRhs) pRhs->setZero(MatrixSize);
    if (pLhs == nullptr) return;
    Matrix& lhs = *pLhs;
    lhs.setZero(MatrixSize, MatrixSize);
    if (!Is(SLIP) || !mPreviousMortarOperators.initialized) return;
    const Geometry& slave = GetParentGeometry();
    bool any_slip = false;
    for (int i = 0; i < TNS; ++i) any_slip = any_slip || (IsActiveNode(slave[i]) && slave[i].Is(SLIP));
    if (!any_slip) return;
    bool dual = false;
    const Operators operators = CurrentOperators(rCurrentProcessInfo, dual);
    const Eigen::Matrix<double, TNS, TNM> Q = ComputeQ(operators, dual);
    const Operators& previous = mPreviousMortarOperators.operators;
    const auto normals = NodalNormals<TDim, TNS>(slave);
    using VectorD = Eigen::Matrix<double, TDim, 1>;
    using MatrixD = Eigen::Matrix<double, TDim, TDim>;
    for (int i = 0; i < TNS; ++i) {
        const Node& node = slave[i];
        if (Q.row(i).cwiseAbs().sum() == 0.0) continue;  // this pair does not overlap the node
        const VectorD n = normals.row(i).transpose().normalized();
        const SlipFriction<TDim> friction = SlipFrictionOf<TDim>(node, n);
        if (!friction.Applies() || !node.SolutionStepsDataHas(WEIGHTED_SLIP)) continue;
        // λ: the normal constraint force of the current iterate (the reaction of a slipping node is λ(n − μe)).
        const double normal_force = node.FastGetSolutionStepValue(REACTION).head<TDim>().dot(n);
        const double area = node.Has(NODAL_AREA) ? node.GetValue(NODAL_AREA) : 0.0;
        if (!(normal_force < 0.0) || !(area > 0.0)) continue;
        VectorD slip = node.FastGetSolutionStepValue(WEIGHTED_SLIP).head<TDim>();
        slip -= slip.dot(n) * n;
        const double length = TDim == 2 ? area : std::sqrt(area);
        if (!(slip.norm() > 1.0e-12 * area * length)) continue;  // round-off slip: no direction to linearise
        const VectorD s = slip / slip.norm();
        if (s.dot(friction.direction) < kDirectionFromSlip) continue;
        // f = μ|λ| s/|s| with s the node's weighted slip of the step, Σ over its pairs of M⁰u_m − D⁰u_s (start-of-step
        // operators; the current ones only add a normal part on coplanar faces): this pair's share of ds is S du, and
        // df = μ|λ| P ds / |s| with P = I − ŝŝᵀ − nnᵀ. The slave rows are exact; the master rows spread this pair's
        // share with its own Q (exact when the node's pairs project it alike, as on matching meshes).
        Eigen::Matrix<double, TDim, MatrixSize> S = Eigen::Matrix<double, TDim, MatrixSize>::Zero();
        for (int j = 0; j < TNM; ++j)
            S.template block<TDim, TDim>(0, j * TDim) = previous.M(i, j) * MatrixD::Identity();
        for (int k = 0; k < TNS; ++k)
            S.template block<TDim, TDim>(0, TDim * TNM + k * TDim) = -previous.D(i, k) * MatrixD::Identity();
        Eigen::Matrix<double, MatrixSize, TDim> B = Eigen::Matrix<double, MatrixSize, TDim>::Zero();
        for (int j = 0; j < TNM; ++j) B.template block<TDim, TDim>(j * TDim, 0) = -Q(i, j) * MatrixD::Identity();
        B.template block<TDim, TDim>(TDim * TNM + i * TDim, 0) = MatrixD::Identity();
        const MatrixD P = MatrixD::Identity() - s * s.transpose() - n * n.transpose();
        Matrix block = (-friction.mu * normal_force / slip.norm()) * (B * P * S);
        // The row of the solved-for component is the constraint's, not an equation (its residual is the force λ).
        const VectorD v = n - friction.mu * friction.direction;
        block.row(TDim * TNM + i * TDim + static_cast<int>(PivotComponent<TDim>(n, v))).setZero();
        lhs -= block;  // the LHS is −d(force)/du
    }
}

MPC_TEMPLATE
void MPC_CLASS::GetDofList(DofsVectorType& rElementalDofList, const ProcessInfo&) const {
    const Geometry& slave = GetParentGeometry();
    const Geometry& master = GetPairedGeometry();
    rElementalDofList.clear();
    rElementalDofList.reserve(MatrixSize);
    for (int l = 0; l < TNM; ++l)
        for (int c = 0; c < TDim; ++c) rElementalDofList.push_back(&master[l].GetDof(*kDisplacementComponents[c]));
    for (int j = 0; j < TNS; ++j)
        for (int c = 0; c < TDim; ++c) rElementalDofList.push_back(&slave[j].GetDof(*kDisplacementComponents[c]));
}

MPC_TEMPLATE
void MPC_CLASS::AddExplicitContribution(const ProcessInfo& rCurrentProcessInfo) {
    Geometry& slave = *pGetParentGeometry();
    const Geometry& master = GetPairedGeometry();
    const MortarIntegrator<TDim, TNS, TNM, double> integrator(
        pair_settings::IntegrationSettingsFrom(pGetProperties()),
        pair_settings::PairSegmentationSettings<TDim, TNS, TNM>(rCurrentProcessInfo, pGetProperties(),
                                                                GetParentGeometry(), GetPairedGeometry()));
    ExplicitContributionOptions options;
    options.compute_nodal_area = true;  // as the penalty conditions: NODAL_AREA normalises the constraint gap
    const auto x1 = CurrentCoordinates<TDim, TNS>(slave);
    const auto x2 = CurrentCoordinates<TDim, TNM>(master);
    const SpatialVector<double, TDim> center = ToSpatialVector<TDim>(GetValue(NORMAL));
    const auto normals = NodalNormals<TDim, TNS>(slave);
    const bool slip = Is(SLIP);
    ExplicitMortarContribution<double, TDim, TNS> result;
    if (slip) {
        const double delta_time =
            rCurrentProcessInfo.Has(DELTA_TIME) && rCurrentProcessInfo.GetValue(DELTA_TIME) > 0.0
                ? rCurrentProcessInfo.GetValue(DELTA_TIME)
                : 1.0;
        result = ComputeExplicitFrictionalMortarContribution<TDim, TNS, TNM, double, double>(
            integrator, x1, center, x2, normals, mPreviousMortarOperators.operators,
            CoordinatesAtStep<TDim, TNS>(slave, 1), CoordinatesAtStep<TDim, TNM>(master, 1), delta_time, !Is(MODIFIED),
            options);
    } else {
        result = ComputeExplicitMortarContribution<TDim, TNS, TNM, double, double>(integrator, x1, center, x2,
                                                                                   normals, options);
    }
    // Decided afresh at every pass, as for the other mortar pairs: a pair kept from step to step may come to overlap.
    Set(ISOLATED, result.isolated);
    if (result.isolated) return;
    for (int j = 0; j < TNS; ++j) {
        slave[j].FastGetSolutionStepValue(WEIGHTED_GAP) += result.weighted_gap[j];
        slave[j].SetValue(NODAL_AREA, slave[j].GetValue(NODAL_AREA) + result.nodal_area[j]);
        if (slip) slave[j].FastGetSolutionStepValue(WEIGHTED_SLIP).head<TDim>() += result.weighted_slip.row(j).transpose();
    }
}

MPC_TEMPLATE
int MPC_CLASS::Check(const ProcessInfo& rCurrentProcessInfo) const {
    PairedCondition::Check(rCurrentProcessInfo);
    CheckNodeCounts("MPCMortarContactCondition", TNS, TNM);
    const Geometry& slave = GetParentGeometry();
    const Geometry& master = GetPairedGeometry();
    auto check_node = [&](const Node& node, const char* side, bool is_slave) {
        std::vector<const VariableData*> variables = {&DISPLACEMENT};
        if (is_slave) variables.insert(variables.end(), {&NORMAL, &WEIGHTED_GAP});
        for (const VariableData* variable : variables)
            CONTACT_CHECK(node.SolutionStepsDataHas(*variable), InputError, "MPCMortarContactCondition ", Id(), ": ",
                          side, " node ", node.Id(), " does not store ", variable->Name(), " as a historical variable",
                          "\n  fix: add it to the model part's solution-step variables (the MPC contact solver does)");
        for (int c = 0; c < TDim; ++c)
            CONTACT_CHECK(node.HasDofFor(*kDisplacementComponents[c]), InputError, "MPCMortarContactCondition ", Id(),
                          ": ", side, " node ", node.Id(), " has no ", kDisplacementComponents[c]->Name(), " DoF",
                          "\n  fix: add the DISPLACEMENT DoFs to the ", side, " nodes");
    };
    for (std::size_t l = 0; l < master.size(); ++l) check_node(master[l], "master", false);
    for (std::size_t j = 0; j < slave.size(); ++j) check_node(slave[j], "slave", true);
    return 0;
}

MPC_TEMPLATE
void MPC_CLASS::Save(Serializer& rSerializer) const {
    PairedCondition::Save(rSerializer);
    mPreviousMortarOperators.Save(rSerializer);
}

MPC_TEMPLATE
void MPC_CLASS::Load(Serializer& rSerializer) {
    PairedCondition::Load(rSerializer);
    mPreviousMortarOperators.Load(rSerializer);
    mRestored = true;
}

MPC_TEMPLATE
std::string MPC_CLASS::Info() const {
    return PairInfo("MPCMortarContactCondition");
}

#undef MPC_TEMPLATE
#undef MPC_CLASS

CONTACT_APP_INSTANTIATE_FOR_EACH_MORTAR_PAIR(MPCMortarContactCondition)

}  // namespace contact_app
