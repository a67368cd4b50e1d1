// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/linear_solvers/auto_direct_solver.h"

#include <algorithm>

namespace contact_app {

AutoDirectSolver::AutoDirectSolver(FillReducingOrdering ordering)
    : mUmfpack(DirectSolverKind::UmfPack, ordering), mMumps(ordering) {}

void AutoDirectSolver::Solve(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) {
    const bool large = static_cast<std::size_t>(rA.rows()) >= kAutoMumpsMinimumSize;
    LinearSolver& solver = large ? static_cast<LinearSolver&>(mMumps) : static_cast<LinearSolver&>(mUmfpack);
    mLast = &solver;
    solver.Solve(rA, rX, rB);
}

void AutoDirectSolver::Clear() {
    mUmfpack.Clear();
    mMumps.Clear();
}

std::string AutoDirectSolver::Info() const { return mLast != nullptr ? mLast->Info() : "direct"; }

std::size_t AutoDirectSolver::NumberOfSymbolicAnalyses() const {
    return mUmfpack.NumberOfSymbolicAnalyses() + mMumps.NumberOfSymbolicAnalyses();
}

LinearSolverStatistics AutoDirectSolver::Statistics() const {
    if (mLast == nullptr) {
        LinearSolverStatistics statistics = mUmfpack.Statistics();
        statistics.solver = Info();
        return statistics;
    }
    const LinearSolverStatistics umfpack = mUmfpack.Statistics();
    const LinearSolverStatistics mumps = mMumps.Statistics();
    LinearSolverStatistics statistics = mLast->Statistics();
    if (umfpack.factorizations == 0 || mumps.factorizations == 0) return statistics;
    statistics.solver = "umfpack and mumps";
    statistics.factorizations = umfpack.factorizations + mumps.factorizations;
    statistics.max_factor_nonzeros = std::max(umfpack.max_factor_nonzeros, mumps.max_factor_nonzeros);
    statistics.max_factor_memory = std::max(umfpack.max_factor_memory, mumps.max_factor_memory);
    statistics.factor_flops = umfpack.factor_flops + mumps.factor_flops;
    statistics.symbolic_seconds = umfpack.symbolic_seconds + mumps.symbolic_seconds;
    statistics.numeric_seconds = umfpack.numeric_seconds + mumps.numeric_seconds;
    statistics.workspace_enlargements = mumps.workspace_enlargements;
    return statistics;
}

}  // namespace contact_app
