// SPDX-License-Identifier: BSD-3-Clause
// MumpsSolver: unsymmetric and saddle-point solves, analysis reuse, orderings, statistics, errors.
#include <gtest/gtest.h>

#include <string>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/solving/linear_solvers/linear_solver_factory.h"
#include "contact_app/solving/linear_solvers/mumps_solver.h"
#include "tests/cpp/error_test_utilities.h"
#include "tests/cpp/solving/linear_solver_test_utilities.h"

namespace contact_app {
namespace {

using testing::ExpectError;
using testing::Laplacian;
using testing::SaddlePoint;

/// 2D convection–diffusion on an m×m grid (unsymmetric, non-singular; the upwind terms break symmetry).
SparseMatrixType ConvectionDiffusion(int m) {
    std::vector<Eigen::Triplet<double, int>> entries;
    const auto index = [m](int i, int j) { return i + m * j; };
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
            entries.emplace_back(index(i, j), index(i, j), 4.5);
            if (i > 0) entries.emplace_back(index(i, j), index(i - 1, j), -1.5);
            if (i + 1 < m) entries.emplace_back(index(i, j), index(i + 1, j), -0.5);
            if (j > 0) entries.emplace_back(index(i, j), index(i, j - 1), -1.2);
            if (j + 1 < m) entries.emplace_back(index(i, j), index(i, j + 1), -0.8);
        }
    SparseMatrixType matrix(m * m, m * m);
    matrix.setFromTriplets(entries.begin(), entries.end());
    return matrix;
}

double RelativeError(MumpsSolver& solver, SparseMatrixType matrix) {
    const SystemVectorType expected = SystemVectorType::LinSpaced(matrix.rows(), 1.0, 2.0);
    SystemVectorType b = matrix * expected, x;
    solver.Solve(matrix, x, b);
    return (x - expected).norm() / expected.norm();
}

TEST(MumpsSolver, SolvesAnUnsymmetricAndASaddlePointSystem) {
    for (const auto ordering : {FillReducingOrdering::Auto, FillReducingOrdering::Amd, FillReducingOrdering::Metis}) {
        MumpsSolver unsymmetric(ordering);
        EXPECT_LT(RelativeError(unsymmetric, ConvectionDiffusion(30)), 1e-12);
        MumpsSolver saddle(ordering);
        EXPECT_LT(RelativeError(saddle, SaddlePoint(200)), 1e-12);
    }
}

TEST(MumpsSolver, AnalysesOnlyWhenThePatternChanges) {
    MumpsSolver solver;
    SparseMatrixType matrix = ConvectionDiffusion(12);
    EXPECT_LT(RelativeError(solver, matrix), 1e-12);
    matrix *= 3.0;
    matrix.coeffRef(5, 5) += 1.0;  // new values, same pattern: refactorisation only
    EXPECT_LT(RelativeError(solver, matrix), 1e-12);
    EXPECT_EQ(solver.NumberOfSymbolicAnalyses(), 1u);
    EXPECT_EQ(solver.Statistics().factorizations, 2u);
    EXPECT_LT(RelativeError(solver, SaddlePoint(143)), 1e-12);  // new pattern: analysed again
    EXPECT_EQ(solver.NumberOfSymbolicAnalyses(), 2u);
    EXPECT_EQ(solver.Statistics().system_size, 144u);
    solver.Clear();
    EXPECT_LT(RelativeError(solver, SaddlePoint(143)), 1e-12);
    EXPECT_EQ(solver.NumberOfSymbolicAnalyses(), 3u);
}

TEST(MumpsSolver, StatisticsNameTheSolverTheOrderingAndTheFactors) {
    for (const auto ordering : {FillReducingOrdering::Auto, FillReducingOrdering::Amd, FillReducingOrdering::Metis}) {
        MumpsSolver solver(ordering);
        const SparseMatrixType matrix = ConvectionDiffusion(40);
        RelativeError(solver, matrix);
        const LinearSolverStatistics statistics = solver.Statistics();
        testing::ExpectFactorStatistics(statistics, "mumps", ordering == FillReducingOrdering::Amd ? "amd" : "metis", 1,
                                        matrix);
        EXPECT_EQ(statistics.ordering_setting, FillReducingOrderingName(ordering));
    }
}

TEST(MumpsSolver, SingularMatrixIsAConvergenceErrorNamingTheCode) {
    SparseMatrixType matrix = Laplacian(6);
    matrix.coeffRef(0, 0) = 1.0;  // rows sum to zero: the constant vector is a null vector
    matrix.coeffRef(5, 5) = 1.0;
    SystemVectorType b = SystemVectorType::Ones(6), x;
    MumpsSolver solver;
    ExpectError<ConvergenceError>([&] { solver.Solve(matrix, x, b); },
                                  {"mumps: the factorisation of the 6x6 system failed",
                                   "singular matrix (MUMPS error -10; null pivots: 1)", "fix:"});
    EXPECT_LT(RelativeError(solver, Laplacian(6)), 1e-12);  // usable after the failure
}

/// ConvectionDiffusion(m) bordered by a constraint row u_i − u_{i+1} = 0 for every third unknown, with a zero diagonal:
/// pivots that the threshold pivoting has to delay, so the factorisation needs working space the analysis did not plan.
SparseMatrixType ConstrainedConvectionDiffusion(int m) {
    const SparseMatrixType bulk = ConvectionDiffusion(m);
    std::vector<Eigen::Triplet<double, int>> entries;
    for (int j = 0; j < bulk.outerSize(); ++j)
        for (SparseMatrixType::InnerIterator it(bulk, j); it; ++it) entries.emplace_back(it.row(), it.col(), it.value());
    const int n = m * m;
    int row = n;
    for (int i = 0; i + 1 < n; i += 3, ++row) {
        entries.emplace_back(row, i, 1.0);
        entries.emplace_back(row, i + 1, -1.0);
        entries.emplace_back(i, row, 1.0);
        entries.emplace_back(i + 1, row, -1.0);
    }
    SparseMatrixType matrix(row, row);
    matrix.setFromTriplets(entries.begin(), entries.end());
    return matrix;
}

/// No working space beyond the analysis's estimate (ICNTL(14) = 0): with the METIS ordering (the default) the delayed
/// pivots need more, MUMPS stops with -8/-9, and the factorisation is redone with 20 % (then 40 %) more (measured: once);
/// the solve is exact and the statistics say so. With MUMPS's own 20 % nothing is redone.
TEST(MumpsSolver, RedoesTheFactorisationWithMoreWorkingSpace) {
    for (const auto ordering : {FillReducingOrdering::Auto, FillReducingOrdering::Metis}) {
        MumpsSolver tight(ordering, 0);
        EXPECT_LT(RelativeError(tight, ConstrainedConvectionDiffusion(30)), 1e-10);
        EXPECT_GE(tight.Statistics().workspace_enlargements, 1u);
        EXPECT_LE(tight.Statistics().workspace_enlargements, 2u);
        MumpsSolver standard(ordering);  // MUMPS's own 20 %
        EXPECT_LT(RelativeError(standard, ConstrainedConvectionDiffusion(30)), 1e-10);
        EXPECT_EQ(standard.Statistics().workspace_enlargements, 0u);
    }
    EXPECT_THROW(MumpsSolver(FillReducingOrdering::Auto, -1), InputError);
}

/// Files of MUMPS's out-of-core factors in the temporary directory.
std::size_t OutOfCoreFiles() { return testing::TemporaryFiles("contact_app_mumps_"); }

/// A limit of 0 bytes sends every factorisation out of core: the solutions are those in core, the factors are on disk
/// while the solver keeps them and gone with it; the default (70 % of the available memory) keeps these in core.
TEST(MumpsSolver, OutOfCoreSolvesAsInCoreAndLeavesNoFiles) {
    const std::size_t before = OutOfCoreFiles();
    {
        MumpsSolver in_core, out_of_core(FillReducingOrdering::Auto, 20, 0.0);
        for (const SparseMatrixType& matrix : {ConvectionDiffusion(30), SaddlePoint(200)}) {
            const SystemVectorType b = SystemVectorType::LinSpaced(matrix.rows(), 1.0, 2.0);
            SystemVectorType x_in, x_out, b_in = b, b_out = b;
            SparseMatrixType a_in = matrix, a_out = matrix;
            in_core.Solve(a_in, x_in, b_in);
            out_of_core.Solve(a_out, x_out, b_out);
            EXPECT_LT((matrix * x_out - b).norm(), 1e-12 * b.norm());
            EXPECT_LT((x_out - x_in).norm(), 1e-14 * x_in.norm());
            EXPECT_GT(OutOfCoreFiles(), before);  // the factors of the last factorisation
        }
        EXPECT_EQ(in_core.Statistics().out_of_core_factorizations, 0u);
        EXPECT_EQ(out_of_core.Statistics().out_of_core_factorizations, 2u);
    }
    EXPECT_EQ(OutOfCoreFiles(), before);
}

TEST(MumpsSolver, FactoryNamesAndOrderings) {
    EXPECT_EQ(ResolveLinearSolverName("mumps"), "mumps");
    EXPECT_EQ(ResolveLinearSolverName("LinearSolversApplication.mumps"), "mumps");
    LinearSolverSettings settings;
    settings.solver_type = "mumps";
    settings.ordering = "amd";
    const auto solver = CreateLinearSolver(settings);
    EXPECT_EQ(solver->Info(), "mumps");
    EXPECT_EQ(solver->Statistics().ordering_setting, "amd");
    settings.solver_type = "klu";
    EXPECT_THROW(CreateLinearSolver(settings), InputError);
}

}  // namespace
}  // namespace contact_app
