// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>

#include "contact_app/kernel/model_part.h"
#include "contact_app/solving/schemes/scheme.h"
#include "contact_app/solving/system_types.h"

namespace contact_app {

class BuilderAndSolver;

/// Decides when a Newton loop has converged (Kratos ConvergenceCriteria). PostCriteria runs
/// after each update; criteria that need the residual at the updated state say so with
/// GetActualizeRHSflag() and receive it rebuilt in @p rB.
class ConvergenceCriteria {
public:
    using Pointer = std::shared_ptr<ConvergenceCriteria>;

    virtual ~ConvergenceCriteria() = default;

    virtual void Initialize(ModelPart& rModelPart) { mInitialized = true; }
    /// Called once per step after the step's RHS was assembled (residual reference).
    virtual void InitializeSolutionStep(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                                        const SystemVectorType& rDx, const SystemVectorType& rB,
                                        const BuilderAndSolver& rBuilder);
    /// Called once per Newton loop after the first build, with @p rB the residual at the predicted state (before
    /// the first correction). Residual criteria measure their ratio against the larger of this and the step-start
    /// residual: a prescribed displacement or a predictor moves the state after the step-start residual was taken.
    virtual void InitializePredictedResidual(DofsArrayType& rDofSet, const SystemVectorType& rB,
                                             const BuilderAndSolver& rBuilder) {}
    virtual void FinalizeSolutionStep(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                                      const SystemVectorType& rDx, const SystemVectorType& rB) {}
    virtual bool PreCriteria(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                             const SystemVectorType& rDx, const SystemVectorType& rB) {
        return true;
    }
    /// @brief Convergence test after the solution update of one Newton iteration.
    /// @param[in,out] rModelPart the model part being solved (contact criteria update nodal flags and results on it)
    /// @param[in] rDofSet the system DoFs (not owned), in the builder's order
    /// @param[in] rA the system matrix of the iteration
    /// @param[in] rDx the solution increment of the iteration, one entry per equation
    /// @param[in] rB the rebuilt RHS when GetActualizeRHSflag() is true, else the RHS the iteration solved with
    /// @param[in] rBuilder the builder and solver of the system (equation numbering, Dirichlet and constraint rows)
    /// @return true when converged
    virtual bool PostCriteria(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                              const SystemVectorType& rDx, const SystemVectorType& rB,
                              const BuilderAndSolver& rBuilder) = 0;
    virtual bool GetActualizeRHSflag() const { return false; }
    bool IsInitialized() const { return mInitialized; }
    void SetEchoLevel(int level) { mEchoLevel = level; }
    int GetEchoLevel() const { return mEchoLevel; }
    /// One line with the last ratio and absolute norm(s), for the console table.
    virtual std::string LastNorms() const = 0;
    virtual std::string Info() const = 0;

protected:
    int mEchoLevel = 0;
    bool mInitialized = false;
};

}  // namespace contact_app
