// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/residual_based_newton_raphson_mpc_contact_strategy.h"

#include <iostream>
#include <unordered_map>
#include <utility>
#include <vector>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "custom_conditions/paired_condition.h"
#include "custom_utilities/contact_utilities.h"

namespace contact_app {
ResidualBasedNewtonRaphsonMPCContactStrategy::ResidualBasedNewtonRaphsonMPCContactStrategy(
    ModelPart& rModelPart, Scheme::Pointer scheme, BuilderAndSolver::Pointer builder,
    ConvergenceCriteria::Pointer criteria, int max_iterations, StrategySettings settings,
    MPCContactStrategySettings mpc_settings)
    : NewtonRaphsonStrategy(rModelPart, std::move(scheme), std::move(builder), std::move(criteria), max_iterations,
                            settings),
      mMPCSettings(mpc_settings) {
    CONTACT_CHECK(mpc_settings.inner_loop_iterations >= 1, InputError,
                  "mpc_contact_settings.inner_loop_iterations must be at least 1, got ",
                  mpc_settings.inner_loop_iterations, "\n  fix: set it to 1 or more (default 10)");
}

void ResidualBasedNewtonRaphsonMPCContactStrategy::ComputeNodalWeights(ModelPart& rModelPart) {
    ModelPart* contact = ContactUtilities::FindContactPart(rModelPart, "Contact");
    if (contact == nullptr) return;
    std::unordered_map<IndexType, int> counts;
    for (const auto& condition : contact->Conditions()) {
        if (!condition->Is(SLAVE)) continue;
        const Geometry& face = condition->GetGeometry();
        for (std::size_t i = 0; i < face.size(); ++i) ++counts[face[i].Id()];
    }
    for (const auto& node : contact->Nodes()) {
        const auto found = counts.find(node->Id());
        node->SetValue(NODAL_PAUX, found == counts.end() ? 0.0 : static_cast<double>(found->second));
    }
}

void ResidualBasedNewtonRaphsonMPCContactStrategy::ComputeExplicitContributions() {
    if (ModelPart* computing = ContactUtilities::FindContactPart(mModelPart, "ComputingContact"))
        ContactUtilities::ComputeExplicitContributionConditions(*computing);
}

void ResidualBasedNewtonRaphsonMPCContactStrategy::Initialize() {
    NewtonRaphsonStrategy::Initialize();
    mModelPart.GetProcessInfo().SetValue(NL_ITERATION_NUMBER, 1);
}

void ResidualBasedNewtonRaphsonMPCContactStrategy::InitializeSolutionStep() {
    ComputeNodalWeights(mModelPart);
    // The pairs rebuild their constraints in their InitializeSolutionStep (start-of-step state); the rebuilds inside
    // the step are done by RefreshConstraints, never by the scheme's InitializeNonLinIteration.
    if (ModelPart* computing = ContactUtilities::FindContactPart(mModelPart, "ComputingContact"))
        for (const auto& condition : computing->Conditions()) condition->Set(INTERACTION, false);
    mRefreshConstraints = false;
    NewtonRaphsonStrategy::InitializeSolutionStep();
}

void ResidualBasedNewtonRaphsonMPCContactStrategy::RefreshConstraints() {
    ModelPart* computing = ContactUtilities::FindContactPart(mModelPart, "ComputingContact");
    if (computing == nullptr) return;
    const ProcessInfo& info = mModelPart.GetProcessInfo();
    // INTERACTION tells each pair that its gaps are those of the current iterate (the criteria computed them), so it
    // builds the normal constant at the current displacement (MPCMortarContactCondition::ComputeConstraintRelation).
    for (const auto& condition : computing->Conditions()) {
        condition->Set(INTERACTION, true);
        condition->InitializeNonLinearIteration(info);
        condition->Set(INTERACTION, false);
    }
}

void ResidualBasedNewtonRaphsonMPCContactStrategy::PredictUnknowns() { mScheme->PredictPrescribed(mModelPart); }

void ResidualBasedNewtonRaphsonMPCContactStrategy::Predict() {
    NewtonRaphsonStrategy::Predict();
    // Gaps of the predicted configuration: the first criterion check compares with them.
    ComputeExplicitContributions();
}

bool ResidualBasedNewtonRaphsonMPCContactStrategy::NewtonLoop() {
    ProcessInfo& info = mModelPart.GetProcessInfo();
    mHistory.clear();
    mIterations = 0;
    bool converged = false;
    while (!converged && mIterations < mMaxIterations) {
        ++mIterations;
        info.SetValue(NL_ITERATION_NUMBER, mIterations);
        ComputeNodalWeights(mModelPart);
        mScheme->InitializeNonLinIteration(mModelPart, mA, mDx, mB);
        if (mMPCSettings.update_each_nl_iteration || mRefreshConstraints) RefreshConstraints();
        mRefreshConstraints = false;
        // The builder eliminates increments (Δu_s = T Δu_m): a rebuilt or newly active constraint is imposed on
        // the total values first, which is the reference's effective constant c + T ū − u.
        ApplyConstraintValues();
        if (mSettings.move_mesh_flag) MoveMesh();
        const bool pre = mCriteria->PreCriteria(mModelPart, mBuilder->GetDofSet(), mA, mDx, mB);
        mBuilder->BuildAndSolve(*mScheme, mModelPart, mA, mDx, mB);
        if (mIterations == 1) mCriteria->InitializePredictedResidual(mBuilder->GetDofSet(), mB, *mBuilder);
        UpdateSolution();
        mScheme->FinalizeNonLinIteration(mModelPart, mA, mDx, mB);
        // The criterion reads the contact forces from the reactions of the constraint slaves.
        mBuilder->CalculateReactions(*mScheme, mModelPart, mA, mDx, mB);
        if (!pre) {
            NotifyIteration();
            continue;
        }
        if (mCriteria->GetActualizeRHSflag()) mBuilder->BuildRHS(*mScheme, mModelPart, mB);
        converged = mCriteria->PostCriteria(mModelPart, mBuilder->GetDofSet(), mA, mDx, mB, *mBuilder);
        // A changed active (or stick/slip) set changes the rows of T: none for inactive slave nodes, normal-only
        // for slipping ones, full for sticking ones.
        mRefreshConstraints = (info.Has(ACTIVE_SET_CONVERGED) && !info.GetValue(ACTIVE_SET_CONVERGED)) ||
                              (info.Has(SLIP_SET_CONVERGED) && !info.GetValue(SLIP_SET_CONVERGED));
        mHistory.push_back(mCriteria->LastNorms());
        if (mSettings.echo_level >= 2)
            std::cout << "  MPC Newton iteration " << mIterations << ": " << mHistory.back() << "\n";
        NotifyIteration();
    }
    return converged;
}

bool ResidualBasedNewtonRaphsonMPCContactStrategy::SolveSolutionStep() {
    ProcessInfo& info = mModelPart.GetProcessInfo();
    bool converged = false;
    if (!info.Is(INTERACTION)) {
        mInnerLoops = 1;
        converged = NewtonLoop();
    } else {
        for (mInnerLoops = 1; mInnerLoops <= mMPCSettings.inner_loop_iterations; ++mInnerLoops) {
            info.SetValue(INNER_LOOP_ITERATION, mInnerLoops);
            converged = NewtonLoop();
            // Outer check of the set at the converged state (reactions are current).
            info.SetValue(NL_ITERATION_NUMBER, 1);
            mActiveSetCriteria->PreCriteria(mModelPart, mBuilder->GetDofSet(), mA, mDx, mB);
            const bool set_converged =
                mActiveSetCriteria->PostCriteria(mModelPart, mBuilder->GetDofSet(), mA, mDx, mB, *mBuilder);
            mRefreshConstraints = !set_converged;
            if (converged && set_converged) break;
        }
        mInnerLoops = std::min(mInnerLoops, mMPCSettings.inner_loop_iterations);
    }
    mConverged = converged;
    if (mSettings.echo_level >= 1)
        std::cout << "  MPC Newton: " << (converged ? "converged in " : "NOT converged after ") << mIterations
                  << " iteration(s), " << mInnerLoops << " active-set loop(s)\n";
    if (mSettings.compute_reactions) mBuilder->CalculateReactions(*mScheme, mModelPart, mA, mDx, mB);
    return converged;
}

}  // namespace contact_app
