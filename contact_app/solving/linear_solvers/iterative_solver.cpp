// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/linear_solvers/iterative_solver.h"

#include <Eigen/IterativeLinearSolvers>

#include "contact_app/kernel/exceptions.h"

namespace contact_app {

IterativeSolver::IterativeSolver(IterativeSolverKind kind, double tolerance, int max_iterations)
    : mKind(kind), mTolerance(tolerance), mMaxIterations(max_iterations) {
    CONTACT_CHECK(tolerance > 0.0 && max_iterations > 0, InputError, Info(),
                  ": tolerance must be positive and max_iteration at least 1, got ", tolerance, " and ",
                  max_iterations);
}

std::string IterativeSolver::Info() const {
    return mKind == IterativeSolverKind::ConjugateGradient ? "cg" : "bicgstab";
}

namespace {
template <class TSolver>
void RunKrylov(TSolver& solver, const SparseMatrixType& rA, SystemVectorType& rX, const SystemVectorType& rB,
               double tolerance, int max_iterations, int& iterations, double& error) {
    solver.setTolerance(tolerance);
    solver.setMaxIterations(max_iterations);
    solver.compute(rA);
    const SystemVectorType guess = rX.size() == rB.size() ? rX : SystemVectorType::Zero(rB.size());
    rX = solver.solveWithGuess(rB, guess);
    iterations = static_cast<int>(solver.iterations());
    error = solver.error();
}
}  // namespace

void IterativeSolver::Solve(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) {
    if (rA.rows() == 0) {
        rX.resize(0);
        return;
    }
    if (mKind == IterativeSolverKind::ConjugateGradient) {
        Eigen::ConjugateGradient<SparseMatrixType, Eigen::Lower | Eigen::Upper> solver;
        RunKrylov(solver, rA, rX, rB, mTolerance, mMaxIterations, mLastIterations, mLastError);
    } else {
        Eigen::BiCGSTAB<SparseMatrixType, Eigen::IncompleteLUT<double, int>> solver;
        RunKrylov(solver, rA, rX, rB, mTolerance, mMaxIterations, mLastIterations, mLastError);
    }
    CONTACT_CHECK(mLastError <= mTolerance && rX.allFinite(), ConvergenceError, Info(), ": no convergence after ",
                  mLastIterations, " iterations (relative residual ", mLastError, ", tolerance ", mTolerance, ")",
                  "\n  fix: raise max_iteration, or use a direct solver (\"umfpack\") for indefinite contact systems");
}

}  // namespace contact_app
