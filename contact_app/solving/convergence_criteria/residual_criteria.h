// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/solving/convergence_criteria/convergence_criteria.h"

namespace contact_app {

/// ‖r‖/‖r₀‖ ≤ relative tolerance or ‖r‖/n < absolute tolerance over the free, unconstrained
/// DoFs, with r₀ the larger of the residual assembled at the start of the step (Kratos ResidualCriteria,
/// docs/theory/structural.md §6; the absolute norm divides by n, not √n, as Kratos) and the residual
/// at the predicted state, before the first correction. A residual whose correction is at round-off
/// (RoundOffBound) is converged too: neither test can be met reliably below it.
class ResidualCriteria : public ConvergenceCriteria {
public:
    ResidualCriteria(double relative_tolerance, double absolute_tolerance);

    void InitializeSolutionStep(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                                const SystemVectorType& rDx, const SystemVectorType& rB,
                                const BuilderAndSolver& rBuilder) override;
    void InitializePredictedResidual(DofsArrayType& rDofSet, const SystemVectorType& rB,
                                     const BuilderAndSolver& rBuilder) override;
    bool PostCriteria(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                      const SystemVectorType& rDx, const SystemVectorType& rB, const BuilderAndSolver& rBuilder) override;
    bool GetActualizeRHSflag() const override { return true; }
    std::string LastNorms() const override;
    std::string Info() const override { return "residual_criterion"; }
    double LastRatio() const { return mRatio; }
    double LastAbsolute() const { return mAbsolute; }
    /// Whether the last check passed at round-off only (RoundOffBound).
    bool LastAtRoundOff() const { return mAtRoundOff; }

private:
    struct Norm {
        double norm = 0.0;       ///< ‖r‖₂ over the free DoFs not touched by a constraint
        std::size_t count = 0;   ///< their number
        double increment = 0.0;  ///< ‖Δx‖₂ over them (0 without @p pDx)
        double state = 0.0;      ///< Σ z² over them (RoundOffBound)
    };
    Norm ResidualNorm(const DofsArrayType& rDofSet, const SystemVectorType& rB, const BuilderAndSolver& rBuilder,
                      const SystemVectorType* pDx) const;

    double mRelativeTolerance;
    double mAbsoluteTolerance;
    double mInitialNorm = 0.0;
    double mRatio = 0.0;
    double mAbsolute = 0.0;
    bool mAtRoundOff = false;
};

}  // namespace contact_app
