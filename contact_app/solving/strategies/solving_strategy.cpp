// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/strategies/solving_strategy.h"

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/variables.h"

namespace contact_app {

SolvingStrategy::SolvingStrategy(ModelPart& rModelPart, Scheme::Pointer scheme, BuilderAndSolver::Pointer builder,
                                 StrategySettings settings)
    : mModelPart(rModelPart), mScheme(std::move(scheme)), mBuilder(std::move(builder)), mSettings(settings) {
    CONTACT_CHECK(mScheme && mBuilder, InternalError, "strategy created without a scheme or a builder-and-solver");
}

void SolvingStrategy::Initialize() {
    if (mInitialized) return;
    mScheme->Initialize(mModelPart);
    mInitialized = true;
}

void SolvingStrategy::SetUpSystemIfNeeded() {
    if (mBuilder->GetDofSetIsInitializedFlag() && !mSettings.reform_dofs_at_each_step) return;
    mBuilder->SetUpDofSet(*mScheme, mModelPart);
    mBuilder->SetUpSystem(mModelPart);
    mBuilder->ResizeAndInitializeVectors(*mScheme, mA, mDx, mB, mModelPart);
}

void SolvingStrategy::InitializeSolutionStep() {
    if (!mInitialized) Initialize();
    SetUpSystemIfNeeded();
    mBuilder->InitializeSolutionStep(mModelPart, mA, mDx, mB);
    mScheme->InitializeSolutionStep(mModelPart, mA, mDx, mB);
    mSolutionStepInitialized = true;
}

void SolvingStrategy::ApplyConstraintValues() {
    const ProcessInfo& info = mModelPart.GetProcessInfo();
    DofsVectorType slaves, masters;
    bool any = false;
    for (const auto& constraint : mModelPart.MasterSlaveConstraints()) {
        if (!IsAssembled(*constraint)) continue;
        constraint->GetDofList(slaves, masters, info);
        for (Dof* slave : slaves) slave->GetSolutionStepValue() = 0.0;
        any = true;
    }
    if (!any) return;
    Matrix relation;
    Vector constant;
    for (const auto& constraint : mModelPart.MasterSlaveConstraints()) {
        if (!IsAssembled(*constraint)) continue;
        constraint->GetDofList(slaves, masters, info);
        constraint->CalculateLocalSystem(relation, constant, info);
        Vector master_values(static_cast<Eigen::Index>(masters.size()));
        for (std::size_t m = 0; m < masters.size(); ++m) master_values[m] = masters[m]->GetSolutionStepValue();
        const Vector slave_values = relation * master_values + constant;
        for (std::size_t s = 0; s < slaves.size(); ++s) slaves[s]->GetSolutionStepValue() += slave_values[s];
    }
    // Recompute the derived quantities (velocities and accelerations in dynamics) with Δx = 0.
    mDx.setZero(static_cast<Eigen::Index>(mBuilder->GetEquationSystemSize()));
    mScheme->Update(mModelPart, mBuilder->GetDofSet(), mA, mDx, mB);
}

void SolvingStrategy::Predict() {
    if (!mSolutionStepInitialized) InitializeSolutionStep();
    PredictUnknowns();
    ApplyConstraintValues();
    if (mSettings.move_mesh_flag) MoveMesh();
}

void SolvingStrategy::PredictUnknowns() { mScheme->Predict(mModelPart, mBuilder->GetDofSet(), mA, mDx, mB); }

bool SolvingStrategy::SolveSolutionStep() {
    mScheme->InitializeNonLinIteration(mModelPart, mA, mDx, mB);
    mBuilder->BuildAndSolve(*mScheme, mModelPart, mA, mDx, mB);
    mScheme->Update(mModelPart, mBuilder->GetDofSet(), mA, mDx, mB);
    if (mSettings.move_mesh_flag) MoveMesh();
    mScheme->FinalizeNonLinIteration(mModelPart, mA, mDx, mB);
    if (mSettings.compute_reactions) mBuilder->CalculateReactions(*mScheme, mModelPart, mA, mDx, mB);
    mIterations = 1;
    mConverged = true;
    return true;
}

void SolvingStrategy::FinalizeSolutionStep() {
    mScheme->FinalizeSolutionStep(mModelPart, mA, mDx, mB);
    mBuilder->FinalizeSolutionStep(mModelPart, mA, mDx, mB);
    if (mSettings.reform_dofs_at_each_step) mBuilder->Clear();
    mSolutionStepInitialized = false;
}

bool SolvingStrategy::Solve() {
    InitializeSolutionStep();
    Predict();
    const bool converged = SolveSolutionStep();
    FinalizeSolutionStep();
    return converged;
}

int SolvingStrategy::Check() { return mScheme->Check(mModelPart); }

void SolvingStrategy::Clear() {
    mBuilder->Clear();
    mA.resize(0, 0);
    mDx.resize(0);
    mB.resize(0);
}

void SolvingStrategy::MoveMesh() {
    if (!mModelPart.HasNodalSolutionStepVariable(DISPLACEMENT)) return;
    for (const auto& node : mModelPart.Nodes())
        node->Coordinates() = node->InitialCoordinates() + node->FastGetSolutionStepValue(DISPLACEMENT);
}

}  // namespace contact_app
