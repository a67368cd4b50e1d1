// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/solving/strategies/newton_raphson_strategy.h"

namespace contact_app {

/// Settings of the secant line search (Kratos LineSearchStrategy defaults).
struct LineSearchSettings {
    int max_line_search_iterations = 5;
    double first_alpha_value = 0.5;
    double second_alpha_value = 1.0;
    double min_alpha = 0.1;
    double max_alpha = 2.0;
    double line_search_tolerance = 0.5;
};

/// Newton–Raphson whose update x += α Δx picks α by a secant search on φ(α) = Δx · r(x + α Δx),
/// stopping when |φ(α)| ≤ tolerance · |φ(0)|; α is kept in [min_alpha, max_alpha].
class LineSearchStrategy : public NewtonRaphsonStrategy {
public:
    LineSearchStrategy(ModelPart& rModelPart, Scheme::Pointer scheme, BuilderAndSolver::Pointer builder,
                       ConvergenceCriteria::Pointer criteria, int max_iterations = 10, StrategySettings settings = {},
                       LineSearchSettings line_search = {});

    /// α of the last update (for reports and tests).
    double LastAlpha() const { return mLastAlpha; }

protected:
    void UpdateSolution() override;

private:
    /// Moves the unknowns by @p step · Δx and returns φ = Δx · r at the new state.
    double Move(const SystemVectorType& rDirection, double step);

    LineSearchSettings mLineSearch;
    double mLastAlpha = 1.0;
};

}  // namespace contact_app
