// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/residual_based_newton_raphson_contact_strategy.h"

#include <algorithm>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "custom_strategies/mortar_convergence_criteria.h"
#include "custom_strategies/nodal_normal_coupling.h"
#include "custom_strategies/nodal_penalty_coupling.h"
#include "custom_utilities/contact_utilities.h"
#include "custom_utilities/mortar_normals.h"

namespace contact_app {
namespace {

template <class TContributor>
void AddContributorOnce(BuilderAndSolver& rBuilder) {
    const auto& contributors = rBuilder.AssemblyContributors();
    if (std::none_of(contributors.begin(), contributors.end(), [](const auto& contributor) {
            return dynamic_cast<const TContributor*>(contributor.get()) != nullptr;
        }))
        rBuilder.AddAssemblyContributor(std::make_shared<TContributor>());
}

}  // namespace

ResidualBasedNewtonRaphsonContactStrategy::ResidualBasedNewtonRaphsonContactStrategy(
    ModelPart& rModelPart, Scheme::Pointer scheme, BuilderAndSolver::Pointer builder,
    ConvergenceCriteria::Pointer criteria, int max_iterations, StrategySettings settings,
    ContactStrategySettings contact_settings)
    : NewtonRaphsonStrategy(rModelPart, std::move(scheme), std::move(builder), std::move(criteria), max_iterations,
                            settings),
      mContactSettings(contact_settings) {
    CONTACT_CHECK(contact_settings.inner_loop_iterations >= 1, InputError,
                  "contact_settings.inner_loop_iterations must be at least 1, got ",
                  contact_settings.inner_loop_iterations);
    // The penalty pairs of a slave node are coupled through its weighted gap, and the pairs of nodal normals that follow
    // the iterate through the faces around the node (a builder shared by several strategies gets each once).
    AddContributorOnce<NodalPenaltyCoupling>(*mBuilder);
    AddContributorOnce<NodalNormalCoupling>(*mBuilder);
}

void ResidualBasedNewtonRaphsonContactStrategy::Initialize() {
    NewtonRaphsonStrategy::Initialize();
    mModelPart.GetProcessInfo().SetValue(NL_ITERATION_NUMBER, 1);
}

void ResidualBasedNewtonRaphsonContactStrategy::ComputeExplicitContributions() {
    ModelPart& root = mModelPart.GetRootModelPart();
    if (root.HasSubModelPart("ComputingContact"))
        ContactUtilities::ComputeExplicitContributionConditions(root.GetSubModelPart("ComputingContact"));
}

void ResidualBasedNewtonRaphsonContactStrategy::Predict() {
    NewtonRaphsonStrategy::Predict();
    // The prediction moved the mesh (prescribed displacements, dynamics): normals and gaps of the predicted state.
    if (mSettings.move_mesh_flag) UpdateContactNormals(mModelPart);
    ComputeExplicitContributions();
}

void ResidualBasedNewtonRaphsonContactStrategy::PredictUnknowns() { mScheme->PredictPrescribed(mModelPart); }

void ResidualBasedNewtonRaphsonContactStrategy::BeforeReferenceResidual() {
    ComputeExplicitContributions();
}

void ResidualBasedNewtonRaphsonContactStrategy::AfterSolutionUpdate() {
    ModelPart* contact = ContactUtilities::FindContactPart(mModelPart, "Contact");
    if (contact == nullptr) return;
    if (mIterations == 1 && mSettings.move_mesh_flag) ComputeNodesMeanNormalModelPart(*contact, true);
    // The residual of the criteria and the set update read the weighted gaps of the updated configuration; the
    // previous iteration's gap stays in WEIGHTED_GAP(1) for the adaptive penalty and the dynamic factor.
    ModelPart& root = mModelPart.GetRootModelPart();
    if (root.HasNodalSolutionStepVariable(WEIGHTED_GAP) && root.GetBufferSize() > 1)
        for (const auto& node : contact->Nodes())
            node->FastGetSolutionStepValue(WEIGHTED_GAP, 1) = node->FastGetSolutionStepValue(WEIGHTED_GAP);
    ComputeExplicitContributions();
}

void ResidualBasedNewtonRaphsonContactStrategy::RefreshBeforeBuild() {
    ComputeExplicitContributions();
    NewtonRaphsonStrategy::RefreshBeforeBuild();
}

bool ResidualBasedNewtonRaphsonContactStrategy::SolveSolutionStep() {
    ProcessInfo& info = mModelPart.GetProcessInfo();
    const bool full_semi_smooth = mModelPart.IsNotDefined(INTERACTION) || mModelPart.Is(INTERACTION);
    if (full_semi_smooth) {
        mInnerLoops = 1;
        return NewtonRaphsonStrategy::SolveSolutionStep();
    }
    bool converged = false;
    for (mInnerLoops = 1; mInnerLoops <= mContactSettings.inner_loop_iterations; ++mInnerLoops) {
        info.SetValue(INNER_LOOP_ITERATION, mInnerLoops);
        converged = NewtonRaphsonStrategy::SolveSolutionStep();
        // The set is frozen after the first iteration of a loop: ask the criteria once more whether it still holds.
        info.SetValue(NL_ITERATION_NUMBER, 1);
        if (mCriteria->GetActualizeRHSflag()) mBuilder->BuildRHS(*mScheme, mModelPart, mB);
        const bool set_converged = mCriteria->PostCriteria(mModelPart, mBuilder->GetDofSet(), mA, mDx, mB, *mBuilder);
        if (converged && set_converged) break;
    }
    mInnerLoops = std::min(mInnerLoops, mContactSettings.inner_loop_iterations);
    mConverged = converged;
    return converged;
}

}  // namespace contact_app
