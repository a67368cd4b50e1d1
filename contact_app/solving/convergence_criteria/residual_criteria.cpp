// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/convergence_criteria/residual_criteria.h"

#include <cmath>
#include <algorithm>
#include <limits>
#include <sstream>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/solving/builder_and_solvers/builder_and_solver.h"
#include "contact_app/solving/convergence_criteria/round_off_bound.h"

namespace contact_app {

ResidualCriteria::ResidualCriteria(double relative_tolerance, double absolute_tolerance)
    : mRelativeTolerance(relative_tolerance), mAbsoluteTolerance(absolute_tolerance) {
    CONTACT_CHECK(relative_tolerance >= 0.0 && absolute_tolerance >= 0.0, InputError,
                  "residual tolerances must be non-negative, got relative ", relative_tolerance, " and absolute ",
                  absolute_tolerance);
}

ResidualCriteria::Norm ResidualCriteria::ResidualNorm(const DofsArrayType& rDofSet, const SystemVectorType& rB,
                                                      const BuilderAndSolver& rBuilder,
                                                      const SystemVectorType* pDx) const {
    const auto& constrained = rBuilder.ConstrainedEquations();
    double sum = 0.0, increment = 0.0;
    Norm result;
    for (const Dof* dof : rDofSet) {
        if (dof->IsFixed()) continue;
        const std::size_t id = dof->EquationId();
        const auto row = static_cast<Eigen::Index>(id);
        if (row >= rB.size()) continue;
        if (id < constrained.size() && constrained[id]) continue;
        sum += rB[row] * rB[row];
        if (pDx && row < pDx->size()) increment += (*pDx)[row] * (*pDx)[row];
        result.state += std::pow(RoundOffBound::StateMagnitude(*dof), 2);
        ++result.count;
    }
    result.norm = std::sqrt(sum);
    result.increment = std::sqrt(increment);
    return result;
}

void ResidualCriteria::InitializeSolutionStep(ModelPart&, DofsArrayType& rDofSet, const SparseMatrixType&,
                                              const SystemVectorType&, const SystemVectorType& rB,
                                              const BuilderAndSolver& rBuilder) {
    mInitialNorm = ResidualNorm(rDofSet, rB, rBuilder, nullptr).norm;
}

void ResidualCriteria::InitializePredictedResidual(DofsArrayType& rDofSet, const SystemVectorType& rB,
                                                   const BuilderAndSolver& rBuilder) {
    mInitialNorm = std::max(mInitialNorm, ResidualNorm(rDofSet, rB, rBuilder, nullptr).norm);
}

bool ResidualCriteria::PostCriteria(ModelPart&, DofsArrayType& rDofSet, const SparseMatrixType&,
                                    const SystemVectorType& rDx, const SystemVectorType& rB,
                                    const BuilderAndSolver& rBuilder) {
    const Norm residual = ResidualNorm(rDofSet, rB, rBuilder, &rDx);
    mAtRoundOff = false;
    if (residual.count == 0) {
        mRatio = mAbsolute = 0.0;
        return true;
    }
    // Kratos reports ratio 0 when the step-start residual vanishes, which declares convergence after one
    // iteration even if the update created a residual (a prescribed displacement the geometry did not
    // see yet). Without a reference the ratio is undefined: only the absolute test can pass then.
    const double eps = std::numeric_limits<double>::epsilon();
    const double norm = residual.norm;
    if (mInitialNorm >= eps) mRatio = norm / mInitialNorm;
    else mRatio = norm < eps ? 0.0 : std::numeric_limits<double>::infinity();
    mAbsolute = norm / static_cast<double>(residual.count);
    if (mRatio <= mRelativeTolerance || mAbsolute < mAbsoluteTolerance) return true;
    mAtRoundOff = RoundOffBound::IsRoundOff(residual.increment, residual.state, norm);
    return mAtRoundOff;
}

std::string ResidualCriteria::LastNorms() const {
    std::ostringstream out;
    out.precision(3);
    out << std::scientific << "res ratio " << mRatio << " abs " << mAbsolute;
    if (mAtRoundOff) out << " (round-off)";
    return out.str();
}

}  // namespace contact_app
