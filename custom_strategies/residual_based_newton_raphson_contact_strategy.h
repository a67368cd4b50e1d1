// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/solving/strategies/newton_raphson_strategy.h"

namespace contact_app {

/// Settings of the contact Newton strategy (contact_settings keys of the same names).
struct ContactStrategySettings {
    /// Active-set loops of the simplified semi-smooth Newton (model part not INTERACTION).
    int inner_loop_iterations = 5;
};

/// Newton–Raphson for mortar contact (Kratos ResidualBasedNewtonRaphsonContactStrategy,
/// docs/theory/contact_strategies.md §1).
/// - Predict: only what the step prescribes (the scheme's PredictPrescribed: free DoFs stay at the last converged
///   state, as the reference's contact strategy, which does not call the scheme's predictor; extrapolating a body
///   about to touch or slide pushes it through the other and can invert the elements next to a driven face), then
///   the contact normals and the weighted gaps (and slips) of the pairs in
///   "ComputingContact" are recomputed at the predicted configuration (the first build and the active-set criteria
///   use them; with prescribed displacements the predicted configuration is already the deformed one).
/// - SolveSolutionStep: with the model part flagged INTERACTION (the default, full semi-smooth Newton) one Newton
///   loop in which the mortar criterion updates the active set at every iteration; otherwise (simplified
///   semi-smooth Newton) up to inner_loop_iterations Newton loops, the set being updated only at the first
///   iteration of each (NL_ITERATION_NUMBER == 1) and the loop stopping when it no longer changes.
/// Step splitting on non-convergence (adaptative_strategy) is done by the Python contact solver, which owns the
/// processes that must run in each sub-step.
class ResidualBasedNewtonRaphsonContactStrategy : public NewtonRaphsonStrategy {
public:
    ResidualBasedNewtonRaphsonContactStrategy(ModelPart& rModelPart, Scheme::Pointer scheme,
                                              BuilderAndSolver::Pointer builder, ConvergenceCriteria::Pointer criteria,
                                              int max_iterations = 30, StrategySettings settings = {},
                                              ContactStrategySettings contact_settings = {});

    void Initialize() override;
    void Predict() override;
    bool SolveSolutionStep() override;

    /// Inner (active-set) loops used by the last step (1 with the full semi-smooth Newton).
    int GetInnerLoopIterations() const { return mInnerLoops; }

protected:
    /// After the first iteration of a Newton loop, with a moving mesh: the nodal and condition normals of
    /// "Contact" are recomputed on the moved mesh, once, before the first PostCriteria. The reference strategy
    /// does this by calling the criteria's InitializeSolutionStep again at that point; without it the whole
    /// step keeps the normals of its start while the mortar operators are integrated on the current surface.
    void BeforeReferenceResidual() override;
    void PredictUnknowns() override;
    void AfterSolutionUpdate() override;
    /// The nodal sums of the pairs, then the criteria's normal and tangent refresh.
    void RefreshBeforeBuild() override;

private:
    void ComputeExplicitContributions();

    ContactStrategySettings mContactSettings;
    int mInnerLoops = 0;
};

}  // namespace contact_app
