// SPDX-License-Identifier: BSD-3-Clause
// StaticCondensationSolver against the full solve on a small assembled contact-like system: exactness,
// reuse of the condensed bulk, recondensation and refusals.
#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/model.h"
#include "contact_app/kernel/variables.h"
#include "contact_app/solving/linear_solvers/direct_solver.h"
#include "contact_app/solving/linear_solvers/static_condensation_solver.h"
#include "tests/cpp/solving/linear_solver_test_utilities.h"

namespace contact_app {
namespace {

using Triplets = std::vector<Eigen::Triplet<double, int>>;

/// A grid of nx × ny nodes with DISPLACEMENT_X/Y; the top row is the INTERFACE and carries a
/// VECTOR_LAGRANGE_MULTIPLIER_Y DoF (unless @p with_interface is false); the bottom row is fixed. Equation ids follow the DoF order.
struct GridSystem {
    Model model;
    std::vector<Dof*> dofs;
    std::vector<char> fixed;
    int nx, ny;
    bool interface;

    explicit GridSystem(bool with_interface = true, int columns = 9, int rows = 8)
        : nx(columns), ny(rows), interface(with_interface) {
        RegisterContactApplication();
        ModelPart& part = model.CreateModelPart("Main", 1);
        part.AddNodalSolutionStepVariable(DISPLACEMENT);
        part.AddNodalSolutionStepVariable(VECTOR_LAGRANGE_MULTIPLIER);
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                auto node = part.CreateNewNode(static_cast<IndexType>(1 + i + nx * j), i, j, 0.0);
                for (const auto* variable : {&DISPLACEMENT_X, &DISPLACEMENT_Y}) {
                    dofs.push_back(&node->AddDof(*variable));
                    fixed.push_back(j == 0);
                }
                if (interface && j + 1 == ny) {
                    node->Set(INTERFACE, true);
                    dofs.push_back(&node->AddDof(VECTOR_LAGRANGE_MULTIPLIER_Y));
                    fixed.push_back(0);
                }
            }
        for (std::size_t k = 0; k < dofs.size(); ++k) dofs[k]->SetEquationId(k);
    }
    ModelPart& Part() { return model.GetModelPart("Main"); }
    int Size() const { return static_cast<int>(dofs.size()); }
    int Displacement(int i, int j, int c) const {
        return j * nx * 2 + i * (interface && j + 1 == ny ? 3 : 2) + c;
    }

    /// Element-like stiffness: springs between neighbours, symmetric and positive definite with the
    /// fixed bottom row; @p skew > 0 makes it unsymmetric.
    Triplets Bulk(double scale = 1.0, double skew = 0.0) const {
        Triplets t;
        auto spring = [&](int a, int b, double k) {
            t.emplace_back(a, a, k);
            t.emplace_back(b, b, k);
            t.emplace_back(a, b, -k * (1.0 + skew));
            t.emplace_back(b, a, -k);
        };
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                for (int c = 0; c < 2; ++c) {
                    const int a = Displacement(i, j, c);
                    t.emplace_back(a, a, 0.1 * scale);
                    if (i + 1 < nx) spring(a, Displacement(i + 1, j, c), scale * (1.0 + 0.1 * c));
                    if (j + 1 < ny) spring(a, Displacement(i, j + 1, c), scale * (1.3 - 0.2 * c));
                    if (c == 0 && i + 1 < nx && j + 1 < ny) spring(a, Displacement(i + 1, j + 1, 1), 0.4 * scale);
                }
        return t;
    }

    /// Contact-like interface block: unsymmetric couplings of the top-row displacements and a
    /// saddle-point multiplier row per node, with a @p seed for iteration-dependent values.
    Triplets Contact(unsigned seed) const {
        std::mt19937 random(seed);
        std::uniform_real_distribution<double> value(0.2, 1.0);
        Triplets t;
        for (int i = 0; i < nx; ++i) {
            const int u = Displacement(i, ny - 1, 1), lambda = u + 1;
            t.emplace_back(u, lambda, 1.0);
            t.emplace_back(lambda, u, value(random));
            t.emplace_back(lambda, lambda, -0.1 * value(random));
            if (i + 1 < nx) t.emplace_back(u, Displacement(i + 1, ny - 1, 0), 0.3 * value(random));
        }
        return t;
    }

    /// A from both parts, with the block builder's Dirichlet treatment of the bottom row.
    SparseMatrixType Assemble(const Triplets& bulk, const Triplets& contact) const {
        Triplets all = bulk;
        all.insert(all.end(), contact.begin(), contact.end());
        SparseMatrixType a(Size(), Size());
        a.setFromTriplets(all.begin(), all.end());
        for (int j = 0; j < a.outerSize(); ++j)
            for (SparseMatrixType::InnerIterator entry(a, j); entry; ++entry)
                if (entry.row() != j && (fixed[entry.row()] || fixed[j])) entry.valueRef() = 0.0;
        return a;
    }
    SystemVectorType Rhs(unsigned seed) const {
        std::mt19937 random(seed);
        std::uniform_real_distribution<double> value(-1.0, 1.0);
        SystemVectorType b(Size());
        for (int k = 0; k < Size(); ++k) b[k] = fixed[k] ? 0.0 : value(random);
        return b;
    }
};

/// Solves with @p solver (given the DoF data) and with UMFPACK on the full system; returns the relative difference.
double Difference(StaticCondensationSolver& solver, GridSystem& grid, SparseMatrixType a, SystemVectorType b,
                  bool provide = true) {
    SystemVectorType x, reference;
    if (provide) solver.ProvideAdditionalData(grid.dofs, grid.Part());
    solver.Solve(a, x, b);
    DirectSolver full(DirectSolverKind::UmfPack);
    full.Solve(a, reference, b);
    return (x - reference).norm() / reference.norm();
}

std::shared_ptr<LinearSolver> Umfpack() { return std::make_shared<DirectSolver>(DirectSolverKind::UmfPack); }

/// Files of MUMPS's out-of-core factors for the Schur product in the temporary directory.
std::size_t SchurFactorFiles() { return testing::TemporaryFiles("contact_app_schur_"); }

TEST(StaticCondensationSolver, EqualsTheFullSolveAndReusesTheBulk) {
    GridSystem grid;
    StaticCondensationSolver solver(Umfpack(), StaticCondensationMode::On);
    const Triplets bulk = grid.Bulk();
    for (unsigned iteration = 0; iteration < 3; ++iteration) {
        EXPECT_LT(Difference(solver, grid, grid.Assemble(bulk, grid.Contact(iteration)), grid.Rhs(iteration)), 1e-12);
        EXPECT_TRUE(solver.LastSolveWasCondensed());
    }
    const LinearSolverStatistics statistics = solver.Statistics();
    EXPECT_EQ(statistics.condensation, "yes");
    EXPECT_EQ(statistics.bulk_factorizations, 1u);  // the contact block changed, the bulk did not
    EXPECT_EQ(statistics.condensed_solves, 3u);
    EXPECT_EQ(statistics.interface_size, static_cast<std::size_t>(3 * grid.nx));
    EXPECT_EQ(statistics.bulk_size, static_cast<std::size_t>(grid.Size() - 3 * grid.nx));
    EXPECT_EQ(statistics.factorizations, 0u);  // the inner solver never ran
}

// A bulk factor over the in-core limit (0 bytes here): MUMPS's factorisation for P is kept out of core and solves
// the bulk, for a definite and for an indefinite symmetric bulk (LDLᵀ with 2×2 pivots), and leaves no files.
TEST(StaticCondensationSolver, BulkOverTheInCoreLimitIsSolvedByMumpsOutOfCore) {
    const std::size_t before = SchurFactorFiles();
    for (const double indefinite : {0.0, -40.0}) {
        GridSystem grid;
        StaticCondensationSolver solver(Umfpack(), StaticCondensationMode::On);
        solver.SetBulkInCoreLimit(0.0);
        Triplets bulk = grid.Bulk();
        for (int i : {2, 5}) bulk.emplace_back(grid.Displacement(i, 3, 0), grid.Displacement(i, 3, 0), indefinite);
        for (unsigned iteration = 0; iteration < 3; ++iteration) {
            EXPECT_LT(Difference(solver, grid, grid.Assemble(bulk, grid.Contact(iteration)), grid.Rhs(iteration)),
                      1e-10);
            EXPECT_TRUE(solver.LastSolveWasCondensed());
            EXPECT_GT(SchurFactorFiles(), before);  // the factor on disk while the condensation keeps it
        }
        EXPECT_EQ(solver.Statistics().bulk_factorizations, 1u);
        EXPECT_EQ(solver.Statistics().solver, "static condensation (bulk mumps out of core, interface dense LU)");
    }
    EXPECT_EQ(SchurFactorFiles(), before);
}

TEST(StaticCondensationSolver, UnsymmetricBulkTakesTheLuPath) {
    GridSystem grid;
    StaticCondensationSolver solver(Umfpack(), StaticCondensationMode::On);
    EXPECT_LT(Difference(solver, grid, grid.Assemble(grid.Bulk(1.0, 0.05), grid.Contact(1)), grid.Rhs(1)), 1e-12);
    EXPECT_TRUE(solver.LastSolveWasCondensed());
}

// A symmetric bulk that is not positive definite: CHOLMOD's numeric factor (which runs after MUMPS's symmetric
// factorisation for P) fails, so P must come from MUMPS's unsymmetric factorisation and the bulk from UMFPACK.
TEST(StaticCondensationSolver, SymmetricIndefiniteBulkTakesTheLuPath) {
    GridSystem grid;
    StaticCondensationSolver solver(Umfpack(), StaticCondensationMode::On);
    Triplets bulk = grid.Bulk();
    for (int i : {2, 5}) bulk.emplace_back(grid.Displacement(i, 3, 0), grid.Displacement(i, 3, 0), -40.0);
    EXPECT_LT(Difference(solver, grid, grid.Assemble(bulk, grid.Contact(2)), grid.Rhs(2)), 1e-10);
    EXPECT_TRUE(solver.LastSolveWasCondensed());
}

TEST(StaticCondensationSolver, ChangedBulkIsCondensedAgainAndTwiceInARowStops) {
    GridSystem grid;
    StaticCondensationSolver solver(Umfpack(), StaticCondensationMode::On);
    EXPECT_LT(Difference(solver, grid, grid.Assemble(grid.Bulk(1.0), grid.Contact(0)), grid.Rhs(0)), 1e-12);
    EXPECT_LT(Difference(solver, grid, grid.Assemble(grid.Bulk(2.0), grid.Contact(0)), grid.Rhs(0)), 1e-12);
    EXPECT_EQ(solver.Statistics().bulk_factorizations, 2u);
    EXPECT_TRUE(solver.LastSolveWasCondensed());
    EXPECT_LT(Difference(solver, grid, grid.Assemble(grid.Bulk(3.0), grid.Contact(0)), grid.Rhs(0)), 1e-12);
    EXPECT_FALSE(solver.LastSolveWasCondensed());
    EXPECT_NE(solver.Statistics().condensation.find("no (the bulk block changed on two consecutive solves"),
              std::string::npos);
    // Given up for the run, even with a constant bulk again.
    EXPECT_LT(Difference(solver, grid, grid.Assemble(grid.Bulk(3.0), grid.Contact(0)), grid.Rhs(0)), 1e-12);
    EXPECT_FALSE(solver.LastSolveWasCondensed());
}

TEST(StaticCondensationSolver, BulkNodesWhoseRowsChangeJoinTheInterface) {
    GridSystem grid(true, 30, 30);  // an interface under 10 % of the equations, so nodes may join it
    StaticCondensationSolver solver(Umfpack(), StaticCondensationMode::On);
    Triplets bulk = grid.Bulk();
    EXPECT_LT(Difference(solver, grid, grid.Assemble(bulk, grid.Contact(0)), grid.Rhs(0)), 1e-12);
    // A load on the current configuration: one bulk node's diagonal changes at every solve.
    const int loaded = grid.Displacement(14, 13, 0);
    for (unsigned iteration = 1; iteration < 4; ++iteration) {
        bulk.emplace_back(loaded, loaded, 0.01 * iteration);
        EXPECT_LT(Difference(solver, grid, grid.Assemble(bulk, grid.Contact(iteration)), grid.Rhs(iteration)), 1e-12);
        EXPECT_TRUE(solver.LastSolveWasCondensed());
    }
    const LinearSolverStatistics statistics = solver.Statistics();
    EXPECT_EQ(statistics.bulk_factorizations, 2u);  // the node joined the interface once
    EXPECT_EQ(statistics.interface_size, static_cast<std::size_t>(3 * grid.nx + 2));
}

TEST(StaticCondensationSolver, RefusesWithTheReason) {
    GridSystem grid;
    const SparseMatrixType a = grid.Assemble(grid.Bulk(), grid.Contact(0));
    const SystemVectorType b = grid.Rhs(0);
    struct Case {
        StaticCondensationMode mode;
        std::string bulk_not_linear;
        bool provide;
        std::string reason;
    };
    const Case cases[] = {
        {StaticCondensationMode::Auto, "", true, "equations, fewer than the 20000 from which \"auto\" condenses"},
        {StaticCondensationMode::Auto, "element 3 is a TotalLagrangianElement2D4N", true,
         "no (element 3 is a TotalLagrangianElement2D4N)"},
        {StaticCondensationMode::Off, "", true, "no (switched off by linear_solver_settings.static_condensation)"},
        {StaticCondensationMode::On, "", false, "no (no DoF data: master-slave constraints are active)"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.reason);
        StaticCondensationSolver solver(Umfpack(), c.mode, c.bulk_not_linear);
        EXPECT_LT(Difference(solver, grid, a, b, c.provide), 1e-14);
        EXPECT_FALSE(solver.LastSolveWasCondensed());
        EXPECT_NE(solver.Statistics().condensation.find(c.reason), std::string::npos) << solver.Statistics().condensation;
        EXPECT_EQ(solver.Statistics().factorizations, 1u);
    }
}

TEST(StaticCondensationSolver, NoInterfaceIsAFullSolve) {
    GridSystem grid(false);
    StaticCondensationSolver solver(Umfpack(), StaticCondensationMode::On);
    EXPECT_LT(Difference(solver, grid, grid.Assemble(grid.Bulk(), {}), grid.Rhs(0)), 1e-14);
    EXPECT_FALSE(solver.LastSolveWasCondensed());
    EXPECT_EQ(solver.Statistics().condensation,
              "no (no contact interface: no equation of an INTERFACE node or a multiplier)");
}

/// A_BB: a 2D Laplacian on n × n points plus the identity (symmetric positive definite); A_BC: random sparse
/// n² × n_c; A_CB = A_BCᵀ, or with an unsymmetric perturbation.
struct SchurBlocks {
    SparseMatrixType a_bb, a_bc, a_cb;
    SchurBlocks(int n, int n_c, bool symmetric) {
        const int n_b = n * n;
        Triplets bb, bc;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const int k = i + n * j;
                bb.emplace_back(k, k, 5.0);
                if (i + 1 < n) bb.emplace_back(k, k + 1, -1.0), bb.emplace_back(k + 1, k, -1.0);
                if (j + 1 < n) bb.emplace_back(k, k + n, -1.0), bb.emplace_back(k + n, k, -1.0);
            }
        std::mt19937 rng(5);
        std::uniform_int_distribution<int> row(0, n_b - 1);
        std::uniform_real_distribution<double> value(-1.0, 1.0);
        for (int c = 0; c < n_c; ++c)
            for (int e = 0; e < 6; ++e) bc.emplace_back(row(rng), c, value(rng));
        a_bb.resize(n_b, n_b);
        a_bb.setFromTriplets(bb.begin(), bb.end());
        a_bc.resize(n_b, n_c);
        a_bc.setFromTriplets(bc.begin(), bc.end());
        a_cb = a_bc.transpose();
        if (!symmetric) a_cb.coeffs() *= 1.5;
    }
    Eigen::MatrixXd Dense() const {
        return Eigen::MatrixXd(a_cb) * Eigen::MatrixXd(a_bb).ldlt().solve(Eigen::MatrixXd(a_bc));
    }
};

TEST(StaticCondensationSolver, SchurProductOutOfCoreEqualsInCoreAndLeavesNoFiles) {
    const std::size_t before = SchurFactorFiles();
    using detail::SchurSymmetry;
    for (const SchurSymmetry symmetry :
         {SchurSymmetry::POSITIVE_DEFINITE, SchurSymmetry::SYMMETRIC, SchurSymmetry::UNSYMMETRIC}) {
        const bool symmetric = symmetry != SchurSymmetry::UNSYMMETRIC;
        const SchurBlocks blocks(40, 25, symmetric);
        const Eigen::MatrixXd reference = blocks.Dense();
        Eigen::MatrixXd in_core, out_of_core;
        ASSERT_TRUE(detail::SchurProductWithMumps(blocks.a_bb, blocks.a_bc, blocks.a_cb, symmetry, {}, in_core,
                                                  std::numeric_limits<double>::infinity()));
        ASSERT_TRUE(detail::SchurProductWithMumps(blocks.a_bb, blocks.a_bc, blocks.a_cb, symmetry, {}, out_of_core,
                                                  0.0));
        EXPECT_LT((in_core - reference).norm(), 1e-12 * reference.norm()) << symmetric;
        EXPECT_EQ((out_of_core - in_core).norm(), 0.0) << symmetric;
    }
    EXPECT_EQ(SchurFactorFiles(), before);
}

TEST(StaticCondensationSolver, ModeNames) {
    EXPECT_EQ(ParseStaticCondensationMode("auto"), StaticCondensationMode::Auto);
    EXPECT_EQ(ParseStaticCondensationMode("on"), StaticCondensationMode::On);
    EXPECT_EQ(ParseStaticCondensationMode("off"), StaticCondensationMode::Off);
    EXPECT_THROW(ParseStaticCondensationMode("yes"), InputError);
}

}  // namespace
}  // namespace contact_app
