// SPDX-License-Identifier: BSD-3-Clause
// Every linear solver on an SPD and an indefinite system; factory names; pattern reuse; failures.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/solving/linear_solvers/direct_solver.h"
#include "contact_app/solving/linear_solvers/linear_solver_factory.h"

namespace contact_app {
namespace {

/// 1D Laplacian with Dirichlet ends (SPD, condition ~ n²).
SparseMatrixType Laplacian(int n) {
    std::vector<Eigen::Triplet<double, int>> entries;
    for (int i = 0; i < n; ++i) {
        entries.emplace_back(i, i, 2.0);
        if (i > 0) entries.emplace_back(i, i - 1, -1.0);
        if (i + 1 < n) entries.emplace_back(i, i + 1, -1.0);
    }
    SparseMatrixType matrix(n, n);
    matrix.setFromTriplets(entries.begin(), entries.end());
    return matrix;
}

/// Saddle-point system [K Bᵀ; B 0] with a one-row B (indefinite, like a contact multiplier block).
SparseMatrixType SaddlePoint(int n) {
    const SparseMatrixType stiffness = Laplacian(n);
    std::vector<Eigen::Triplet<double, int>> entries;
    for (int j = 0; j < stiffness.outerSize(); ++j)
        for (SparseMatrixType::InnerIterator it(stiffness, j); it; ++it) entries.emplace_back(it.row(), it.col(), it.value());
    entries.emplace_back(n, n / 2, 1.0);
    entries.emplace_back(n / 2, n, 1.0);
    entries.emplace_back(n, n - 1, -0.5);
    entries.emplace_back(n - 1, n, -0.5);
    SparseMatrixType matrix(n + 1, n + 1);
    matrix.setFromTriplets(entries.begin(), entries.end());
    return matrix;
}

void ExpectSolves(const std::string& name, SparseMatrixType matrix, double tolerance) {
    SCOPED_TRACE(name);
    const SystemVectorType expected = SystemVectorType::LinSpaced(matrix.rows(), 1.0, 2.0);
    SystemVectorType b = matrix * expected;
    SystemVectorType x = SystemVectorType::Zero(matrix.rows());
    LinearSolverSettings settings;
    settings.solver_type = name;
    settings.tolerance = 1e-12;
    settings.max_iteration = 2000;
    CreateLinearSolver(settings)->Solve(matrix, x, b);
    EXPECT_LT((x - expected).norm() / expected.norm(), tolerance);
}

TEST(LinearSolvers, EverySolverSolvesAnSpdSystem) {
    for (const char* name : {"umfpack", "cholmod", "klu", "sparse_lu", "cg", "bicgstab"})
        ExpectSolves(name, Laplacian(60), name == std::string("cg") || name == std::string("bicgstab") ? 1e-8 : 1e-11);
}

TEST(LinearSolvers, LuAndBicgstabSolveAnIndefiniteSystem) {
    for (const char* name : {"umfpack", "klu", "sparse_lu", "bicgstab"})
        ExpectSolves(name, SaddlePoint(40), name == std::string("bicgstab") ? 1e-8 : 1e-11);
}

TEST(LinearSolvers, CholeskyRefusesAnIndefiniteSystemWithAClearError) {
    SparseMatrixType matrix = SaddlePoint(10);
    SystemVectorType b = SystemVectorType::Ones(11), x;
    DirectSolver solver(DirectSolverKind::Cholmod);
    try {
        solver.Solve(matrix, x, b);
        FAIL();
    } catch (const ConvergenceError& error) {
        EXPECT_NE(std::string(error.what()).find("not positive definite"), std::string::npos);
    }
}

TEST(LinearSolvers, SingularMatrixIsAConvergenceError) {
    SparseMatrixType matrix = Laplacian(5);
    matrix.coeffRef(0, 0) = 1.0;  // rows sum to zero: the constant vector is a null vector
    matrix.coeffRef(4, 4) = 1.0;
    SystemVectorType b = SystemVectorType::Ones(5), x;
    EXPECT_THROW(DirectSolver(DirectSolverKind::UmfPack).Solve(matrix, x, b), ConvergenceError);
}

TEST(LinearSolvers, SymbolicAnalysisIsReusedWhileThePatternIsUnchanged) {
    DirectSolver solver(DirectSolverKind::UmfPack);
    SparseMatrixType matrix = Laplacian(20);
    SystemVectorType b = SystemVectorType::Ones(20), x;
    solver.Solve(matrix, x, b);
    matrix *= 3.0;
    solver.Solve(matrix, x, b);
    EXPECT_EQ(solver.NumberOfSymbolicAnalyses(), 1u);
    EXPECT_NEAR(x[10], (Laplacian(20).toDense().inverse() * b)[10] / 3.0, 1e-10);
    SparseMatrixType other = SaddlePoint(19);
    solver.Solve(other, x, b);
    EXPECT_EQ(solver.NumberOfSymbolicAnalyses(), 2u);
}

TEST(LinearSolvers, UmfpackOrderingIsASettingAndTheStatisticsReportIt) {
    const SparseMatrixType saddle = SaddlePoint(60);
    const SystemVectorType expected = SystemVectorType::LinSpaced(saddle.rows(), 1.0, 2.0);
    for (const auto ordering : {FillReducingOrdering::Amd, FillReducingOrdering::Metis}) {
        DirectSolver solver(DirectSolverKind::UmfPack, ordering);
        SparseMatrixType matrix = saddle;
        SystemVectorType b = matrix * expected, x;
        solver.Solve(matrix, x, b);
        solver.Solve(matrix, x, b);  // refactorised on the kept analysis
        EXPECT_LT((x - expected).norm() / expected.norm(), 1e-12);
        const LinearSolverStatistics statistics = solver.Statistics();
        EXPECT_EQ(statistics.solver, "umfpack");
        EXPECT_EQ(statistics.ordering, ordering == FillReducingOrdering::Amd ? "amd" : "metis");
        EXPECT_EQ(statistics.ordering_setting, statistics.ordering);
        EXPECT_EQ(statistics.factorizations, 2u);
        EXPECT_EQ(statistics.system_size, 61u);
        EXPECT_GE(statistics.factor_nonzeros, static_cast<double>(matrix.nonZeros()));
        EXPECT_GT(statistics.factor_memory, 0.0);
        EXPECT_EQ(statistics.max_factor_memory, statistics.factor_memory);
        EXPECT_GT(statistics.factor_flops, 0.0);
    }
}

TEST(LinearSolvers, AutoOrderingIsAmdForSmallAndMetisForLargeSystems) {
    for (const int n : {100, static_cast<int>(kAutoMetisMinimumSize)}) {
        DirectSolver solver(DirectSolverKind::UmfPack);
        SparseMatrixType matrix = Laplacian(n);
        SystemVectorType b = SystemVectorType::Ones(n), x;
        solver.Solve(matrix, x, b);
        EXPECT_EQ(solver.Statistics().ordering, n < 1000 ? "amd" : "metis");
        EXPECT_EQ(solver.Statistics().ordering_setting, "auto");
    }
}

TEST(LinearSolverFactory, OrderingIsValidatedWithTheKeyNamed) {
    LinearSolverSettings settings;
    settings.ordering = "nested_dissection";
    try {
        CreateLinearSolver(settings);
        FAIL();
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("unknown linear_solver_settings.ordering \"nested_dissection\""),
                  std::string::npos);
    }
    settings.solver_type = "klu";
    settings.ordering = "metis";
    EXPECT_THROW(CreateLinearSolver(settings), InputError);
    settings.solver_type = "super_lu";
    EXPECT_EQ(CreateLinearSolver(settings)->Statistics().ordering_setting, "metis");
}

TEST(LinearSolverFactory, KratosNamesMapAndUnknownNamesSuggest) {
    EXPECT_EQ(ResolveLinearSolverName("skyline_lu_factorization"), "umfpack");
    EXPECT_EQ(ResolveLinearSolverName("SkylineLUFactorizationSolver"), "umfpack");
    EXPECT_EQ(ResolveLinearSolverName("ExternalSolversApplication.super_lu"), "umfpack");
    EXPECT_EQ(ResolveLinearSolverName("LinearSolversApplication.sparse_lu"), "sparse_lu");
    EXPECT_EQ(ResolveLinearSolverName("pardiso_lu"), "umfpack");
    EXPECT_EQ(ResolveLinearSolverName("amgcl"), "bicgstab");
    EXPECT_EQ(ResolveLinearSolverName(""), "umfpack");
    try {
        ResolveLinearSolverName("skyline_lu_factorisation");
        FAIL();
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("did you mean \"skyline_lu_factorization\""), std::string::npos);
    }
}

}  // namespace
}  // namespace contact_app
