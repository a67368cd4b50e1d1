// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/line_search_contact_strategy.h"

#include <algorithm>
#include <cmath>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"

namespace contact_app {
namespace {

/// 1 for the multiplier DoFs of the contact and tying formulations, 0 otherwise.
int BlockOf(const Dof& dof) {
    const Variable<double>& v = dof.GetVariable();
    const bool multiplier = v == LAGRANGE_MULTIPLIER_CONTACT_PRESSURE || v == SCALAR_LAGRANGE_MULTIPLIER ||
                            v == VECTOR_LAGRANGE_MULTIPLIER_X || v == VECTOR_LAGRANGE_MULTIPLIER_Y ||
                            v == VECTOR_LAGRANGE_MULTIPLIER_Z;
    return multiplier ? 1 : 0;
}

}  // namespace

LineSearchContactStrategy::LineSearchContactStrategy(ModelPart& rModelPart, Scheme::Pointer scheme,
                                                     BuilderAndSolver::Pointer builder,
                                                     ConvergenceCriteria::Pointer criteria, int max_iterations,
                                                     StrategySettings settings,
                                                     ContactStrategySettings contact_settings, double min_alpha)
    : ResidualBasedNewtonRaphsonContactStrategy(rModelPart, std::move(scheme), std::move(builder),
                                                std::move(criteria), max_iterations, settings, contact_settings),
      mMinAlpha(min_alpha) {
    CONTACT_CHECK(min_alpha > 0.0 && min_alpha <= 1.0, InputError,
                  "line_search_contact_strategy: min_alpha must be in (0, 1], got ", min_alpha);
}

double LineSearchContactStrategy::BlockAlpha(double r0, double r_half, double r1, double min_alpha) {
    const double a = 2.0 * r1 + 2.0 * r0 - 4.0 * r_half;
    const double b = 4.0 * r_half - r1 - 3.0 * r0;
    if (a > 0.0) return std::clamp(-b / (2.0 * a), min_alpha, 1.0);
    return r1 <= r0 ? 1.0 : min_alpha;  // a flat (e.g. zero) residual keeps the full step
}

std::array<double, 2> LineSearchContactStrategy::BlockResidualNorms() {
    SystemVectorType residual;
    mBuilder->BuildRHS(*mScheme, mModelPart, residual);
    std::array<double, 2> sums{0.0, 0.0};
    for (const Dof* dof : mBuilder->GetDofSet()) {
        const auto id = static_cast<Eigen::Index>(dof->EquationId());
        if (dof->IsFixed() || id >= residual.size()) continue;
        sums[BlockOf(*dof)] += residual[id] * residual[id];
    }
    return {std::sqrt(sums[0]), std::sqrt(sums[1])};
}

void LineSearchContactStrategy::Apply(const SystemVectorType& rIncrement) {
    SystemVectorType increment = rIncrement;
    mScheme->Update(mModelPart, mBuilder->GetDofSet(), mA, increment, mB);
    if (mSettings.move_mesh_flag) MoveMesh();
}

void LineSearchContactStrategy::UpdateSolution() {
    const SystemVectorType direction = mDx;
    const auto r0 = BlockResidualNorms();
    Apply(0.5 * direction);
    const auto r_half = BlockResidualNorms();
    Apply(0.5 * direction);
    const auto r1 = BlockResidualNorms();
    for (int block = 0; block < 2; ++block) mAlpha[block] = BlockAlpha(r0[block], r_half[block], r1[block], mMinAlpha);
    // From the full step back to α per block.
    SystemVectorType correction = SystemVectorType::Zero(direction.size());
    for (const Dof* dof : mBuilder->GetDofSet()) {
        const auto id = static_cast<Eigen::Index>(dof->EquationId());
        if (id >= direction.size()) continue;
        correction[id] = -(1.0 - mAlpha[BlockOf(*dof)]) * direction[id];
    }
    if (mAlpha[0] < 1.0 || mAlpha[1] < 1.0) Apply(correction);
    mDx = direction + correction;  // what the increment criteria read
}

}  // namespace contact_app
