// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/strategies/line_search_strategy.h"

#include <algorithm>
#include <cmath>

#include "contact_app/kernel/exceptions.h"

namespace contact_app {

LineSearchStrategy::LineSearchStrategy(ModelPart& rModelPart, Scheme::Pointer scheme,
                                       BuilderAndSolver::Pointer builder, ConvergenceCriteria::Pointer criteria,
                                       int max_iterations, StrategySettings settings, LineSearchSettings line_search)
    : NewtonRaphsonStrategy(rModelPart, std::move(scheme), std::move(builder), std::move(criteria), max_iterations,
                            settings),
      mLineSearch(line_search) {
    CONTACT_CHECK(line_search.min_alpha > 0.0 && line_search.min_alpha <= line_search.max_alpha, InputError,
                  "line search needs 0 < min_alpha <= max_alpha, got ", line_search.min_alpha, " and ",
                  line_search.max_alpha);
}

double LineSearchStrategy::Move(const SystemVectorType& rDirection, double step) {
    SystemVectorType increment = step * rDirection;
    mScheme->Update(mModelPart, mBuilder->GetDofSet(), mA, increment, mB);
    if (mSettings.move_mesh_flag) MoveMesh();
    SystemVectorType residual;
    mBuilder->BuildRHS(*mScheme, mModelPart, residual);
    return rDirection.dot(residual);
}

void LineSearchStrategy::UpdateSolution() {
    const SystemVectorType direction = mDx;
    const double phi_0 = Move(direction, 0.0);
    double alpha_1 = mLineSearch.first_alpha_value;
    double alpha_2 = mLineSearch.second_alpha_value;
    double phi_1 = Move(direction, alpha_1);
    double phi_2 = Move(direction, alpha_2 - alpha_1);
    double current = alpha_2;
    for (int i = 0; i < mLineSearch.max_line_search_iterations; ++i) {
        if (std::abs(phi_2) <= mLineSearch.line_search_tolerance * std::abs(phi_0) || phi_2 == phi_1) break;
        const double next = std::clamp(alpha_2 - phi_2 * (alpha_2 - alpha_1) / (phi_2 - phi_1), mLineSearch.min_alpha,
                                       mLineSearch.max_alpha);
        alpha_1 = alpha_2;
        phi_1 = phi_2;
        alpha_2 = next;
        phi_2 = Move(direction, alpha_2 - current);
        current = alpha_2;
    }
    mLastAlpha = current;
    mDx = current * direction;  // what the displacement criterion reads
}

}  // namespace contact_app
