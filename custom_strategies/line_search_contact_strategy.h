// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>

#include "custom_strategies/residual_based_newton_raphson_contact_strategy.h"

namespace contact_app {

/// The contact Newton strategy with a block line search (Kratos LineSearchContactStrategy, registered
/// `line_search_contact_strategy`, docs/theory/contact_strategies.md §2). After each solve the residual is evaluated at
/// 0, ½ and 1 times the increment and split into the displacement and the multiplier blocks; per block a parabola
/// through the three norms gives the step length α (its minimum when convex, clamped to [α_min, 1]; otherwise 1
/// if the full step did not increase the norm, else α_min). The increment of each block is then scaled by its α.
/// The reference's implementation keeps the full step in every case ([BUG?]: the optimum is written into the
/// wrong variable); this is the intended search.
class LineSearchContactStrategy : public ResidualBasedNewtonRaphsonContactStrategy {
public:
    /// @param[in,out] rModelPart the model part solved; it outlives the strategy
    /// @param[in] scheme,builder,criteria shared with the caller (not null)
    /// @param[in] max_iterations Newton iterations per step at most (≥ 1)
    /// @param[in] settings the solver_settings the strategy reads (reactions, DoF rebuild, mesh motion, echo)
    /// @param[in] contact_settings the contact_settings of the contact Newton strategy
    /// @param[in] min_alpha smallest step length (the reference's 1e-3)
    LineSearchContactStrategy(ModelPart& rModelPart, Scheme::Pointer scheme, BuilderAndSolver::Pointer builder,
                              ConvergenceCriteria::Pointer criteria, int max_iterations = 30,
                              StrategySettings settings = {}, ContactStrategySettings contact_settings = {},
                              double min_alpha = 1.0e-3);

    /// Step lengths of the last update: displacement block, multiplier block.
    double LastDisplacementAlpha() const { return mAlpha[0]; }
    double LastMultiplierAlpha() const { return mAlpha[1]; }
    /// α of one block from its residual norms at 0, ½ and 1 (public for the tests).
    static double BlockAlpha(double r0, double r_half, double r1, double min_alpha);

protected:
    void UpdateSolution() override;

private:
    /// Residual ℓ2 norms of the free displacement and multiplier equations at the current state.
    std::array<double, 2> BlockResidualNorms();
    void Apply(const SystemVectorType& rIncrement);

    double mMinAlpha;
    double mAlpha[2] = {1.0, 1.0};
};

}  // namespace contact_app
