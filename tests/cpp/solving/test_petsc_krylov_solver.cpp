// SPDX-License-Identifier: BSD-3-Clause
// The PETSc Krylov + AMG solver (solver_type "amgcl" / "gmres"): a nodal 3-component system with its rigid-body
// near-null space, the mapping of the amgcl keys, the preconditioner kept or set up again
// (reform_preconditioner_at_each_step), a not-converged solve. Skipped, naming the package, when this
// build has no PETSc.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <vector>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/solving/linear_solvers/linear_solver_factory.h"
#include "contact_app/solving/linear_solvers/petsc_krylov_solver.h"
#include "tests/cpp/error_test_utilities.h"

namespace contact_app {
namespace {

using testing::ExpectError;

#define SKIP_WITHOUT_PETSC()                                                   \
    do {                                                                       \
        const std::string reason = PetscUnavailableReason();                   \
        if (!reason.empty()) GTEST_SKIP() << "no PETSc solver: " << reason;    \
    } while (0)

/// Three uncoupled 3D grid Laplacians (7-point, Dirichlet outside) interleaved by node, and their layout.
struct NodalSystem {
    SparseMatrixType matrix;
    UnknownLayout layout;
};

NodalSystem GridSystem(int n) {
    const int nodes = n * n * n;
    std::vector<Eigen::Triplet<double, int>> entries;
    NodalSystem system;
    system.layout.dimension = 3;
    auto id = [n](int i, int j, int k) { return (i * n + j) * n + k; };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                const int node = id(i, j, k);
                for (int c = 0; c < 3; ++c) {
                    const int row = 3 * node + c;
                    entries.emplace_back(row, row, 6.0);
                    const int neighbours[6][3] = {{i - 1, j, k}, {i + 1, j, k}, {i, j - 1, k},
                                                  {i, j + 1, k}, {i, j, k - 1}, {i, j, k + 1}};
                    for (const auto& m : neighbours)
                        if (m[0] >= 0 && m[0] < n && m[1] >= 0 && m[1] < n && m[2] >= 0 && m[2] < n)
                            entries.emplace_back(row, 3 * id(m[0], m[1], m[2]) + c, -1.0);
                    system.layout.node.push_back(node + 1);
                    system.layout.component.push_back(c);
                    system.layout.coordinates.push_back({double(i), double(j), double(k)});
                }
            }
    system.matrix.resize(3 * nodes, 3 * nodes);
    system.matrix.setFromTriplets(entries.begin(), entries.end());
    system.matrix.makeCompressed();
    return system;
}

TEST(PetscKrylovSolver, AmgclSolvesANodalSystemWithTheRigidBodyModes) {
    SKIP_WITHOUT_PETSC();
    NodalSystem system = GridSystem(12);
    const SystemVectorType expected = SystemVectorType::LinSpaced(system.matrix.rows(), 1.0, 2.0);
    SystemVectorType b = system.matrix * expected;
    SystemVectorType x;
    LinearSolverSettings settings;
    settings.solver_type = "amgcl";
    settings.tolerance = 1e-10;
    auto solver = CreateLinearSolver(settings);
    ASSERT_EQ(solver->Info(), "petsc");
    ASSERT_TRUE(solver->UnknownLayoutIsNeeded());
    solver->ProvideUnknownLayout(system.layout);
    solver->Solve(system.matrix, x, b);
    EXPECT_LT((x - expected).norm() / expected.norm(), 1e-8);
    const LinearSolverStatistics statistics = solver->Statistics();
    EXPECT_TRUE(statistics.krylov);
    ASSERT_EQ(statistics.krylov_iterations.size(), 1u);
    EXPECT_GT(statistics.krylov_iterations[0], 0);
    EXPECT_LT(statistics.krylov_iterations[0], 60);
    EXPECT_EQ(statistics.near_null_space, 6u);
    EXPECT_LE(statistics.last_relative_residual, 1e-10);
    EXPECT_NE(statistics.krylov_method.find("gmres + gamg"), std::string::npos) << statistics.krylov_method;
}

TEST(PetscKrylovSolver, EveryKrylovAndSmootherChoiceSolves) {
    SKIP_WITHOUT_PETSC();
    NodalSystem system = GridSystem(6);
    const SystemVectorType expected = SystemVectorType::LinSpaced(system.matrix.rows(), -1.0, 3.0);
    for (const char* krylov : {"gmres", "fgmres", "lgmres", "cg", "bicgstab", "bicgstabl"})
        for (const char* smoother : {"gauss_seidel", "chebyshev", "damped_jacobi", "ilu0"})
            for (const char* coarsening : {"smoothed_aggregation", "aggregation", "ruge_stuben"}) {
                SCOPED_TRACE(std::string(krylov) + " " + smoother + " " + coarsening);
                LinearSolverSettings settings;
                settings.solver_type = "gmres";
                settings.tolerance = 1e-9;
                settings.krylov.krylov_type = krylov;
                settings.krylov.smoother_type = smoother;
                settings.krylov.coarsening_type = coarsening;
                auto solver = CreateLinearSolver(settings);
                solver->ProvideUnknownLayout(system.layout);
                SystemVectorType b = system.matrix * expected, x;
                try {
                    solver->Solve(system.matrix, x, b);
                } catch (const std::exception& error) {
                    ADD_FAILURE() << error.what();
                    continue;
                }
                EXPECT_LT((x - expected).norm() / expected.norm(), 1e-7);
            }
}

/// The grid system with the values of a later Newton iteration: same pattern, the diagonal of every
/// third node stiffened by @p factor.
SparseMatrixType Stiffened(const SparseMatrixType& matrix, double factor) {
    SparseMatrixType changed = matrix;
    for (int row = 0; row < changed.rows(); row += 9) changed.coeffRef(row, row) *= factor;
    return changed;
}

/// Solves A x = A x* with @p solver; the error of x against x*.
double SolveError(LinearSolver& solver, const UnknownLayout& layout, SparseMatrixType& matrix) {
    const SystemVectorType expected = SystemVectorType::LinSpaced(matrix.rows(), 1.0, 2.0);
    SystemVectorType b = matrix * expected, x;
    solver.ProvideUnknownLayout(layout);
    solver.Solve(matrix, x, b);
    return (x - expected).norm() / expected.norm();
}

/// A GMRES + GAMG solver ("amgcl").
LinearSolver::Pointer AmgclSolver(bool reform, double tolerance = 1e-10, int max_iteration = 1000) {
    LinearSolverSettings settings;
    settings.solver_type = "amgcl";
    settings.tolerance = tolerance;
    settings.max_iteration = max_iteration;
    settings.krylov.reform_preconditioner_at_each_step = reform;
    return CreateLinearSolver(settings);
}

/// Solves the grid system stiffened by each factor in turn (one pattern), each to 1e-8.
void SolveStiffened(LinearSolver& solver, const NodalSystem& system, std::initializer_list<double> factors) {
    for (const double factor : factors) {
        SparseMatrixType matrix = Stiffened(system.matrix, factor);
        EXPECT_LT(SolveError(solver, system.layout, matrix), 1e-8) << factor;
    }
}

TEST(PetscKrylovSolver, WithoutReformThePreconditionerIsSetUpOncePerPattern) {
    SKIP_WITHOUT_PETSC();
    NodalSystem system = GridSystem(10);
    auto solver = AmgclSolver(false);
    SolveStiffened(*solver, system, {1.0, 1.5, 3.0, 0.7});
    LinearSolverStatistics statistics = solver->Statistics();
    ASSERT_EQ(statistics.krylov_iterations.size(), 4u);
    EXPECT_EQ(statistics.preconditioner_setups, 1u);
    EXPECT_LE(statistics.last_relative_residual, 1e-10);
    // One more entry in each of two rows (a contact pair found): a new pattern, a new set-up.
    SparseMatrixType coupled = system.matrix;
    const auto last = static_cast<int>(coupled.rows()) - 1;
    coupled.coeffRef(0, last) = -0.5;
    coupled.coeffRef(last, 0) = -0.5;
    coupled.makeCompressed();
    EXPECT_LT(SolveError(*solver, system.layout, coupled), 1e-8);
    EXPECT_EQ(solver->Statistics().preconditioner_setups, 2u);
    EXPECT_LT(SolveError(*solver, system.layout, coupled), 1e-8);
    EXPECT_EQ(solver->Statistics().preconditioner_setups, 2u);
    // Another size.
    NodalSystem smaller = GridSystem(7);
    EXPECT_LT(SolveError(*solver, smaller.layout, smaller.matrix), 1e-8);
    statistics = solver->Statistics();
    EXPECT_EQ(statistics.preconditioner_setups, 3u);
    EXPECT_EQ(statistics.krylov_iterations.size(), 7u);
}

TEST(PetscKrylovSolver, ByDefaultThePreconditionerIsSetUpAtEverySolve) {
    SKIP_WITHOUT_PETSC();
    NodalSystem system = GridSystem(8);
    auto solver = AmgclSolver(true);
    SolveStiffened(*solver, system, {1.0, 2.0, 4.0});
    EXPECT_EQ(solver->Statistics().preconditioner_setups, 3u);
}

TEST(PetscKrylovSolver, WhatWasKeptAndFailsIsSetUpAnew) {
    SKIP_WITHOUT_PETSC();
    // First values: the diagonal alone (entries of the pattern left zero), whose AMG is no help on the full
    // Laplacian. The solve with what was kept (the whole preconditioner without reform, GAMG's prolongators
    // with it) stops at max_iteration; the retry after a complete set-up converges (else ConvergenceError).
    NodalSystem system = GridSystem(14);
    SparseMatrixType diagonal = system.matrix;
    for (int col = 0; col < diagonal.outerSize(); ++col)
        for (SparseMatrixType::InnerIterator it(diagonal, col); it; ++it)
            if (it.row() != it.col()) it.valueRef() = 0.0;
    for (const bool reform : {false, true}) {
        SCOPED_TRACE(reform ? "reform" : "no reform");
        auto solver = AmgclSolver(reform, 1e-8, 10);  // a fresh set-up needs 7 iterations, the kept prolongators 12
        EXPECT_LT(SolveError(*solver, system.layout, diagonal), 1e-6);
        EXPECT_LT(SolveError(*solver, system.layout, system.matrix), 1e-6);
        const LinearSolverStatistics statistics = solver->Statistics();
        EXPECT_EQ(statistics.preconditioner_setups, 2u);
        EXPECT_LT(statistics.krylov_iterations.back(), 10);
    }
}

TEST(PetscKrylovSolver, UnknownSettingsNameTheKey) {
    // No PETSc needed: the settings are checked before the plugin is loaded.
    KrylovSettings settings;
    settings.smoother_type = "gauss_seidl";
    ExpectError<InputError>([&] { PetscOptionsFromSettings(settings); },
                            {"linear_solver_settings.smoother_type \"gauss_seidl\"", "did you mean \"gauss_seidel\""});
    settings = {};
    settings.krylov_type = "idrs";
    EXPECT_THROW(PetscOptionsFromSettings(settings), InputError);
    settings = {};
    settings.preconditioner_type = "relaxation";
    settings.smoother_type = "ilu0";
    EXPECT_EQ(std::string(PetscOptionsFromSettings(settings).preconditioner), "bjacobi");
    settings = {};
    settings.coarsening_type = "ruge_stuben";
    EXPECT_EQ(std::string(PetscOptionsFromSettings(settings).preconditioner), "hypre");
    settings = {};
    settings.pre_sweeps = 2;
    settings.post_sweeps = 3;
    settings.gmres_krylov_space_dimension = 30;
    const auto options = PetscOptionsFromSettings(settings);
    EXPECT_EQ(options.smoothing_steps, 3);
    EXPECT_EQ(options.restart, 30);
    EXPECT_EQ(std::string(options.krylov), "fgmres");  // GMRES in its flexible form (docs/running.md)
    EXPECT_EQ(std::string(options.smoother), "sor");
}

TEST(PetscKrylovSolver, NotConvergedSaysWhatToChange) {
    SKIP_WITHOUT_PETSC();
    NodalSystem system = GridSystem(8);
    SystemVectorType b = SystemVectorType::Ones(system.matrix.rows()), x;
    LinearSolverSettings settings;
    settings.solver_type = "amgcl";
    settings.tolerance = 1e-12;
    settings.max_iteration = 2;
    auto solver = CreateLinearSolver(settings);
    ExpectError<ConvergenceError>([&] { solver->Solve(system.matrix, x, b); },
                                  {"no convergence", "after 2 iterations", "relative residual",
                                   "raise linear_solver_settings.max_iteration (now 2)"});
}

}  // namespace
}  // namespace contact_app
