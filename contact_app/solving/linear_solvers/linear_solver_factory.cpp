// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/linear_solvers/linear_solver_factory.h"

#include <algorithm>
#include <memory>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/string_utilities.h"
#include "contact_app/solving/linear_solvers/auto_direct_solver.h"
#include "contact_app/solving/linear_solvers/direct_solver.h"
#include "contact_app/solving/linear_solvers/iterative_solver.h"
#include "contact_app/solving/linear_solvers/mumps_solver.h"

namespace contact_app {

namespace {

/// solver_type spelling -> our solver. Kratos module prefixes are stripped before the lookup.
struct SolverNameRow {
    const char* name;
    const char* resolved;
};

constexpr SolverNameRow kSolverNames[] = {
    {"umfpack", "umfpack"},
    {"cholmod", "cholmod"},
    {"klu", "klu"},
    {"mumps", "mumps"},
    {"MUMPSSolver", "mumps"},
    {"sparse_lu", "sparse_lu"},
    {"eigen_sparse_lu", "sparse_lu"},
    {"skyline_lu_factorization", "direct"},
    {"SkylineLUFactorizationSolver", "direct"},
    {"skyline_lu", "direct"},
    {"super_lu", "direct"},
    {"SuperLUSolver", "direct"},
    {"Super_LU", "direct"},
    {"superlu", "direct"},
    {"pardiso_lu", "direct"},
    {"pastix", "direct"},
    {"sparse_qr", "direct"},
    {"pardiso_llt", "cholmod"},
    {"sparse_llt", "cholmod"},
    {"cholmod_llt", "cholmod"},
    {"cg", "cg"},
    {"CGSolver", "cg"},
    {"bicgstab", "bicgstab"},
    {"BICGSTABSolver", "bicgstab"},
    {"amgcl", "petsc"},
    {"AMGCL", "petsc"},
    {"AMGCLSolver", "petsc"},
    {"gmres", "petsc"},
    {"GMRESSolver", "petsc"},
    {"petsc", "petsc"},
};

std::string StripModulePrefix(const std::string& name) {
    const auto dot = name.rfind('.');
    return dot == std::string::npos ? name : name.substr(dot + 1);
}

}  // namespace

std::vector<std::string> RegisteredLinearSolverNames() {
    std::vector<std::string> names;
    for (const auto& row : kSolverNames) names.emplace_back(row.name);
    std::sort(names.begin(), names.end());
    return names;
}

std::string ResolveLinearSolverName(const std::string& solver_type) {
    // No solver_type: as in Kratos, the fastest direct solver.
    const std::string name = solver_type.empty() ? std::string("skyline_lu_factorization") : StripModulePrefix(solver_type);
    for (const auto& row : kSolverNames)
        if (name == row.name) return row.resolved;
    const auto names = RegisteredLinearSolverNames();
    CONTACT_THROW(InputError, "unknown linear solver \"", solver_type, "\"", "\n  expected: one of ", QuotedList(names),
                  DidYouMean(name, names));
}

LinearSolver::Pointer CreateLinearSolver(const LinearSolverSettings& settings) {
    const std::string resolved = ResolveLinearSolverName(settings.solver_type);
    const FillReducingOrdering ordering = ParseFillReducingOrdering(settings.ordering);
    CONTACT_CHECK(resolved == "umfpack" || resolved == "mumps" || resolved == "direct" || ordering == FillReducingOrdering::Auto, InputError,
                  "linear_solver_settings.ordering \"", settings.ordering,
                  "\" applies to UMFPACK and MUMPS only, and solver_type \"", settings.solver_type, "\" runs ", resolved,
                  "\n  fix: remove \"ordering\", or use a solver_type that maps to umfpack or mumps (\"umfpack\", "
                  "\"mumps\", \"skyline_lu_factorization\", \"super_lu\", \"pardiso_lu\", ...)");
    if (resolved == "direct") return std::make_shared<AutoDirectSolver>(ordering);
    if (resolved == "umfpack") return std::make_shared<DirectSolver>(DirectSolverKind::UmfPack, ordering);
    if (resolved == "mumps") return std::make_shared<MumpsSolver>(ordering);
    if (resolved == "cholmod") return std::make_shared<DirectSolver>(DirectSolverKind::Cholmod);
    if (resolved == "klu") return std::make_shared<DirectSolver>(DirectSolverKind::Klu);
    if (resolved == "sparse_lu") return std::make_shared<DirectSolver>(DirectSolverKind::SparseLU);
    if (resolved == "petsc") {
        KrylovSettings krylov = settings.krylov;
        krylov.tolerance = settings.tolerance;
        krylov.max_iteration = settings.max_iteration;
        return std::make_shared<PetscKrylovSolver>(krylov);
    }
    if (resolved == "cg")
        return std::make_shared<IterativeSolver>(IterativeSolverKind::ConjugateGradient, settings.tolerance,
                                                 settings.max_iteration);
    return std::make_shared<IterativeSolver>(IterativeSolverKind::BiCGStab, settings.tolerance, settings.max_iteration);
}

}  // namespace contact_app
