// SPDX-License-Identifier: BSD-3-Clause
/// The condensing solver gives the solution of the full saddle-point system (to round-off) when the slave-row /
/// multiplier coupling is diagonal (dual basis), and falls back to the full solve otherwise.
#include <random>

#include <gtest/gtest.h>

#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/model.h"
#include "contact_app/solving/linear_solvers/linear_solver_factory.h"
#include "custom_strategies/mixed_ulm_linear_solver.h"

namespace contact_app::testing {
namespace {

/// Two slave nodes (active / inactive), one master node and one interior node in 2D with
/// DISPLACEMENT_X/Y and VECTOR_LAGRANGE_MULTIPLIER_X/Y; equation ids in DoF order.
struct SaddleSystem {
    Model model;
    ModelPart* part = nullptr;
    std::vector<Dof*> dofs;
    SparseMatrixType A;
    SystemVectorType b;

    /// @p dual: the slave rows couple to their own multiplier only. @p slipping: the active node's multiplier rows
    /// depend most on the other displacement component (as a slipping node's tangential rows on its normal
    /// displacement through μ|λ̄n|), so their own diagonal is small.
    explicit SaddleSystem(bool dual, bool slipping = false) {
        RegisterContactApplication();
        part = &model.CreateModelPart("Structure");
        part->AddNodalSolutionStepVariable(DISPLACEMENT);
        part->AddNodalSolutionStepVariable(VECTOR_LAGRANGE_MULTIPLIER);
        for (int id = 1; id <= 4; ++id) {
            auto node = part->CreateNewNode(id, id, 0.0, 0.0);
            for (const auto* v :
                 {&DISPLACEMENT_X, &DISPLACEMENT_Y, &VECTOR_LAGRANGE_MULTIPLIER_X, &VECTOR_LAGRANGE_MULTIPLIER_Y})
                dofs.push_back(&node->AddDof(*v));
        }
        part->GetNode(1).Set(SLAVE, true);
        part->GetNode(1).Set(ACTIVE, true);
        part->GetNode(2).Set(SLAVE, true);
        part->GetNode(2).Set(ACTIVE, false);
        part->GetNode(3).Set(MASTER, true);
        for (std::size_t i = 0; i < dofs.size(); ++i) dofs[i]->SetEquationId(i);
        const int n = static_cast<int>(dofs.size());
        // Equation index of (node, dof kind): node k (1-based), kind 0/1 = ux/uy, 2/3 = λx/λy.
        auto eq = [](int node, int kind) { return 4 * (node - 1) + kind; };
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
        // Displacement block: SPD-like random stiffness over all displacement DoFs.
        std::vector<int> disp;
        for (int node = 1; node <= 4; ++node) disp.insert(disp.end(), {eq(node, 0), eq(node, 1)});
        Eigen::MatrixXd G(disp.size(), disp.size());
        for (int i = 0; i < G.rows(); ++i)
            for (int j = 0; j < G.cols(); ++j) G(i, j) = u(rng);
        const Eigen::MatrixXd S = G * G.transpose() + 4.0 * Eigen::MatrixXd::Identity(G.rows(), G.rows());
        for (std::size_t i = 0; i < disp.size(); ++i)
            for (std::size_t j = 0; j < disp.size(); ++j) K(disp[i], disp[j]) = S(i, j);
        // Active node 1: slave rows couple to its own multiplier (k D), master rows to it (−k M); multiplier rows
        // couple to slave and master displacements and to themselves (ALM).
        for (int c = 0; c < 2; ++c) {
            K(eq(1, c), eq(1, 2 + c)) = 2.5;
            if (!dual) K(eq(1, c), eq(1, 2 + (1 - c))) = 0.3;  // standard basis: not diagonal
            K(eq(3, c), eq(1, 2 + c)) = -2.5;
            K(eq(1, 2 + c), eq(1, c)) = slipping ? 0.05 : 1.7;
            K(eq(1, 2 + c), eq(3, c)) = -1.7;
            if (slipping) K(eq(1, 2 + c), eq(1, 1 - c)) = c == 0 ? 40.0 : -35.0;
            K(eq(1, 2 + c), eq(1, 2 + c)) = 0.4;
            // Inactive node 2: −k²/ε λ on its multiplier rows only; interior node 4 multipliers unused (identity).
            K(eq(2, 2 + c), eq(2, 2 + c)) = -3.0;
            K(eq(4, 2 + c), eq(4, 2 + c)) = 1.0;
            K(eq(3, 2 + c), eq(3, 2 + c)) = 1.0;
        }
        A = K.sparseView();
        A.makeCompressed();
        b = SystemVectorType::NullaryExpr(n, [&]() { return u(rng); });
    }
};

LinearSolver::Pointer Umfpack() {
    LinearSolverSettings settings;
    settings.solver_type = "umfpack";
    return CreateLinearSolver(settings);
}

TEST(MixedULMLinearSolver, CondensedSolutionEqualsTheFullSolveWithDualMultipliers) {
    SaddleSystem system(true);
    SystemVectorType full = SystemVectorType::Zero(system.b.size()), condensed = full;
    SparseMatrixType A_full = system.A;
    SystemVectorType b_full = system.b;
    Umfpack()->Solve(A_full, full, b_full);
    MixedULMLinearSolver solver(Umfpack());
    solver.ProvideAdditionalData(system.dofs, *system.part);
    solver.Solve(system.A, condensed, system.b);
    EXPECT_TRUE(solver.LastSolveWasCondensed());
    EXPECT_EQ(solver.LastCondensedMultipliers(), 2u);  // λx, λy of the active node
    EXPECT_LT((condensed - full).norm(), 1e-12 * full.norm());
    EXPECT_LT((system.A * condensed - system.b).norm(), 1e-11 * system.b.norm());
}

/// UMFPACK that asks for the unknown layout (as the PETSc AMG does) and keeps the reduced system it solves.
class RecordingSolver : public LinearSolver {
public:
    void Solve(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) override {
        reduced = rA;
        Umfpack()->Solve(rA, rX, rB);
    }
    std::string Info() const override { return "recording"; }
    bool UnknownLayoutIsNeeded() const override { return true; }
    void ProvideUnknownLayout(UnknownLayout layout) override { kept = std::move(layout); }
    SparseMatrixType reduced;
    UnknownLayout kept;
};

/// The moved multiplier rows of node 1 in the reduced system (the positions of its displacement unknowns).
Eigen::Matrix2d NodeOneBlock(const RecordingSolver& inner) {
    Eigen::Matrix2d block;
    std::vector<int> at;
    for (int i = 0; i < static_cast<int>(inner.kept.size()); ++i)
        if (inner.kept.node[i] == 1) at.push_back(i);
    EXPECT_EQ(at.size(), 2u);
    for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) block(a, b) = inner.reduced.coeff(at[a], at[b]);
    return block;
}

TEST(MixedULMLinearSolver, ForALayoutEachNodesMovedRowsTakeTheDisplacementDiagonal) {
    // docs/theory/condensation.md §5: the moved rows of a node are combined (slipping) or scaled (sticking) so that
    // their block on the node's displacements is diag |K_ss|; the solution is the full solve's either way.
    for (const bool slipping : {false, true}) {
        SaddleSystem system(true, slipping);
        SystemVectorType full = SystemVectorType::Zero(system.b.size()), condensed = full;
        SparseMatrixType A_full = system.A;
        SystemVectorType b_full = system.b;
        Umfpack()->Solve(A_full, full, b_full);
        auto inner = std::make_shared<RecordingSolver>();
        MixedULMLinearSolver solver(inner);
        solver.ProvideAdditionalData(system.dofs, *system.part);
        solver.Solve(system.A, condensed, system.b);
        ASSERT_TRUE(solver.LastSolveWasCondensed());
        EXPECT_LT((condensed - full).norm(), 1e-12 * full.norm()) << "slipping " << slipping;
        const Eigen::Matrix2d block = NodeOneBlock(*inner);
        const Eigen::Vector2d displacement(system.A.coeff(0, 0), system.A.coeff(1, 1));
        for (int a = 0; a < 2; ++a) {
            EXPECT_NEAR(block(a, a), displacement[a], 1e-12 * displacement[a]) << "slipping " << slipping;
            // Slipping: the combination removes the cross-coupling (row-wise scaling would leave it about 800× the
            // diagonal, 40 against 0.05).
            if (slipping) EXPECT_LT(std::abs(block(a, 1 - a)), 1e-12 * displacement[a]);
        }
    }
}

TEST(MixedULMLinearSolver, FallsBackToTheFullSolveWhenTheCouplingIsNotDiagonal) {
    SaddleSystem system(false);
    SystemVectorType x = SystemVectorType::Zero(system.b.size());
    MixedULMLinearSolver solver(Umfpack());
    solver.ProvideAdditionalData(system.dofs, *system.part);
    solver.Solve(system.A, x, system.b);
    EXPECT_FALSE(solver.LastSolveWasCondensed());
    EXPECT_LT((system.A * x - system.b).norm(), 1e-11 * system.b.norm());
}

TEST(MixedULMLinearSolver, WithoutDataItSolvesTheFullSystem) {
    SaddleSystem system(true);
    SystemVectorType x = SystemVectorType::Zero(system.b.size());
    MixedULMLinearSolver solver(Umfpack());
    solver.Solve(system.A, x, system.b);
    EXPECT_FALSE(solver.LastSolveWasCondensed());
    EXPECT_LT((system.A * x - system.b).norm(), 1e-11 * system.b.norm());
}

}  // namespace
}  // namespace contact_app::testing
