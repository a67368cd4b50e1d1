// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "contact_app/solving/convergence_criteria/convergence_criteria.h"
#include "contact_app/solving/strategies/solving_strategy.h"

namespace contact_app {

/// Full Newton–Raphson with the LHS rebuilt every iteration (Kratos
/// ResidualBasedNewtonRaphsonStrategy, docs/theory/structural.md §6): at most
/// max_iterations linear solves per step; a step that does not converge is reported
/// (LastStepConverged() == false, the norms in IterationHistory()) and left as it is — the caller
/// decides whether to go on (Kratos does) or to cut the step.
class NewtonRaphsonStrategy : public SolvingStrategy {
public:
    /// @param[in,out] rModelPart the model part solved; it outlives the strategy
    /// @param[in] scheme,builder shared with the caller (not null)
    /// @param[in] criteria shared with the caller (not null)
    /// @param[in] max_iterations linear solves per step at most (≥ 1)
    /// @param[in] settings the solver_settings the strategy reads (reactions, DoF rebuild, mesh motion, echo)
    NewtonRaphsonStrategy(ModelPart& rModelPart, Scheme::Pointer scheme, BuilderAndSolver::Pointer builder,
                          ConvergenceCriteria::Pointer criteria, int max_iterations = 10,
                          StrategySettings settings = {});

    void Initialize() override;
    void InitializeSolutionStep() override;
    bool SolveSolutionStep() override;
    void FinalizeSolutionStep() override;

    ConvergenceCriteria& GetConvergenceCriteria() { return *mCriteria; }
    int GetMaxIterationNumber() const { return mMaxIterations; }
    void SetMaxIterationNumber(int max_iterations);
    /// One line per iteration of the last step: the criterion's norms.
    const std::vector<std::string>& IterationHistory() const { return mHistory; }

    /// A(x) v and the central difference −(b(x + hv) − b(x − hv)) / 2h of the RHS at the current iterate x (a check of
    /// a whole model's tangent, docs/theory/structural.md §6 "Checking the assembled tangent"), both zero on the fixed
    /// DoFs. What the residual reads besides the unknowns is refreshed at every state as before a build
    /// (RefreshBeforeBuild); the state is restored afterwards (round-off aside).
    struct TangentCheck {
        SystemVectorType tangent_times_direction;
        SystemVectorType central_difference;
        SystemVectorType direction;  ///< v as used: fixed entries zeroed, or the Newton correction
    };
    /// @param[in] direction v over the equation ids; empty: the Newton correction A(x)⁻¹ b(x)
    /// @param[in] step h, in the units of the unknowns
    /// @throws InputError for a model with multipoint constraints, a direction of the wrong size or h ≤ 0
    TangentCheck CheckTangentAlong(SystemVectorType direction, double step);

protected:
    /// Updates the unknowns with Δx (line search overrides it).
    virtual void UpdateSolution();
    /// Called after the update of an iteration whose PreCriteria passed, just before the residual of the criteria
    /// and PostCriteria (contact strategies refresh their normals and nodal weighted gaps there). Does nothing by
    /// default.
    virtual void AfterSolutionUpdate() {}
    /// Called after the entities' InitializeSolutionStep, before the step's reference residual: data the residual
    /// reads besides the unknowns (contact: the nodal weighted gaps of new pairs). Does nothing by default.
    virtual void BeforeReferenceResidual() {}
    /// What an iteration refreshes before its build besides the unknowns (the criterion's PreCriteria; contact: also
    /// the nodal sums), for CheckTangentAlong's perturbed states.
    virtual void RefreshBeforeBuild();
    /// One Newton iteration: build, solve, update, move mesh, hooks. Returns the criterion's verdict.
    bool Iterate();

    ConvergenceCriteria::Pointer mCriteria;
    int mMaxIterations;
    std::vector<std::string> mHistory;
};

}  // namespace contact_app
