// SPDX-License-Identifier: BSD-3-Clause
// Every linear solver on an SPD and an indefinite system; factory names; pattern reuse; failures.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/solving/linear_solvers/direct_solver.h"
#include "contact_app/solving/linear_solvers/linear_solver_factory.h"
#include "tests/cpp/error_test_utilities.h"
#include "tests/cpp/solving/linear_solver_test_utilities.h"

namespace contact_app {
namespace {

using testing::ExpectError;
using testing::Laplacian;
using testing::SaddlePoint;

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
    for (const char* name : {"umfpack", "mumps", "cholmod", "klu", "sparse_lu", "cg", "bicgstab"})
        ExpectSolves(name, Laplacian(60), name == std::string("cg") || name == std::string("bicgstab") ? 1e-8 : 1e-11);
}

TEST(LinearSolvers, LuAndBicgstabSolveAnIndefiniteSystem) {
    for (const char* name : {"umfpack", "mumps", "klu", "sparse_lu", "bicgstab"})
        ExpectSolves(name, SaddlePoint(40), name == std::string("bicgstab") ? 1e-8 : 1e-11);
}

TEST(LinearSolvers, CholeskyRefusesAnIndefiniteSystemWithAClearError) {
    SparseMatrixType matrix = SaddlePoint(10);
    SystemVectorType b = SystemVectorType::Ones(11), x;
    DirectSolver solver(DirectSolverKind::Cholmod);
    ExpectError<ConvergenceError>([&] { solver.Solve(matrix, x, b); }, {"not positive definite"});
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
        testing::ExpectFactorStatistics(statistics, "umfpack", ordering == FillReducingOrdering::Amd ? "amd" : "metis", 2,
                                        matrix);
        EXPECT_EQ(statistics.ordering_setting, statistics.ordering);
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
    ExpectError<InputError>([&] { CreateLinearSolver(settings); },
                            {"unknown linear_solver_settings.ordering \"nested_dissection\""});
    settings.solver_type = "klu";
    settings.ordering = "metis";
    EXPECT_THROW(CreateLinearSolver(settings), InputError);
    settings.solver_type = "super_lu";
    EXPECT_EQ(CreateLinearSolver(settings)->Statistics().ordering_setting, "metis");
}

TEST(LinearSolverFactory, KratosNamesMapAndUnknownNamesSuggest) {
    EXPECT_EQ(ResolveLinearSolverName("skyline_lu_factorization"), "direct");
    EXPECT_EQ(ResolveLinearSolverName("SkylineLUFactorizationSolver"), "direct");
    EXPECT_EQ(ResolveLinearSolverName("ExternalSolversApplication.super_lu"), "direct");
    EXPECT_EQ(ResolveLinearSolverName("LinearSolversApplication.sparse_lu"), "sparse_lu");
    EXPECT_EQ(ResolveLinearSolverName("pardiso_lu"), "direct");
    EXPECT_EQ(ResolveLinearSolverName("umfpack"), "umfpack");
    EXPECT_EQ(ResolveLinearSolverName("amgcl"), "petsc");
    EXPECT_EQ(ResolveLinearSolverName("gmres"), "petsc");
    EXPECT_EQ(ResolveLinearSolverName(""), "direct");
    ExpectError<InputError>([] { ResolveLinearSolverName("skyline_lu_factorisation"); },
                            {"did you mean \"skyline_lu_factorization\""});
}

}  // namespace
}  // namespace contact_app
