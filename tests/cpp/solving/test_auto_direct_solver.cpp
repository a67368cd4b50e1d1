// SPDX-License-Identifier: BSD-3-Clause
// AutoDirectSolver: UMFPACK below kAutoMumpsMinimumSize equations (bit for bit), MUMPS from it.
#include <gtest/gtest.h>

#include "contact_app/solving/linear_solvers/auto_direct_solver.h"
#include "contact_app/solving/linear_solvers/linear_solver_factory.h"
#include "tests/cpp/solving/linear_solver_test_utilities.h"

namespace contact_app {
namespace {

using testing::Laplacian;
using testing::SaddlePoint;

TEST(AutoDirectSolver, SmallSystemsGetUmfpackBitForBit) {
    AutoDirectSolver automatic;
    DirectSolver umfpack(DirectSolverKind::UmfPack);
    EXPECT_EQ(automatic.Info(), "direct");
    SparseMatrixType matrix = SaddlePoint(300);
    SystemVectorType b = SystemVectorType::LinSpaced(matrix.rows(), -1.0, 1.0), x, y;
    automatic.Solve(matrix, x, b);
    umfpack.Solve(matrix, y, b);
    EXPECT_EQ(x, y);
    EXPECT_EQ(automatic.Info(), "umfpack");
    EXPECT_EQ(automatic.Statistics().solver, "umfpack");
    EXPECT_EQ(automatic.Statistics().ordering, "amd");
}

TEST(AutoDirectSolver, LargeSystemsGetMumpsAndTheStatisticsSayWhichRan) {
    const auto size = static_cast<int>(kAutoMumpsMinimumSize);
    LinearSolverSettings settings;
    settings.solver_type = "skyline_lu_factorization";
    const auto solver = CreateLinearSolver(settings);
    SparseMatrixType identity(size, size);
    identity.setIdentity();
    SparseMatrixType large = Laplacian(size) + 2.0 * identity;  // condition number below 3
    const SystemVectorType expected = SystemVectorType::LinSpaced(size, 1.0, 2.0);
    SystemVectorType b = large * expected, x;
    solver->Solve(large, x, b);
    EXPECT_LT((x - expected).norm() / expected.norm(), 1e-12);
    EXPECT_EQ(solver->Info(), "mumps");
    EXPECT_EQ(solver->Statistics().solver, "mumps");
    EXPECT_EQ(solver->Statistics().ordering, "metis");
    SparseMatrixType small = Laplacian(size - 1);
    SystemVectorType c = SystemVectorType::Ones(size - 1);
    solver->Solve(small, x, c);
    const LinearSolverStatistics both = solver->Statistics();
    EXPECT_EQ(both.solver, "umfpack and mumps");
    EXPECT_EQ(both.factorizations, 2u);
    EXPECT_EQ(solver->NumberOfSymbolicAnalyses(), 2u);
}

}  // namespace
}  // namespace contact_app
