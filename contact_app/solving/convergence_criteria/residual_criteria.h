// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/solving/convergence_criteria/convergence_criteria.h"

namespace contact_app {

/// ‖r‖/‖r₀‖ ≤ relative tolerance or ‖r‖/n < absolute tolerance over the free, unconstrained
/// DoFs, with r₀ the residual assembled at the start of the step (Kratos ResidualCriteria,
/// ../shared/spec/kratos_structural.md §6.2; the absolute norm divides by n, not √n, as Kratos).
class ResidualCriteria : public ConvergenceCriteria {
public:
    ResidualCriteria(double relative_tolerance, double absolute_tolerance);

    void InitializeSolutionStep(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                                const SystemVectorType& rDx, const SystemVectorType& rB,
                                const BuilderAndSolver& rBuilder) override;
    bool PostCriteria(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                      const SystemVectorType& rDx, const SystemVectorType& rB, const BuilderAndSolver& rBuilder) override;
    bool GetActualizeRHSflag() const override { return true; }
    std::string LastNorms() const override;
    std::string Info() const override { return "residual_criterion"; }
    double LastRatio() const { return mRatio; }
    double LastAbsolute() const { return mAbsolute; }

private:
    /// ‖r‖₂ over free DoFs not touched by a constraint, and their count.
    std::pair<double, std::size_t> ResidualNorm(const DofsArrayType& rDofSet, const SystemVectorType& rB,
                                                const BuilderAndSolver& rBuilder) const;

    double mRelativeTolerance;
    double mAbsoluteTolerance;
    double mInitialNorm = 0.0;
    double mRatio = 0.0;
    double mAbsolute = 0.0;
};

}  // namespace contact_app
