// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/convergence_criteria/displacement_criteria.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/solving/convergence_criteria/round_off_bound.h"

namespace contact_app {

DisplacementCriteria::DisplacementCriteria(double relative_tolerance, double absolute_tolerance)
    : mRelativeTolerance(relative_tolerance), mAbsoluteTolerance(absolute_tolerance) {
    CONTACT_CHECK(relative_tolerance >= 0.0 && absolute_tolerance >= 0.0, InputError,
                  "displacement tolerances must be non-negative, got relative ", relative_tolerance, " and absolute ",
                  absolute_tolerance);
}

bool DisplacementCriteria::PostCriteria(ModelPart&, DofsArrayType& rDofSet, const SparseMatrixType&,
                                        const SystemVectorType& rDx, const SystemVectorType&, const BuilderAndSolver&) {
    double increment = 0.0, reference = 0.0, magnitude = 0.0;
    std::size_t free_count = 0;
    for (const Dof* dof : rDofSet) {
        if (dof->IsFixed()) continue;
        const auto id = static_cast<Eigen::Index>(dof->EquationId());
        if (id >= rDx.size()) continue;
        increment += rDx[id] * rDx[id];
        reference += dof->GetSolutionStepValue() * dof->GetSolutionStepValue();
        magnitude += RoundOffBound::StateMagnitude(*dof) * RoundOffBound::StateMagnitude(*dof);
        ++free_count;
    }
    mAtRoundOff = false;
    if (free_count == 0) {
        mRatio = mAbsolute = 0.0;
        return true;
    }
    increment = std::sqrt(increment);
    reference = std::sqrt(reference);
    constexpr double eps = std::numeric_limits<double>::epsilon();
    if (reference < eps) reference = increment;
    mRatio = increment < eps ? 0.0 : increment / reference;
    mAbsolute = increment / std::sqrt(static_cast<double>(free_count));
    if (mRatio <= mRelativeTolerance || mAbsolute < mAbsoluteTolerance) return true;
    mAtRoundOff = RoundOffBound::IsRoundOff(increment, magnitude, 0.0);
    return mAtRoundOff;
}

std::string DisplacementCriteria::LastNorms() const {
    std::ostringstream out;
    out.precision(3);
    out << std::scientific << "dx ratio " << mRatio << " abs " << mAbsolute;
    if (mAtRoundOff) out << " (round-off)";
    return out.str();
}

}  // namespace contact_app
