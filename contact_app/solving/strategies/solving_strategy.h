// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "contact_app/kernel/model_part.h"
#include "contact_app/solving/builder_and_solvers/builder_and_solver.h"
#include "contact_app/solving/schemes/scheme.h"
#include "contact_app/solving/system_types.h"

namespace contact_app {

/// Settings shared by the implicit strategies (names and defaults of the Kratos solver_settings).
struct StrategySettings {
    bool compute_reactions = true;
    bool reform_dofs_at_each_step = false;
    bool move_mesh_flag = true;
    int echo_level = 0;
};

/// Drives one time step (Kratos ImplicitSolvingStrategy): Initialize once, then per step
/// InitializeSolutionStep → Predict → SolveSolutionStep → FinalizeSolutionStep (or Solve()).
/// The base is the linear strategy: one build, solve and update per step.
class SolvingStrategy {
public:
    using Pointer = std::shared_ptr<SolvingStrategy>;

    /// @param[in,out] rModelPart the model part solved; it outlives the strategy
    /// @param[in] scheme,builder shared with the caller (not null)
    /// @param[in] settings the solver_settings the strategy reads (reactions, DoF rebuild, mesh motion, echo)
    SolvingStrategy(ModelPart& rModelPart, Scheme::Pointer scheme, BuilderAndSolver::Pointer builder,
                    StrategySettings settings = {});
    virtual ~SolvingStrategy() = default;

    virtual void Initialize();
    virtual void InitializeSolutionStep();
    virtual void Predict();
    /// @return true when the step converged (the linear strategy always does).
    virtual bool SolveSolutionStep();
    virtual void FinalizeSolutionStep();
    /// The four calls above in order. @return SolveSolutionStep's result.
    bool Solve();
    /// Runs the scheme's and entities' checks. @throws InputError from the first failure.
    virtual int Check();
    /// Forgets the DoF set, the graph and the factorisation.
    virtual void Clear();

    /// Current coordinates = initial coordinates + DISPLACEMENT (when DISPLACEMENT is historical).
    void MoveMesh();
    ModelPart& GetModelPart() { return mModelPart; }
    Scheme& GetScheme() { return *mScheme; }
    BuilderAndSolver& GetBuilderAndSolver() { return *mBuilder; }
    SparseMatrixType& GetSystemMatrix() { return mA; }
    SystemVectorType& GetSystemVector() { return mB; }
    SystemVectorType& GetSolutionVector() { return mDx; }
    /// Iterations (linear solves) of the last step and whether it converged.
    int GetIterationNumber() const { return mIterations; }
    bool LastStepConverged() const { return mConverged; }
    void SetEchoLevel(int level) { mSettings.echo_level = level; }
    /// Called after every Newton iteration (its number is GetIterationNumber()), e.g. to show live progress; an
    /// empty function removes it. An exception thrown by the observer ends the step and propagates.
    void SetIterationObserver(std::function<void()> observer) { mIterationObserver = std::move(observer); }
    const StrategySettings& Settings() const { return mSettings; }

protected:
    /// Builds the DoF set, numbering and graph when missing or when reforming each step.
    void SetUpSystemIfNeeded();
    /// Imposes u_s = T u_m + c on the slaves of the active constraints (Predict).
    void ApplyConstraintValues();
    /// The unknowns of the new step, before the constraints and the mesh motion of Predict: the scheme's predictor.
    virtual void PredictUnknowns();
    /// Calls the iteration observer, if any.
    void NotifyIteration() {
        if (mIterationObserver) mIterationObserver();
    }

    ModelPart& mModelPart;
    Scheme::Pointer mScheme;
    BuilderAndSolver::Pointer mBuilder;
    StrategySettings mSettings;
    SparseMatrixType mA;
    SystemVectorType mDx;
    SystemVectorType mB;
    bool mInitialized = false;
    bool mSolutionStepInitialized = false;
    int mIterations = 0;
    bool mConverged = false;
    std::function<void()> mIterationObserver;
};

}  // namespace contact_app
