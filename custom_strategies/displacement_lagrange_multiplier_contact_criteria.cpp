// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/displacement_lagrange_multiplier_contact_criteria.h"

#include <cmath>
#include <algorithm>
#include <limits>
#include <sstream>
#include <unordered_map>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/solving/builder_and_solvers/builder_and_solver.h"
#include "contact_app/solving/convergence_criteria/round_off_bound.h"

namespace contact_app {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

/// -1: not a multiplier; 0..2: component of VECTOR_LAGRANGE_MULTIPLIER; 3: a scalar multiplier.
int MultiplierComponent(const Dof& dof) {
    const Variable<double>& variable = dof.GetVariable();
    if (variable == VECTOR_LAGRANGE_MULTIPLIER_X) return 0;
    if (variable == VECTOR_LAGRANGE_MULTIPLIER_Y) return 1;
    if (variable == VECTOR_LAGRANGE_MULTIPLIER_Z) return 2;
    if (variable == LAGRANGE_MULTIPLIER_CONTACT_PRESSURE || variable == SCALAR_LAGRANGE_MULTIPLIER) return 3;
    return -1;
}

/// The vector multiplier of one node, gathered over its components (value, increment, residual).
struct NodeMultiplier {
    Array3 value = Array3::Zero(), increment = Array3::Zero(), residual = Array3::Zero();
    double state = 0.0;  ///< Σ z² over the components (RoundOffBound)
    int components = 0;
};

const char* const kBlockNames[] = {"disp", "lm", "stick", "slip"};

}  // namespace

DisplacementLagrangeMultiplierContactCriteria::DisplacementLagrangeMultiplierContactCriteria(
    ContactBlockMeasure displacement_measure, ContactBlockMeasure lm_measure, ContactCriteriaTolerances tolerances)
    : mDisplacementMeasure(displacement_measure), mLMMeasure(lm_measure), mTolerances(tolerances) {
    for (double t : {tolerances.displacement_relative, tolerances.displacement_absolute, tolerances.lm_relative,
                     tolerances.lm_absolute, tolerances.stick_relative, tolerances.stick_absolute,
                     tolerances.slip_relative, tolerances.slip_absolute})
        CONTACT_CHECK(t >= 0.0, InputError, "contact convergence criterion: tolerances must be non-negative, got ", t,
                      "\n  fix: check the *_tolerance keys of solver_settings and contact_settings");
}

bool DisplacementLagrangeMultiplierContactCriteria::GetActualizeRHSflag() const {
    return mDisplacementMeasure == ContactBlockMeasure::RESIDUAL || mLMMeasure == ContactBlockMeasure::RESIDUAL;
}

DisplacementLagrangeMultiplierContactCriteria::Sums DisplacementLagrangeMultiplierContactCriteria::Accumulate(
    const DofsArrayType& rDofSet, const SystemVectorType& rDx, const SystemVectorType& rB,
    const BuilderAndSolver& rBuilder) const {
    Sums sums;
    const auto& constrained = rBuilder.ConstrainedEquations();
    std::unordered_map<Node*, NodeMultiplier> vectors;
    auto add = [&sums](int block, double value, double increment, double residual, double state) {
        sums.value[block] += value * value;
        sums.increment[block] += increment * increment;
        sums.residual[block] += residual * residual;
        sums.state[block] += state;
        ++sums.count[block];
    };
    for (const Dof* dof : rDofSet) {
        if (dof->IsFixed()) continue;
        const std::size_t id = dof->EquationId();
        const auto row = static_cast<Eigen::Index>(id);
        if (row >= rDx.size() || row >= rB.size()) continue;
        if (id < constrained.size() && constrained[id]) continue;
        const int component = MultiplierComponent(*dof);
        const double value = dof->GetSolutionStepValue(), increment = rDx[row], residual = rB[row];
        const double state = std::pow(RoundOffBound::StateMagnitude(*dof), 2);
        if (component < 0) {
            add(DISPLACEMENT, value, increment, residual, state);
        } else if (component == 3 || !mTolerances.split_frictional) {
            add(LM_NORMAL, value, increment, residual, state);
        } else {
            NodeMultiplier& node = vectors[&dof->GetNode()];
            node.value[component] = value;
            node.increment[component] = increment;
            node.residual[component] = residual;
            node.state += state;
            ++node.components;
        }
    }
    // Frictional split: normal part (λ·n) n, tangential rest, by the node's stick / slip state.
    for (auto& [node, lm] : vectors) {
        const bool active = node->Is(ACTIVE);
        const double mu = node->GetValue(FRICTION_COEFFICIENT);
        if (!active || mu < kEps || !node->SolutionStepsDataHas(NORMAL)) {
            sums.value[LM_NORMAL] += lm.value.squaredNorm();
            sums.increment[LM_NORMAL] += lm.increment.squaredNorm();
            sums.residual[LM_NORMAL] += lm.residual.squaredNorm();
            sums.state[LM_NORMAL] += lm.state;
            sums.count[LM_NORMAL] += lm.components;
            continue;
        }
        Array3 n = node->FastGetSolutionStepValue(NORMAL);
        if (n.norm() > kEps) n.normalize();
        const int tangent = (mTolerances.pure_slip || node->Is(SLIP)) ? LM_SLIP : LM_STICK;
        auto split = [&](const Array3& v, double* normal_sum, double* tangent_sum) {
            const double normal = v.dot(n);
            *normal_sum += normal * normal;
            *tangent_sum += (v - normal * n).squaredNorm();
        };
        split(lm.value, &sums.value[LM_NORMAL], &sums.value[tangent]);
        split(lm.increment, &sums.increment[LM_NORMAL], &sums.increment[tangent]);
        split(lm.residual, &sums.residual[LM_NORMAL], &sums.residual[tangent]);
        // The magnitude bounds both parts (a projection does not enlarge it).
        sums.state[LM_NORMAL] += lm.state;
        sums.state[tangent] += lm.state;
        sums.count[LM_NORMAL] += 1;
        sums.count[tangent] += lm.components - 1;
    }
    return sums;
}

void DisplacementLagrangeMultiplierContactCriteria::InitializeSolutionStep(ModelPart&, DofsArrayType& rDofSet,
                                                                           const SparseMatrixType&,
                                                                           const SystemVectorType& rDx,
                                                                           const SystemVectorType& rB,
                                                                           const BuilderAndSolver& rBuilder) {
    SystemVectorType zero = SystemVectorType::Zero(rB.size());
    const Sums sums = Accumulate(rDofSet, rDx.size() == rB.size() ? rDx : zero, rB, rBuilder);
    for (int b = 0; b < NUM_BLOCKS; ++b) mInitialResidual[b] = std::sqrt(sums.residual[b]);
}

void DisplacementLagrangeMultiplierContactCriteria::InitializePredictedResidual(DofsArrayType& rDofSet,
                                                                                const SystemVectorType& rB,
                                                                                const BuilderAndSolver& rBuilder) {
    const SystemVectorType zero = SystemVectorType::Zero(rB.size());
    const Sums sums = Accumulate(rDofSet, zero, rB, rBuilder);
    for (int b = 0; b < NUM_BLOCKS; ++b)
        mInitialResidual[b] = std::max(mInitialResidual[b], std::sqrt(sums.residual[b]));
}

bool DisplacementLagrangeMultiplierContactCriteria::PostCriteria(ModelPart& rModelPart, DofsArrayType& rDofSet,
                                                                 const SparseMatrixType&, const SystemVectorType& rDx,
                                                                 const SystemVectorType& rB,
                                                                 const BuilderAndSolver& rBuilder) {
    const Sums sums = Accumulate(rDofSet, rDx, rB, rBuilder);
    std::size_t active = 0;
    for (const auto& node : rModelPart.Nodes())
        if (node->Is(ACTIVE) && node->Is(SLAVE)) ++active;
    const bool has_multipliers = sums.count[LM_NORMAL] + sums.count[LM_STICK] + sums.count[LM_SLIP] > 0;
    if (mTolerances.ensure_contact && has_multipliers && active == 0)
        CONTACT_THROW(ConvergenceError, "contact lost: no slave node is active in ", rModelPart.FullName(),
                      "\n  expected: contact (contact_settings.ensure_contact is true)",
                      "\n  fix: check the loads and the initial gap, or set ensure_contact to false");

    const double relative[NUM_BLOCKS] = {mTolerances.displacement_relative, mTolerances.lm_relative,
                                         mTolerances.stick_relative, mTolerances.slip_relative};
    const double absolute[NUM_BLOCKS] = {mTolerances.displacement_absolute, mTolerances.lm_absolute,
                                         mTolerances.stick_absolute, mTolerances.slip_absolute};
    bool displacement_round_off = false;  // the blocks run in order: DISPLACEMENT first
    for (int b = 0; b < NUM_BLOCKS; ++b) {
        mRatio[b] = mAbsolute[b] = 0.0;
        mConverged[b] = true;
        mAtRoundOff[b] = false;
        if (sums.count[b] == 0) continue;
        const double n = static_cast<double>(sums.count[b]);
        const bool increment_measure = MeasureOf(static_cast<Block>(b)) == ContactBlockMeasure::INCREMENT;
        if (increment_measure) {
            const double dx = std::sqrt(sums.increment[b]), x = std::sqrt(sums.value[b]);
            // A zero increment is converged (the reference replaces it by 1, which fails the absolute test).
            mRatio[b] = dx < kEps ? 0.0 : (x < kEps ? (b == DISPLACEMENT ? dx : 0.0) : dx / x);
            mAbsolute[b] = dx / n;
        } else {
            const double r = std::sqrt(sums.residual[b]);
            // A block without residual at the step start (a multiplier block that becomes active in the step) takes
            // its first non-zero residual as the reference, as the reference criteria do with the first iteration.
            if (mInitialResidual[b] < kEps && r >= kEps) mInitialResidual[b] = r;
            const double r0 = mInitialResidual[b];
            mRatio[b] = r0 >= kEps ? r / r0 : (r < kEps ? 0.0 : std::numeric_limits<double>::infinity());
            mAbsolute[b] = r / n;
        }
        mConverged[b] = mRatio[b] <= relative[b] || mAbsolute[b] < absolute[b];
        // Round-off: the block's correction, or for a multiplier block a non-zero displacement correction at
        // round-off (for a fixed active and slip set the equations are linear in the multipliers, so such a Δu
        // leaves the updated state at round-off whatever Δλ was; the mortar criterion judges the sets).
        const bool round_off = RoundOffBound::IsRoundOff(std::sqrt(sums.increment[b]), sums.state[b],
                                                         increment_measure ? 0.0 : sums.residual[b]);
        if (b == DISPLACEMENT) displacement_round_off = round_off && sums.increment[b] > 0.0;
        if (!mConverged[b]) mAtRoundOff[b] = mConverged[b] = round_off || displacement_round_off;
    }
    // The multiplier blocks are not judged while nothing is in contact (their unknowns are zero by construction).
    if (active == 0 && !mTolerances.ensure_contact)
        mConverged[LM_NORMAL] = mConverged[LM_STICK] = mConverged[LM_SLIP] = true;
    // Tangential blocks small compared with the normal one are converged too.
    for (const int b : {LM_STICK, LM_SLIP})
        if (!mConverged[b] && mAbsolute[LM_NORMAL] > kEps &&
            mAbsolute[b] / mAbsolute[LM_NORMAL] <= mTolerances.ratio_normal_tangent_threshold)
            mConverged[b] = true;
    return mConverged[DISPLACEMENT] && mConverged[LM_NORMAL] && mConverged[LM_STICK] && mConverged[LM_SLIP];
}

std::string DisplacementLagrangeMultiplierContactCriteria::LastNorms() const {
    std::ostringstream out;
    out.precision(3);
    out << std::scientific;
    const int blocks = mTolerances.split_frictional ? NUM_BLOCKS : 2;
    for (int b = 0; b < blocks; ++b) {
        if (b > 0) out << "; ";
        out << kBlockNames[b] << " ratio " << mRatio[b] << " abs " << mAbsolute[b];
        if (mAtRoundOff[b]) out << " (round-off)";
    }
    return out.str();
}

std::string DisplacementLagrangeMultiplierContactCriteria::Info() const {
    const bool disp_residual = mDisplacementMeasure == ContactBlockMeasure::RESIDUAL;
    const bool lm_residual = mLMMeasure == ContactBlockMeasure::RESIDUAL;
    std::string name = disp_residual && lm_residual ? "contact_residual_criterion"
                       : disp_residual              ? "contact_mixed_criterion"
                                                    : "contact_displacement_criterion";
    return mTolerances.split_frictional ? name + " (frictional)" : name;
}

}  // namespace contact_app
