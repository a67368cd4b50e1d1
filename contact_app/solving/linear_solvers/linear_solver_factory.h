// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "contact_app/solving/linear_solvers/linear_solver.h"

namespace contact_app {

/// Typed linear-solver settings (the Python layer validates the JSON and fills this).
struct LinearSolverSettings {
    /// A Kratos solver_type name ("skyline_lu_factorization", "super_lu", "sparse_lu", "amgcl", "cg", ...)
    /// or one of ours ("umfpack", "cholmod", "klu", "sparse_lu", "cg", "bicgstab"). Empty = the default (umfpack).
    std::string solver_type;
    double tolerance = 1.0e-6;  ///< iterative solvers only
    int max_iteration = 1000;   ///< iterative solvers only
    /// Fill-reducing ordering of UMFPACK: "auto" (METIS for large systems, AMD for small ones), "amd"
    /// or "metis". Another solver accepts only "auto".
    std::string ordering = "auto";
};

/// Creates the solver a name maps to. Every Kratos direct name maps to UMFPACK (all of them are
/// LU factorisations that agree to round-off); "cholmod" to CHOLMOD, "klu" to KLU, "sparse_lu"
/// to Eigen's SparseLU; the iterative names to CG or BiCGSTAB(ILUT).
/// @throws InputError for an unknown name, listing the accepted names with a suggestion, and for an
/// unknown ordering or an ordering given to a solver other than UMFPACK (naming linear_solver_settings.ordering).
LinearSolver::Pointer CreateLinearSolver(const LinearSolverSettings& settings);

/// Every accepted solver_type, sorted.
std::vector<std::string> RegisteredLinearSolverNames();

/// The solver a name resolves to ("umfpack", "cholmod", "klu", "sparse_lu", "cg", "bicgstab").
/// @throws InputError for an unknown name.
std::string ResolveLinearSolverName(const std::string& solver_type);

}  // namespace contact_app
