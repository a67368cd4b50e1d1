// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/solving/convergence_criteria/convergence_criteria.h"

namespace contact_app {

/// ‖Δx_free‖/‖x_free‖ ≤ relative tolerance or ‖Δx_free‖/√n_free < absolute tolerance
/// (Kratos DisplacementCriteria, docs/theory/structural.md §6), or an increment at round-off:
/// ‖Δx_free‖ below the RoundOffBound floor of the state it corrects.
class DisplacementCriteria : public ConvergenceCriteria {
public:
    DisplacementCriteria(double relative_tolerance, double absolute_tolerance);

    bool PostCriteria(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                      const SystemVectorType& rDx, const SystemVectorType& rB, const BuilderAndSolver& rBuilder) override;
    std::string LastNorms() const override;
    std::string Info() const override { return "displacement_criterion"; }
    double LastRatio() const { return mRatio; }
    double LastAbsolute() const { return mAbsolute; }
    /// Whether the last check passed at round-off only.
    bool LastAtRoundOff() const { return mAtRoundOff; }

private:
    double mRelativeTolerance;
    double mAbsoluteTolerance;
    double mRatio = 0.0;
    double mAbsolute = 0.0;
    bool mAtRoundOff = false;
};

}  // namespace contact_app
