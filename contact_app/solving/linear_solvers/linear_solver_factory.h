// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "contact_app/solving/linear_solvers/linear_solver.h"
#include "contact_app/solving/linear_solvers/petsc_krylov_solver.h"

namespace contact_app {

/// Typed linear-solver settings (the Python layer validates the JSON and fills this).
struct LinearSolverSettings {
    /// A Kratos solver_type name ("skyline_lu_factorization", "super_lu", "sparse_lu", "amgcl", "cg", ...)
    /// or one of ours ("umfpack", "mumps", "cholmod", "klu", "sparse_lu", "cg", "bicgstab"). Empty = the
    /// default, as "skyline_lu_factorization" (UMFPACK or MUMPS by size).
    std::string solver_type;
    double tolerance = 1.0e-6;  ///< iterative solvers only
    int max_iteration = 1000;   ///< iterative solvers only
    /// Fill-reducing ordering of UMFPACK and MUMPS: "auto" (the measured best: for UMFPACK METIS for
    /// large systems, AMD for small ones), "amd" or "metis". Another solver accepts only "auto".
    std::string ordering = "auto";
    /// The amgcl keys of the PETSc Krylov solver ("amgcl", "gmres", "petsc"); its tolerance and max_iteration
    /// are the two above.
    KrylovSettings krylov;
};

/// Creates the solver a name maps to. Every Kratos LU name maps to AutoDirectSolver (UMFPACK for
/// small systems, MUMPS for large ones: all of them are LU factorisations that agree to round-off);
/// "umfpack" and "mumps" to those alone, "cholmod" to CHOLMOD, "klu" to KLU, "sparse_lu" to Eigen's
/// SparseLU; "cg" and "bicgstab" to Eigen's CG or BiCGSTAB(ILUT); "amgcl", "gmres" and "petsc" to the PETSc
/// Krylov solver with algebraic multigrid (PetscKrylovSolver; ConfigurationError naming the package when
/// PETSc is not available).
/// @throws InputError for an unknown name, listing the accepted names with a suggestion, and for an
/// unknown ordering or an ordering given to a solver other than UMFPACK or MUMPS (naming
/// linear_solver_settings.ordering).
LinearSolver::Pointer CreateLinearSolver(const LinearSolverSettings& settings);

/// Every accepted solver_type, sorted.
std::vector<std::string> RegisteredLinearSolverNames();

/// The solver a name resolves to ("direct" = UMFPACK or MUMPS by size, "umfpack", "mumps", "cholmod",
/// "klu", "sparse_lu", "cg", "bicgstab", "petsc").
/// @throws InputError for an unknown name.
std::string ResolveLinearSolverName(const std::string& solver_type);

}  // namespace contact_app
