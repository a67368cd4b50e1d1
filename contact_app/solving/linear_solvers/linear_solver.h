// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "contact_app/solving/linear_solvers/unknown_layout.h"
#include "contact_app/solving/system_types.h"

namespace contact_app {

class Dof;
class ModelPart;

/// What a solver reports about its work so far (the run summary and the step log print it).
/// Figures a solver does not know stay 0 / empty.
struct LinearSolverStatistics {
    std::string solver;           ///< Info() of the solver that ran
    std::string ordering;         ///< fill-reducing ordering of the last factorisation ("metis", "amd", ...)
    std::string ordering_setting; ///< what was asked for ("auto", "amd", "metis"); empty = no such setting
    std::size_t factorizations = 0;  ///< numeric factorisations (one per Solve of a direct solver)
    std::size_t system_size = 0;     ///< rows of the last system
    double factor_nonzeros = 0.0;    ///< nnz(L) + nnz(U) of the last factorisation
    double max_factor_nonzeros = 0.0;
    double factor_memory = 0.0;      ///< bytes: peak memory of the last symbolic + numeric factorisation
    double max_factor_memory = 0.0;
    double factor_flops = 0.0;       ///< floating-point operations of all numeric factorisations
    double symbolic_seconds = 0.0;   ///< CPU time of all symbolic analyses (ordering included)
    double numeric_seconds = 0.0;    ///< CPU time of all numeric factorisations
    std::size_t workspace_enlargements = 0;  ///< MUMPS: factorisations redone with more working space (ICNTL(14))
    std::size_t out_of_core_factorizations = 0;  ///< MUMPS: factorisations whose factors went to disk (ICNTL(22))
    // Static condensation (StaticCondensationSolver; docs/theory/static_condensation.md):
    std::string condensation;          ///< "" = not a condensing solver; "yes", or "no (why)"
    std::size_t interface_size = 0;    ///< n_I of the last condensed solve
    std::size_t bulk_size = 0;         ///< n_B of the last condensed solve
    std::size_t bulk_factorizations = 0;
    std::size_t condensed_solves = 0;
    double bulk_seconds = 0.0;       ///< wall time of all bulk factorisations and Schur products
    double interface_seconds = 0.0;  ///< wall time of all condensed solves (interface LU, bulk back-solves)
    // Krylov solvers (PetscKrylovSolver; docs/running.md, "Iterative solver (PETSc)"):
    bool krylov = false;                   ///< an iterative solver: the step table shows its iterations
    std::string krylov_method;             ///< "gmres + gamg, 4 levels" of the last solve
    std::vector<int> krylov_iterations;    ///< iterations of every solve of the run, in order
    double last_relative_residual = 0.0;   ///< ‖b − Ax‖/‖b‖ of the last solve
    double tolerance = 0.0;
    double preconditioner_seconds = 0.0;   ///< wall time of all matrix distributions and preconditioner set-ups
    std::size_t preconditioner_setups = 0; ///< solves whose preconditioner was set up (the others reused one)
    double krylov_seconds = 0.0;           ///< wall time of all Krylov iterations
    int ranks = 0;                         ///< MPI ranks of the last solve (0 = not an MPI solver)
    std::size_t near_null_space = 0;       ///< near-null-space vectors given to the AMG (rigid-body modes)
};

/// Solves A x = b for the global system (Kratos LinearSolver). Direct solvers keep their
/// symbolic factorisation while the sparsity pattern of A is unchanged.
class LinearSolver {
public:
    using Pointer = std::shared_ptr<LinearSolver>;

    virtual ~LinearSolver() = default;
    /// @param[in] rA square system matrix @param[in,out] rX initial guess (iterative) / solution
    /// @param[in] rB right-hand side. @throws ConvergenceError if the solve fails (singular matrix,
    /// iteration limit), naming the solver and the reason.
    virtual void Solve(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) = 0;
    /// Forgets cached factorisations (the next Solve analyses the pattern again).
    virtual void Clear() {}
    /// The solver's own name, e.g. "umfpack".
    virtual std::string Info() const = 0;
    /// Number of symbolic analyses performed so far (a pattern-reuse diagnostic).
    virtual std::size_t NumberOfSymbolicAnalyses() const { return 0; }
    /// The solver's figures so far (name, ordering, fill, memory).
    virtual LinearSolverStatistics Statistics() const {
        LinearSolverStatistics statistics;
        statistics.solver = Info();
        return statistics;
    }
    /// True when Solve needs to know which DoF each equation is (condensing solvers).
    virtual bool AdditionalPhysicalDataIsNeeded() const { return false; }
    /// The DoF set (equation id = position in the system) and the model part of the next Solve.
    virtual void ProvideAdditionalData(const std::vector<Dof*>& rDofSet, ModelPart& rModelPart) {}
    /// True when Solve needs the node and component of each unknown (the rigid-body modes of an AMG).
    /// A solver that hands a reduced system to an inner one (MixedULMLinearSolver) passes the reduced layout.
    virtual bool UnknownLayoutIsNeeded() const { return false; }
    /// The layout of the next Solve's unknowns (overrides what ProvideAdditionalData gave).
    virtual void ProvideUnknownLayout(UnknownLayout layout) {}
};

}  // namespace contact_app
