// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/strategies/newton_raphson_strategy.h"

#include <iostream>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/variables.h"

namespace contact_app {

NewtonRaphsonStrategy::NewtonRaphsonStrategy(ModelPart& rModelPart, Scheme::Pointer scheme,
                                             BuilderAndSolver::Pointer builder, ConvergenceCriteria::Pointer criteria,
                                             int max_iterations, StrategySettings settings)
    : SolvingStrategy(rModelPart, std::move(scheme), std::move(builder), settings),
      mCriteria(std::move(criteria)),
      mMaxIterations(max_iterations) {
    CONTACT_CHECK(mCriteria != nullptr, InternalError, "Newton strategy created without a convergence criterion");
    SetMaxIterationNumber(max_iterations);
}

void NewtonRaphsonStrategy::SetMaxIterationNumber(int max_iterations) {
    CONTACT_CHECK(max_iterations >= 1, InputError, "max_iteration must be at least 1, got ", max_iterations);
    mMaxIterations = max_iterations;
}

void NewtonRaphsonStrategy::Initialize() {
    SolvingStrategy::Initialize();
    if (!mCriteria->IsInitialized()) mCriteria->Initialize(mModelPart);
}

void NewtonRaphsonStrategy::InitializeSolutionStep() {
    SolvingStrategy::InitializeSolutionStep();
    BeforeReferenceResidual();
    // The residual reference is taken before Predict, as Kratos does.
    if (mCriteria->GetActualizeRHSflag()) mBuilder->BuildRHS(*mScheme, mModelPart, mB);
    mCriteria->InitializeSolutionStep(mModelPart, mBuilder->GetDofSet(), mA, mDx, mB, *mBuilder);
}

void NewtonRaphsonStrategy::UpdateSolution() {
    mScheme->Update(mModelPart, mBuilder->GetDofSet(), mA, mDx, mB);
    if (mSettings.move_mesh_flag) MoveMesh();
}

bool NewtonRaphsonStrategy::Iterate() {
    ProcessInfo& info = mModelPart.GetProcessInfo();
    info.SetValue(NL_ITERATION_NUMBER, mIterations);
    mScheme->InitializeNonLinIteration(mModelPart, mA, mDx, mB);
    const bool pre = mCriteria->PreCriteria(mModelPart, mBuilder->GetDofSet(), mA, mDx, mB);
    mBuilder->BuildAndSolve(*mScheme, mModelPart, mA, mDx, mB);
    if (mIterations == 1) mCriteria->InitializePredictedResidual(mBuilder->GetDofSet(), mB, *mBuilder);
    UpdateSolution();
    mScheme->FinalizeNonLinIteration(mModelPart, mA, mDx, mB);
    if (!pre) return false;
    AfterSolutionUpdate();
    if (mCriteria->GetActualizeRHSflag()) mBuilder->BuildRHS(*mScheme, mModelPart, mB);
    const bool converged = mCriteria->PostCriteria(mModelPart, mBuilder->GetDofSet(), mA, mDx, mB, *mBuilder);
    mHistory.push_back(mCriteria->LastNorms());
    if (mSettings.echo_level >= 2) std::cout << "  Newton iteration " << mIterations << ": " << mHistory.back() << "\n";
    return converged;
}

bool NewtonRaphsonStrategy::SolveSolutionStep() {
    mHistory.clear();
    mIterations = 0;
    bool converged = false;
    while (!converged && mIterations < mMaxIterations) {
        ++mIterations;
        converged = Iterate();
        NotifyIteration();
    }
    mConverged = converged;
    if (mSettings.echo_level >= 1) {
        std::cout << "  Newton: " << (converged ? "converged in " : "NOT converged after ") << mIterations
                  << " iteration(s)" << (mHistory.empty() ? "" : "; " + mHistory.back()) << "\n";
    }
    if (mSettings.compute_reactions) mBuilder->CalculateReactions(*mScheme, mModelPart, mA, mDx, mB);
    return converged;
}

void NewtonRaphsonStrategy::RefreshBeforeBuild() {
    mCriteria->PreCriteria(mModelPart, mBuilder->GetDofSet(), mA, mDx, mB);
}

NewtonRaphsonStrategy::TangentCheck NewtonRaphsonStrategy::CheckTangentAlong(SystemVectorType direction,
                                                                                 double step) {
    CONTACT_CHECK(step > 0.0, InputError, "CheckTangentAlong: the step h must be positive, got ", step);
    CONTACT_CHECK(mModelPart.MasterSlaveConstraints().empty(), InputError,
                  "CheckTangentAlong: the model part ", mModelPart.FullName(),
                  " has multipoint constraints, whose transformed system the check does not follow");
    SetUpSystemIfNeeded();
    const auto n = static_cast<Eigen::Index>(mBuilder->GetEquationSystemSize());
    CONTACT_CHECK(direction.size() == 0 || direction.size() == n, InputError, "CheckTangentAlong: the direction has ",
                  direction.size(), " entries, the system ", n);
    if (mA.rows() != n) mBuilder->ResizeAndInitializeVectors(*mScheme, mA, mDx, mB, mModelPart);
    const auto& dofs = mBuilder->GetDofSet();
    auto zero_fixed = [&](SystemVectorType& rVector) {
        for (const auto& dof : dofs)
            if (dof->IsFixed() && static_cast<Eigen::Index>(dof->EquationId()) < n) rVector[dof->EquationId()] = 0.0;
    };
    RefreshBeforeBuild();
    mBuilder->Build(*mScheme, mModelPart, mA, mB);
    mBuilder->ApplyDirichletConditions(*mScheme, mModelPart, mA, mDx, mB);
    if (direction.size() == 0) {
        mBuilder->SystemSolve(mA, mDx, mB);
        direction = mDx;
    }
    zero_fixed(direction);
    TangentCheck check;
    check.tangent_times_direction = mA * direction;
    zero_fixed(check.tangent_times_direction);
    auto rhs_at_shift = [&](double shift) {
        mDx = shift * direction;
        NewtonRaphsonStrategy::UpdateSolution();  // the plain update, not a line search
        RefreshBeforeBuild();
        SystemVectorType rhs = SystemVectorType::Zero(n);
        mBuilder->BuildRHS(*mScheme, mModelPart, rhs);
        mDx = -shift * direction;
        NewtonRaphsonStrategy::UpdateSolution();
        return rhs;
    };
    const SystemVectorType plus = rhs_at_shift(step);
    const SystemVectorType minus = rhs_at_shift(-step);
    RefreshBeforeBuild();
    check.central_difference = -(plus - minus) / (2.0 * step);
    zero_fixed(check.central_difference);
    check.direction = std::move(direction);
    return check;
}

void NewtonRaphsonStrategy::FinalizeSolutionStep() {
    SolvingStrategy::FinalizeSolutionStep();
    mCriteria->FinalizeSolutionStep(mModelPart, mBuilder->GetDofSet(), mA, mDx, mB);
}

}  // namespace contact_app
