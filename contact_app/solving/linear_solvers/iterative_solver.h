// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "contact_app/solving/linear_solvers/linear_solver.h"

namespace contact_app {

/// Krylov solvers of Eigen: conjugate gradients with a diagonal preconditioner (SPD systems) and
/// BiCGSTAB with an incomplete LU (ILUT) preconditioner (general systems).
enum class IterativeSolverKind { ConjugateGradient, BiCGStab };

class IterativeSolver : public LinearSolver {
public:
    /// @param[in] kind the Krylov method and its preconditioner
    /// @param[in] tolerance relative residual ‖b − Ax‖/‖b‖ to reach
    /// @param[in] max_iterations iteration limit
    IterativeSolver(IterativeSolverKind kind, double tolerance, int max_iterations);

    /// @throws ConvergenceError with the reached residual when the tolerance is not met.
    void Solve(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) override;
    std::string Info() const override;
    /// Iterations and relative residual of the last solve.
    int LastIterations() const { return mLastIterations; }
    double LastError() const { return mLastError; }

private:
    IterativeSolverKind mKind;
    double mTolerance;
    int mMaxIterations;
    int mLastIterations = 0;
    double mLastError = 0.0;
};

}  // namespace contact_app
