// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "contact_app/solving/linear_solvers/direct_solver.h"
#include "contact_app/solving/linear_solvers/linear_solver.h"
#include "contact_app/solving/linear_solvers/sparsity_pattern.h"

namespace contact_app {

/// MUMPS (multifrontal LU; Debian's sequential double-precision build, libmumps-seq) on the
/// unsymmetric system (SYM = 0), centralized and assembled in coordinate format. The analysis
/// (ordering, symbolic factorisation) is redone only when the sparsity pattern changes; every Solve
/// refactorises numerically. Ordering: "metis" (the default under "auto") is METIS nested
/// dissection of the pattern of A + Aᵀ, computed through CHOLMOD and given to MUMPS
/// (ICNTL(7) = 1), because Debian's MUMPS is built without METIS; "amd" is MUMPS's AMD
/// (ICNTL(7) = 0). Why and when: docs/architecture.md, "Solving layer".
/// Out of core: when the analysis expects the factorisation to need more memory than @p out_of_core_bytes (by default
/// 70 % of the memory the system has available at that moment), MUMPS writes the factors to the temporary directory
/// (TMPDIR, else /tmp) and reads them back for the solve (ICNTL(22) = 1): slower, but the run completes where in core it
/// would exhaust the memory. Statistics().out_of_core_factorizations counts those factorisations.
class MumpsSolver : public LinearSolver {
public:
    /// @param ordering fill-reducing ordering: "auto" and "metis" give METIS, "amd" MUMPS's AMD
    /// @param workspace_percent ICNTL(14): the working space the factorisation may take beyond the analysis's estimate,
    ///        in per cent (MUMPS's default, 20). When pivoting needs more (MUMPS errors -8, -9) the factorisation is
    ///        redone with it doubled (at least +20), at most twice; Statistics().workspace_enlargements counts them.
    /// @param out_of_core_bytes factorisations expected to need at least this memory go out of core (0: all of them);
    ///        negative (the default):
    ///        kOutOfCoreShare of the memory available at each analysis (MemAvailable; never when unknown)
    /// @throws InputError if @p workspace_percent is negative
    explicit MumpsSolver(FillReducingOrdering ordering = FillReducingOrdering::Auto, int workspace_percent = 20,
                         double out_of_core_bytes = -1.0);
    /// The share of the available memory a factorisation may expect to use before it goes out of core.
    static constexpr double kOutOfCoreShare = 0.7;
    ~MumpsSolver() override;
    MumpsSolver(const MumpsSolver&) = delete;
    MumpsSolver& operator=(const MumpsSolver&) = delete;

    /// @throws ConvergenceError naming the MUMPS error code (INFOG(1)) and what it means: a singular
    /// matrix (-10), too little working space after two enlargements (-8, -9), no memory (-13).
    void Solve(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) override;
    void Clear() override;
    std::string Info() const override { return "mumps"; }
    std::size_t NumberOfSymbolicAnalyses() const override { return mAnalyses; }
    LinearSolverStatistics Statistics() const override { return mStatistics; }

private:
    struct Instance;
    void Analyse(SparseMatrixType& rA);
    void Factorise(SparseMatrixType& rA);

    FillReducingOrdering mOrdering;
    int mWorkspacePercent;
    double mOutOfCoreBytes;
    std::unique_ptr<Instance> mInstance;  // owned; created by the first Solve, freed by Clear
    SparsityPattern mPattern;             // of the last analysed matrix
    std::size_t mAnalyses = 0;
    LinearSolverStatistics mStatistics;
};

}  // namespace contact_app
