// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <string>

#include "contact_app/solving/linear_solvers/direct_solver.h"
#include "contact_app/solving/linear_solvers/linear_solver.h"
#include "contact_app/solving/linear_solvers/mumps_solver.h"

namespace contact_app {

/// Systems with at least this many equations go to MUMPS under the Kratos direct-solver names
/// (docs/architecture.md has the measured crossover on the Hertz examples).
inline constexpr std::size_t kAutoMumpsMinimumSize = 20000;

/// The direct solver of the Kratos direct solver_type names (skyline_lu_factorization, super_lu,
/// pardiso_lu, ...), like Kratos' "fastest available direct solver": UMFPACK below
/// kAutoMumpsMinimumSize equations, MUMPS from it. Each keeps its own analysis; the statistics name
/// the solver that ran.
class AutoDirectSolver : public LinearSolver {
public:
    explicit AutoDirectSolver(FillReducingOrdering ordering = FillReducingOrdering::Auto);

    /// @throws ConvergenceError from the solver that ran.
    void Solve(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) override;
    void Clear() override;
    /// The solver of the last Solve ("umfpack" or "mumps"); "direct" before the first.
    std::string Info() const override;
    std::size_t NumberOfSymbolicAnalyses() const override;
    /// The last solver's figures; counts, times and maxima over both; solver "umfpack and mumps"
    /// once both have run.
    LinearSolverStatistics Statistics() const override;

private:
    DirectSolver mUmfpack;
    MumpsSolver mMumps;
    const LinearSolver* mLast = nullptr;  // points to mUmfpack or mMumps
};

}  // namespace contact_app
