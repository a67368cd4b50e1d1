// SPDX-License-Identifier: BSD-3-Clause
/// MPCContactCriteria: activation from the reaction (compression) or the gap (penetration), deactivation under
/// tension with an open gap, flips counted, pairs and constraints switched with their slave nodes, the lumped area,
/// the frictional stick/slip test (forces compared with forces) and the output variables.
#include <gtest/gtest.h>

#include "contact_app/application.h"
#include "contact_app/solving/builder_and_solvers/elimination_builder_and_solver.h"
#include "contact_app/solving/linear_solvers/linear_solver_factory.h"
#include "custom_conditions/mpc_mortar_contact_condition.h"
#include "custom_strategies/contact_master_slave_constraint.h"
#include "custom_strategies/mpc_contact_criteria.h"
#include "../custom_conditions/tying_test_utilities.h"

namespace contact_app::testing {
namespace {

/// One 2D MPC pair (slave nodes 1, 2 on y = 0, x ∈ [0, 2]; master nodes 3, 4 at y = gap) in "ComputingContact",
/// the slave face in "Contact" (SLAVE), both slave nodes ACTIVE with NODAL_PAUX = 1.
struct MPCCriteriaFixture {
    explicit MPCCriteriaFixture(double gap) {
        Eigen::MatrixXd s(2, 2), m(2, 2);
        s << 2, 0, 0, 0;
        m << 0, gap, 2, gap;
        pair = model.MakePair("MPCMortarContactCondition2D2N", s, m);
        constraint = std::make_shared<ContactMasterSlaveConstraint>(1);
        pair->SetValue(CONSTRAINT_POINTER, std::shared_ptr<MasterSlaveConstraint>(constraint));
        ModelPart& root = *model.part;
        ModelPart& contact = root.CreateSubModelPart("Contact");
        ModelPart& computing = root.CreateSubModelPart("ComputingContact");
        auto face = std::make_shared<Condition>(10, pair->pGetParentGeometry(), model.properties);
        face->Set(SLAVE, true);
        contact.AddCondition(face);
        for (IndexType id : {1, 2}) {
            Node& node = root.GetNode(id);
            node.Set(SLAVE, true);
            node.Set(ACTIVE, true);
            node.SetValue(NODAL_PAUX, 1.0);
            contact.AddNode(root.pGetNode(id));
        }
        for (IndexType id : {3, 4}) root.GetNode(id).Set(MASTER, true);
        computing.AddCondition(pair);
        constraint->Set(ACTIVE, true);
        pair->Set(ACTIVE, true);
        pair->Initialize(root.GetProcessInfo());
        root.GetProcessInfo().SetValue(NL_ITERATION_NUMBER, 1);
    }
    Node& SlaveNode(IndexType id) { return model.part->GetNode(id); }
    Array3 Normal(IndexType id) { return SlaveNode(id).FastGetSolutionStepValue(NORMAL); }
    /// REACTION of slave node @p id = normal_force n + tangential_force t (t ⊥ n in the plane).
    void SetForce(IndexType id, double normal_force, double tangential_force = 0.0) {
        const Array3 n = Normal(id);
        const Array3 t(-n[1], n[0], 0.0);
        SlaveNode(id).FastGetSolutionStepValue(REACTION) = normal_force * n + tangential_force * t;
    }
    /// "Contact" frictional, both slave nodes sticking with FRICTION_COEFFICIENT @p mu.
    void MakeFrictional(double mu) {
        model.part->GetSubModelPart("Contact").Set(SLIP, true);
        for (IndexType id : {1, 2}) {
            SlaveNode(id).SetValue(FRICTION_COEFFICIENT, mu);
            SlaveNode(id).Set(SLIP, false);
        }
    }
    bool Post() {
        ModelPart& root = *model.part;
        DofsArrayType dofs;
        const SparseMatrixType A;
        const SystemVectorType x;
        criteria.PreCriteria(root, dofs, A, x, x);
        const EliminationBuilderAndSolver builder(CreateLinearSolver(LinearSolverSettings{}));
        return criteria.PostCriteria(root, dofs, A, x, x, builder);
    }

    TyingPairModel model;
    std::shared_ptr<PairedCondition> pair;
    std::shared_ptr<ContactMasterSlaveConstraint> constraint;
    MPCContactCriteria criteria;
};

TEST(MPCContactCriteria, CompressedNodesStayActiveAndTheSetConverges) {
    MPCCriteriaFixture f(0.0);
    f.SetForce(1, -3.0);
    f.SetForce(2, -1.0);
    EXPECT_TRUE(f.Post());
    EXPECT_EQ(f.criteria.LastActiveFlips(), 0u);
    EXPECT_EQ(f.criteria.ActiveNodes(), 2u);
    EXPECT_TRUE(f.SlaveNode(1).Is(ACTIVE) && f.SlaveNode(2).Is(ACTIVE));
    EXPECT_TRUE(f.pair->Is(ACTIVE) && f.constraint->Is(ACTIVE));
    // Lumped slave area: half of the face length (2) per node; p = (F·n)/NODAL_MAUX.
    EXPECT_NEAR(f.SlaveNode(1).GetValue(NODAL_MAUX), 1.0, 1e-14);
    EXPECT_NEAR(f.SlaveNode(1).GetValue(NORMAL_CONTACT_STRESS), -3.0, 1e-12);
    EXPECT_NEAR(f.SlaveNode(2).GetValue(NORMAL_CONTACT_STRESS), -1.0, 1e-12);
    // Frictionless CONTACT_FORCE = (F·n) n / NODAL_PAUX.
    EXPECT_NEAR((f.SlaveNode(1).GetValue(CONTACT_FORCE) - (-3.0) * f.Normal(1)).norm(), 0.0, 1e-12);
}

TEST(MPCContactCriteria, TensionWithAnOpenGapDeactivatesNodesPairAndConstraint) {
    MPCCriteriaFixture f(0.01);  // open gap: the gap cannot keep the nodes active
    f.SetForce(1, 2.0);
    f.SetForce(2, -1.0);
    EXPECT_FALSE(f.Post());
    EXPECT_EQ(f.criteria.LastActiveFlips(), 1u);
    EXPECT_FALSE(f.SlaveNode(1).Is(ACTIVE));
    EXPECT_TRUE(f.SlaveNode(2).Is(ACTIVE));
    EXPECT_TRUE(f.pair->Is(ACTIVE) && f.constraint->Is(ACTIVE));  // one slave node is still active
    EXPECT_GT(f.SlaveNode(1).FastGetSolutionStepValue(WEIGHTED_GAP), 0.0);

    f.SetForce(2, 0.5);
    EXPECT_FALSE(f.Post());
    EXPECT_EQ(f.criteria.LastActiveFlips(), 1u);
    EXPECT_EQ(f.criteria.ActiveNodes(), 0u);
    EXPECT_FALSE(f.pair->Is(ACTIVE));
    EXPECT_FALSE(f.constraint->Is(ACTIVE));
    EXPECT_EQ(f.SlaveNode(2).GetValue(CONTACT_FORCE).norm(), 0.0);

    // Inactive nodes carry no contact force: a stale compressive reaction does not reactivate them.
    f.SetForce(1, -5.0);
    f.SetForce(2, -5.0);
    EXPECT_TRUE(f.Post());
    EXPECT_EQ(f.criteria.ActiveNodes(), 0u);
}

TEST(MPCContactCriteria, PenetrationActivatesInactiveNodes) {
    MPCCriteriaFixture f(-0.01);  // master below the slave: negative gap
    for (IndexType id : {1, 2}) f.SlaveNode(id).Set(ACTIVE, false);
    f.pair->Set(ACTIVE, false);
    f.constraint->Set(ACTIVE, false);
    EXPECT_FALSE(f.Post());
    EXPECT_EQ(f.criteria.LastActiveFlips(), 2u);
    EXPECT_LT(f.SlaveNode(1).FastGetSolutionStepValue(WEIGHTED_GAP), 0.0);
    EXPECT_TRUE(f.SlaveNode(1).Is(ACTIVE) && f.SlaveNode(2).Is(ACTIVE));
    EXPECT_TRUE(f.pair->Is(ACTIVE) && f.constraint->Is(ACTIVE));
}

TEST(MPCContactCriteria, TensionReleasesAnActiveNodeOverTheDriftOfItsClosedGap) {
    // With a Young's modulus the set is decided on p̄ = p + (E/h) g̃/A: the constraint keeps an active node's gap
    // closed only up to the drift of the iterate (here −1e-8), which must not hold a node in tension (it did when a
    // penetration alone kept a node active: an edge node of the Cattaneo–Mindlin 2D level 3 at p = +117); an inactive
    // node still comes in by the same small penetration, and a real penetration keeps even a pulled node.
    for (const double gap : {-1.0e-8, -1.0e-2}) {
        MPCCriteriaFixture f(gap);
        ModelPart& root = *f.model.part;
        auto properties = root.CreateNewProperties(2);
        properties->SetValue(YOUNG_MODULUS, 1.0e3);
        root.AddElement(std::make_shared<Element>(1, f.pair->pGetParentGeometry(), properties));
        f.SetForce(1, 2.0);  // tension
        f.SlaveNode(2).Set(ACTIVE, false);
        EXPECT_FALSE(f.Post());
        EXPECT_LT(f.SlaveNode(1).FastGetSolutionStepValue(WEIGHTED_GAP), 0.0);
        EXPECT_EQ(f.SlaveNode(1).Is(ACTIVE), gap < -1.0e-3) << gap;
        EXPECT_TRUE(f.SlaveNode(2).Is(ACTIVE)) << gap;
    }
}

TEST(MPCContactCriteria, TensionToleranceScalesWithTheYoungModulus) {
    MPCCriteriaFixture f(0.01);
    ModelPart& root = *f.model.part;
    root.GetProcessInfo().SetValue(REACTION_CHECK_STIFFNESS_FACTOR, 1.0e-3);
    // No element: E = 0, any compression keeps a node active.
    f.SetForce(1, -1.0e-6);
    f.SetForce(2, -1.0e-6);
    EXPECT_TRUE(f.Post());
    EXPECT_EQ(f.criteria.ActiveNodes(), 2u);
    // E = 1e3: the tolerance is −1 (traction); −1e-6 is not enough compression, −2 is.
    auto properties = root.CreateNewProperties(2);
    properties->SetValue(YOUNG_MODULUS, 1.0e3);
    root.AddElement(std::make_shared<Element>(1, f.pair->pGetParentGeometry(), properties));
    f.SetForce(2, -2.0);
    EXPECT_FALSE(f.Post());
    EXPECT_EQ(f.criteria.LastActiveFlips(), 1u);
    EXPECT_FALSE(f.SlaveNode(1).Is(ACTIVE));
    EXPECT_TRUE(f.SlaveNode(2).Is(ACTIVE));
}

TEST(MPCContactCriteria, NothingIsJudgedBeforeTheFirstIteration) {
    MPCCriteriaFixture f(0.01);
    f.model.part->GetProcessInfo().SetValue(NL_ITERATION_NUMBER, 0);
    f.SetForce(1, 2.0);
    f.SetForce(2, 2.0);
    EXPECT_TRUE(f.Post());
    EXPECT_TRUE(f.SlaveNode(1).Is(ACTIVE) && f.SlaveNode(2).Is(ACTIVE));
}

TEST(MPCContactCriteria, FrictionalStickSlipComparesForcesWithForces) {
    MPCCriteriaFixture f(0.0);
    f.MakeFrictional(0.5);
    // |F_τ| = 0.3 ≤ μ|F·n| = 0.5: stick; |F_τ| = 0.7 > 0.5: slip.
    f.SetForce(1, -1.0, 0.3);
    f.SetForce(2, -1.0, 0.7);
    EXPECT_FALSE(f.Post());
    EXPECT_EQ(f.criteria.LastActiveFlips(), 0u);
    EXPECT_EQ(f.criteria.LastSlipFlips(), 1u);
    EXPECT_EQ(f.criteria.SlipNodes(), 1u);
    EXPECT_FALSE(f.SlaveNode(1).Is(SLIP));
    EXPECT_TRUE(f.SlaveNode(2).Is(SLIP));
    // Tractions (NODAL_MAUX = 1 here, so the values are also the forces): stick |F_τ|/A, slip −μ (F·n)/A.
    EXPECT_NEAR(f.SlaveNode(1).GetValue(TANGENTIAL_CONTACT_STRESS), 0.3, 1e-12);
    EXPECT_NEAR(f.SlaveNode(2).GetValue(TANGENTIAL_CONTACT_STRESS), 0.5, 1e-12);
    // Frictional CONTACT_FORCE = (normal force + friction) / NODAL_PAUX: stick, the reaction; slip, the Coulomb force
    // μ|F·n| along the stick force it replaces (0.5 of the 0.7).
    EXPECT_NEAR((f.SlaveNode(1).GetValue(CONTACT_FORCE) - f.SlaveNode(1).FastGetSolutionStepValue(REACTION)).norm(),
                0.0, 1e-12);
    const Array3 reaction = f.SlaveNode(2).FastGetSolutionStepValue(REACTION);
    const Array3 tangential = reaction - reaction.dot(f.SlaveNode(2).FastGetSolutionStepValue(NORMAL)) *
                                             f.SlaveNode(2).FastGetSolutionStepValue(NORMAL);
    EXPECT_NEAR((f.SlaveNode(2).GetValue(CONTACT_FORCE) - (reaction - tangential * (0.2 / 0.7))).norm(), 0.0, 1e-12);
    EXPECT_NEAR((f.SlaveNode(2).GetValue(TANGENT_XI) - tangential / tangential.norm()).norm(), 0.0, 1e-12);
    EXPECT_TRUE(f.Post());  // same forces: no flip
    EXPECT_EQ(f.criteria.LastSlipFlips(), 0u);
}

TEST(MPCContactCriteria, TheStickTestLeavesOutTheSupportReactionOfAPrescribedComponent) {
    // On a symmetry plane the REACTION of a slave node also holds the support's force along the plane's normal; the
    // constraint does not exert it (docs/theory/active_set.md §4). Both nodes: |F_τ| = 0.7 > μ|F·n| = 0.5 along x.
    // Node 1 has DISPLACEMENT_X prescribed: that reaction is the support's, and the node sticks.
    MPCCriteriaFixture f(0.0);
    f.MakeFrictional(0.5);
    for (IndexType id : {1, 2}) f.SetForce(id, -1.0, 0.7);
    ASSERT_NEAR(std::abs(f.SlaveNode(1).FastGetSolutionStepValue(REACTION)[0]), 0.7, 1e-12);  // the tangent is x
    f.SlaveNode(1).Fix(DISPLACEMENT_X);
    f.Post();
    EXPECT_FALSE(f.SlaveNode(1).Is(SLIP));
    EXPECT_TRUE(f.SlaveNode(2).Is(SLIP));
    EXPECT_EQ(f.criteria.LastSlipFlips(), 1u);
    // The friction written for node 1 has no component along the prescribed direction.
    EXPECT_NEAR(f.SlaveNode(1).GetValue(TANGENTIAL_CONTACT_STRESS), 0.0, 1e-12);
    EXPECT_NEAR(f.SlaveNode(1).GetValue(CONTACT_FORCE)[0], 0.0, 1e-12);
}

TEST(MPCContactCriteria, StickTestUsesTheLumpedAreaConsistently) {
    // Slave face of length 2 → NODAL_MAUX = 1; scale the face to length 8 → NODAL_MAUX = 4: the verdict must not
    // change (a traction compared with a force, the reference's B9, would flip it).
    MPCCriteriaFixture f(0.0);
    ModelPart& root = *f.model.part;
    root.GetSubModelPart("Contact").Set(SLIP, true);
    for (IndexType id : {1, 2, 3, 4}) {
        Node& node = root.GetNode(id);
        node.Coordinates() *= 4.0;
        node.SetValue(FRICTION_COEFFICIENT, 0.5);
    }
    f.SetForce(1, -1.0, 0.4);
    f.SetForce(2, -1.0, 0.6);
    f.Post();
    EXPECT_NEAR(f.SlaveNode(1).GetValue(NODAL_MAUX), 4.0, 1e-12);
    EXPECT_FALSE(f.SlaveNode(1).Is(SLIP));
    EXPECT_TRUE(f.SlaveNode(2).Is(SLIP));
    EXPECT_NEAR(f.SlaveNode(1).GetValue(NORMAL_CONTACT_STRESS), -0.25, 1e-12);
}

TEST(MPCContactCriteria, MissingContactPartIsAnInputError) {
    RegisterContactApplication();
    Model model;
    ModelPart& part = model.CreateModelPart("Structure");
    part.GetProcessInfo().SetValue(NL_ITERATION_NUMBER, 1);
    MPCContactCriteria criteria;
    DofsArrayType dofs;
    const SparseMatrixType A;
    const SystemVectorType x;
    const EliminationBuilderAndSolver builder(CreateLinearSolver(LinearSolverSettings{}));
    EXPECT_THROW(criteria.PostCriteria(part, dofs, A, x, x, builder), InputError);
}

}  // namespace
}  // namespace contact_app::testing
