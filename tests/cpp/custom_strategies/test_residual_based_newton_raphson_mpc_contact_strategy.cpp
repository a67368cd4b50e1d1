// SPDX-License-Identifier: BSD-3-Clause
/// ResidualBasedNewtonRaphsonMPCContactStrategy: nodal weights, settings checks, and the two-block patch of the
/// reference case (gap closed, force balance) in the three loop variants, pulled apart (contact released), and the
/// reduced system of slipping nodes against the Coulomb equilibrium and its central differences.
#include <gtest/gtest.h>

#include "contact_app/application.h"
#include "contact_app/kernel/constitutive_law.h"
#include "contact_app/solving/builder_and_solvers/elimination_builder_and_solver.h"
#include "contact_app/solving/convergence_criteria/composite_criteria.h"
#include "contact_app/solving/convergence_criteria/residual_criteria.h"
#include "contact_app/solving/linear_solvers/linear_solver_factory.h"
#include "contact_app/structural/structural_registration.h"
#include "custom_strategies/contact_master_slave_constraint.h"
#include "custom_strategies/mortar_convergence_criteria.h"
#include "custom_strategies/residual_based_newton_raphson_mpc_contact_strategy.h"
#include "custom_utilities/contact_utilities.h"
#include "../custom_conditions/tying_test_utilities.h"

namespace contact_app::testing {
namespace {

TEST(ResidualBasedNewtonRaphsonMPCContactStrategy, NodalWeightsCountTheSlaveConditionsOfEachNode) {
    TyingPairModel model;
    ModelPart& root = *model.part;
    for (IndexType id = 1; id <= 4; ++id) model.AddNode(id, Eigen::Vector2d(static_cast<double>(id), 0.0));
    ModelPart& contact = root.CreateSubModelPart("Contact");
    for (IndexType id = 1; id <= 4; ++id) contact.AddNode(root.pGetNode(id));
    // Slave faces 1–2 and 2–3; face 3–4 is a master face (not counted).
    const IndexType faces[3][2] = {{1, 2}, {2, 3}, {3, 4}};
    for (int f = 0; f < 3; ++f) {
        Geometry::PointsArrayType points = {root.pGetNode(faces[f][0]), root.pGetNode(faces[f][1])};
        auto face = std::make_shared<Condition>(f + 1, CreateGeometry("Line2D2", points), model.properties);
        face->Set(SLAVE, f < 2);
        face->Set(MASTER, f == 2);
        contact.AddCondition(face);
    }
    ResidualBasedNewtonRaphsonMPCContactStrategy::ComputeNodalWeights(root);
    EXPECT_EQ(root.GetNode(1).GetValue(NODAL_PAUX), 1.0);
    EXPECT_EQ(root.GetNode(2).GetValue(NODAL_PAUX), 2.0);
    EXPECT_EQ(root.GetNode(3).GetValue(NODAL_PAUX), 1.0);
    EXPECT_EQ(root.GetNode(4).GetValue(NODAL_PAUX), 0.0);
}

TEST(ResidualBasedNewtonRaphsonMPCContactStrategy, RejectsZeroInnerLoops) {
    TyingPairModel model;
    auto solver = CreateLinearSolver(LinearSolverSettings{});
    auto builder = std::make_shared<EliminationBuilderAndSolver>(solver);
    auto scheme = std::make_shared<Scheme>();
    auto criteria = std::make_shared<ResidualCriteria>(1e-4, 1e-9);
    MPCContactStrategySettings mpc;
    mpc.inner_loop_iterations = 0;
    EXPECT_THROW(ResidualBasedNewtonRaphsonMPCContactStrategy(*model.part, scheme, builder, criteria, 10, {}, mpc),
                 InputError);
}

/// Two unit squares, the upper one GAP above the lower one (the reference case mpc 2D matching patch): lower
/// bottom (1, 2) fixed, upper top (7, 8) moved vertically by @p top; slave face 3–4 (lower top), master face 5–6.
struct TwoBlockPatch {
    static constexpr double kGap = 0.001;

    TwoBlockPatch(double top, bool simplified, bool update_each) {
        RegisterContactApplication();
        RegisterStructuralMechanics();
        RegisterContactConditions();
        RegisterContactMasterSlaveConstraints();
        root = &model.CreateModelPart("Structure", 2);
        for (const VariableData* v : std::initializer_list<const VariableData*>{
                 &DISPLACEMENT, &REACTION, &VOLUME_ACCELERATION, &NORMAL, &WEIGHTED_GAP})
            root->AddNodalSolutionStepVariable(*v);
        root->GetProcessInfo().SetValue(DOMAIN_SIZE, 2);
        const double xy[8][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 1 + kGap}, {1, 1 + kGap}, {1, 2}, {0, 2}};
        for (IndexType id = 1; id <= 8; ++id) {
            auto node = root->CreateNewNode(id, xy[id - 1][0], xy[id - 1][1], 0.0);
            node->AddDof(DISPLACEMENT_X, REACTION_X);
            node->AddDof(DISPLACEMENT_Y, REACTION_Y);
        }
        auto properties = root->CreateNewProperties(1);
        properties->SetValue(YOUNG_MODULUS, 1.0e9);
        properties->SetValue(POISSON_RATIO, 0.3);
        properties->SetValue(THICKNESS, 1.0);
        properties->SetValue(CONSTITUTIVE_LAW,
                             Registry<ConstitutiveLaw>::Instance().Get("LinearElasticPlaneStrain2DLaw").Clone());
        root->CreateNewElement("SmallDisplacementElement2D4N", 1, {1, 2, 3, 4}, properties);
        root->CreateNewElement("SmallDisplacementElement2D4N", 2, {5, 6, 7, 8}, properties);

        ModelPart& contact = root->CreateSubModelPart("Contact");
        ModelPart& computing = root->CreateSubModelPart("ComputingContact");
        auto face = [&](IndexType id, IndexType a, IndexType b, const Flags& side) {
            Geometry::PointsArrayType points = {root->pGetNode(a), root->pGetNode(b)};
            auto condition = std::make_shared<Condition>(id, CreateGeometry("Line2D2", points), properties);
            condition->Set(side, true);
            contact.AddCondition(condition);
            for (IndexType n : {a, b}) {
                contact.AddNode(root->pGetNode(n));
                root->GetNode(n).Set(side, true);
            }
            return condition;
        };
        auto slave = face(10, 3, 4, SLAVE);
        auto master = face(11, 5, 6, MASTER);
        for (IndexType n : {3, 4}) root->GetNode(n).Set(ACTIVE, true);
        const auto& prototype =
            dynamic_cast<const PairedCondition&>(Registry<Condition>::Instance().Get("MPCMortarContactCondition2D2N"));
        auto pair = prototype.Create(20, slave->pGetGeometry(), properties, master->pGetGeometry());
        pair->Set(ACTIVE, true);
        computing.AddCondition(pair);
        auto constraint = std::make_shared<ContactMasterSlaveConstraint>(1);
        constraint->Set(ACTIVE, true);
        computing.AddMasterSlaveConstraint(constraint);
        pair->SetValue(CONSTRAINT_POINTER, std::shared_ptr<MasterSlaveConstraint>(constraint));
        UpdateContactNormals(*root);
        ResidualBasedNewtonRaphsonMPCContactStrategy::ComputeNodalWeights(*root);

        for (IndexType n : {1, 2, 7, 8}) {
            root->GetNode(n).Fix(DISPLACEMENT_X);
            root->GetNode(n).Fix(DISPLACEMENT_Y);
        }
        root->GetProcessInfo().Set(INTERACTION, simplified);
        MPCContactStrategySettings mpc;
        mpc.update_each_nl_iteration = update_each;
        mpc_criteria = std::make_shared<MPCContactCriteria>();
        auto criteria = std::make_shared<CompositeCriteria>(CompositeCriteria::Mode::And,
                                                            std::make_shared<ResidualCriteria>(1e-10, 1e-14), mpc_criteria);
        StrategySettings settings;
        settings.reform_dofs_at_each_step = true;
        strategy = std::make_shared<ResidualBasedNewtonRaphsonMPCContactStrategy>(
            *root, std::make_shared<Scheme>(), std::make_shared<EliminationBuilderAndSolver>(CreateLinearSolver({})),
            criteria, 10, settings, mpc);
        strategy->Initialize();
        root->GetProcessInfo().SetValue(DELTA_TIME, 1.0);
        root->CloneTimeStep(1.0);
        for (IndexType n : {7, 8}) root->GetNode(n).FastGetSolutionStepValue(DISPLACEMENT)[1] = top;
        ContactUtilities::ComputeExplicitContributionConditions(computing);  // the search's step-start gaps
        converged = strategy->Solve();
    }
    double U(IndexType id, int k) { return root->GetNode(id).FastGetSolutionStepValue(DISPLACEMENT)[k]; }
    double R(IndexType id, int k) { return root->GetNode(id).FastGetSolutionStepValue(REACTION)[k]; }

    Model model;
    ModelPart* root = nullptr;
    std::shared_ptr<MPCContactCriteria> mpc_criteria;
    std::shared_ptr<ResidualBasedNewtonRaphsonMPCContactStrategy> strategy;
    bool converged = false;
};

class MPCPatchVariants : public ::testing::TestWithParam<std::tuple<bool, bool>> {};

TEST_P(MPCPatchVariants, ResidualBasedNewtonRaphsonMPCContactStrategyClosesTheGapAndTransmitsTheLoad) {
    const auto [simplified, update_each] = GetParam();
    TwoBlockPatch p(-0.2, simplified, update_each);
    ASSERT_TRUE(p.converged);
    EXPECT_EQ(p.strategy->GetInnerLoopIterations(), 1);
    for (const auto& [slave, master] : {std::pair<IndexType, IndexType>{3, 6}, {4, 5}}) {
        EXPECT_NEAR(p.U(slave, 1) - p.U(master, 1), TwoBlockPatch::kGap, 1e-12);  // faces touch
        EXPECT_TRUE(p.root->GetNode(slave).Is(ACTIVE));
        EXPECT_LT(p.root->GetNode(slave).GetValue(NORMAL_CONTACT_STRESS), 0.0);
    }
    // Force balance: the contact forces of the slave nodes carry the load of the top nodes to the bottom ones.
    const double top = p.R(7, 1) + p.R(8, 1), contact = p.R(3, 1) + p.R(4, 1), bottom = p.R(1, 1) + p.R(2, 1);
    EXPECT_LT(top, 0.0);
    EXPECT_NEAR(contact / top, 1.0, 1e-9);
    EXPECT_NEAR(bottom / top, -1.0, 1e-9);
    EXPECT_NEAR(p.U(5, 0), -p.U(6, 0), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(ResidualBasedNewtonRaphsonMPCContactStrategy, MPCPatchVariants,
                         ::testing::Values(std::make_tuple(false, false), std::make_tuple(true, false),
                                           std::make_tuple(false, true)));

TEST(ResidualBasedNewtonRaphsonMPCContactStrategy, PullingApartReleasesTheContactWithinTheStep) {
    TwoBlockPatch p(0.2, false, false);
    ASSERT_TRUE(p.converged);
    EXPECT_GE(p.strategy->GetIterationNumber(), 2);  // the first iteration drags the slave up, the set then changes
    for (IndexType n : {3, 4}) {
        EXPECT_FALSE(p.root->GetNode(n).Is(ACTIVE));
        EXPECT_NEAR(p.U(n, 0), 0.0, 1e-12);
        EXPECT_NEAR(p.U(n, 1), 0.0, 1e-12);
    }
    for (IndexType n : {5, 6}) EXPECT_NEAR(p.U(n, 1), 0.2, 1e-12);  // the free upper block translates
    EXPECT_FALSE(p.root->GetMasterSlaveConstraint(1).Is(ACTIVE));
    EXPECT_FALSE(p.root->GetSubModelPart("ComputingContact").GetCondition(20).Is(ACTIVE));
}

/// A slipping node's test row carries the Coulomb force with the normal constraint force of the current state:
/// after a press, the slave nodes 3 and 4 slip along +x (μ = 0.3) while the masters are sheared. The reduced
/// system of the builder, WᵀAT and Wᵀb, is compared with the Coulomb equilibrium written out: every slave's
/// constraint force λn + f with f = −μλe, λ from the normal component of its equilibrium (r + f + λn)·y = 0, the
/// masters loaded by −Q f; G = Tᵀ(r + F). Its tangent is checked against central differences of G (slaves
/// following u_s = T u_m + c).
TEST(ResidualBasedNewtonRaphsonMPCContactStrategy, SlipTestRowsGiveTheCoulombResidualAndItsTangent) {
    TwoBlockPatch p(-0.2, false, false);
    ASSERT_TRUE(p.converged);
    ModelPart& root = *p.root;
    const ProcessInfo& info = root.GetProcessInfo();
    auto pair = root.GetSubModelPart("ComputingContact").pGetCondition(20);
    const double mu = 0.3;
    pair->Set(SLIP, true);
    for (IndexType n : {3, 4}) {
        root.GetNode(n).Set(SLIP, true);
        root.GetNode(n).SetValue(FRICTION_COEFFICIENT, mu);
        root.GetNode(n).SetValue(TANGENT_XI, Array3(1.0, 0.0, 0.0));
    }
    pair->InitializeSolutionStep(info);
    MasterSlaveConstraint* constraint = &root.GetMasterSlaveConstraint(1);
    Matrix W;
    ASSERT_TRUE(constraint->CalculateTestRelation(W, info));
    root.GetNode(5).FastGetSolutionStepValue(DISPLACEMENT)[0] += 1.0e-3;
    root.GetNode(6).FastGetSolutionStepValue(DISPLACEMENT)[0] += 2.0e-3;
    constraint->Apply(info);

    EliminationBuilderAndSolver builder(CreateLinearSolver({}));
    Scheme scheme;
    builder.SetUpDofSet(scheme, root);
    builder.SetUpSystem(root);
    SparseMatrixType A;
    SystemVectorType dx, b;
    builder.ResizeAndInitializeVectors(scheme, A, dx, b, root);
    builder.Build(scheme, root, A, b);
    builder.ApplyConstraints(scheme, root, A, b);
    const Eigen::MatrixXd reduced(A);
    const auto size = static_cast<Eigen::Index>(builder.GetEquationSystemSize());

    // G = Tᵀ(r + F) from the assembled residual r of the current state.
    auto coulomb_residual = [&] {
        SystemVectorType r;
        builder.BuildRHS(scheme, root, r);
        Matrix T;
        Vector c;
        EquationIdVectorType slaves, masters;
        constraint->CalculateLocalSystem(T, c, info);
        constraint->EquationIdVector(slaves, masters, info);
        Eigen::VectorXd F = Eigen::VectorXd::Zero(size);
        for (std::size_t s = 0; s < slaves.size(); ++s) {
            const Dof* dof = constraint->GetSlaveDofsVector()[s];
            const Node& node = dof->GetNode();
            const Eigen::Vector2d n = node.FastGetSolutionStepValue(NORMAL).head<2>();
            const double lambda = -r[static_cast<Eigen::Index>(slaves[s])] / n[1];  // e·y = 0
            const double f = -mu * lambda;                                           // along e = +x
            F[static_cast<Eigen::Index>(node.GetDof(DISPLACEMENT_X).EquationId())] += f;
            for (std::size_t m = 0; m < masters.size(); ++m) {  // Q from the y columns of T (weight 1, n_y / n_y)
                const Dof* master = constraint->GetMasterDofsVector()[m];
                if (&master->GetVariable() != &DISPLACEMENT_Y || master->GetNode().Is(SLAVE)) continue;
                F[static_cast<Eigen::Index>(master->GetNode().GetDof(DISPLACEMENT_X).EquationId())] -=
                    T(static_cast<Eigen::Index>(s), static_cast<Eigen::Index>(m)) * f;
            }
        }
        Eigen::VectorXd G = r + F;
        for (std::size_t s = 0; s < slaves.size(); ++s)
            for (std::size_t m = 0; m < masters.size(); ++m)
                if (masters[m] < static_cast<std::size_t>(size))
                    G[static_cast<Eigen::Index>(masters[m])] +=
                        T(static_cast<Eigen::Index>(s), static_cast<Eigen::Index>(m)) *
                        (r[static_cast<Eigen::Index>(slaves[s])]);  // F has no y component on the slave
        for (std::size_t s = 0; s < slaves.size(); ++s) G[static_cast<Eigen::Index>(slaves[s])] = 0.0;
        return G;
    };
    const Eigen::VectorXd G = coulomb_residual();
    EXPECT_GT(G.norm(), 1.0);
    EXPECT_LT((Eigen::VectorXd(b) - G).cwiseAbs().maxCoeff(), 1e-9 * G.cwiseAbs().maxCoeff());

    std::vector<char> is_slave(static_cast<std::size_t>(size), 0);
    EquationIdVectorType slaves, masters;
    constraint->EquationIdVector(slaves, masters, info);
    for (auto id : slaves) is_slave[id] = 1;
    const double h = 1.0e-6;
    double error = 0.0;
    for (Dof* dof : builder.GetDofSet()) {
        const auto k = static_cast<Eigen::Index>(dof->EquationId());
        if (k >= size || is_slave[static_cast<std::size_t>(k)]) continue;
        dof->GetSolutionStepValue() += h;
        constraint->Apply(info);
        const Eigen::VectorXd plus = coulomb_residual();
        dof->GetSolutionStepValue() -= 2.0 * h;
        constraint->Apply(info);
        const Eigen::VectorXd minus = coulomb_residual();
        dof->GetSolutionStepValue() += h;
        constraint->Apply(info);
        const Eigen::VectorXd column = -(plus - minus) / (2.0 * h);
        for (Eigen::Index row = 0; row < size; ++row)
            if (!is_slave[static_cast<std::size_t>(row)])
                error = std::max(error, std::abs(column[row] - reduced(row, k)));
    }
    EXPECT_LT(error, 1e-6 * reduced.cwiseAbs().maxCoeff()) << "max |WᵀAT − (−dG/dũ)| = " << error;
}

}  // namespace
}  // namespace contact_app::testing
