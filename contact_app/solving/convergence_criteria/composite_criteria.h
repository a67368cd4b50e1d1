// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/solving/convergence_criteria/convergence_criteria.h"

namespace contact_app {

/// Two criteria evaluated together (Kratos AndCriteria / OrCriteria): both are always evaluated
/// (so both report norms) and their results are combined with AND or OR.
class CompositeCriteria : public ConvergenceCriteria {
public:
    enum class Mode { And, Or };

    /// @param[in] mode how the two results combine: both converged (And) or either (Or)
    /// @param[in] first,second the two criteria, shared with the caller (not null)
    CompositeCriteria(Mode mode, ConvergenceCriteria::Pointer first, ConvergenceCriteria::Pointer second);

    void Initialize(ModelPart& rModelPart) override;
    void InitializeSolutionStep(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                                const SystemVectorType& rDx, const SystemVectorType& rB,
                                const BuilderAndSolver& rBuilder) override;
    void InitializePredictedResidual(DofsArrayType& rDofSet, const SystemVectorType& rB,
                                     const BuilderAndSolver& rBuilder) override;
    void FinalizeSolutionStep(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                              const SystemVectorType& rDx, const SystemVectorType& rB) override;
    bool PreCriteria(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                     const SystemVectorType& rDx, const SystemVectorType& rB) override;
    bool PostCriteria(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                      const SystemVectorType& rDx, const SystemVectorType& rB, const BuilderAndSolver& rBuilder) override;
    bool GetActualizeRHSflag() const override;
    std::string LastNorms() const override;
    std::string Info() const override { return mMode == Mode::And ? "and_criterion" : "or_criterion"; }

private:
    bool Combine(bool a, bool b) const { return mMode == Mode::And ? (a && b) : (a || b); }

    Mode mMode;
    ConvergenceCriteria::Pointer mFirst;
    ConvergenceCriteria::Pointer mSecond;
};

}  // namespace contact_app
