// SPDX-License-Identifier: BSD-3-Clause
// ContactUtilities: nodal size statistics, activity checks, step jump, explicit refresh of the weighted gap,
// multipliers held on symmetry planes.
#include <gtest/gtest.h>

#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/model.h"
#include "custom_utilities/active_set_utilities.h"
#include "custom_utilities/contact_utilities.h"
#include "tests/cpp/custom_conditions/contact_condition_test_utilities.h"

namespace contact_app {
namespace {

TEST(ContactUtilities, test_nodal_size_statistics_and_activity) {
    RegisterContactApplication();
    Model model;
    ModelPart& part = model.CreateModelPart("Structure");
    const double sizes[] = {0.5, 2.0, 1.0};
    for (int i = 0; i < 3; ++i) {
        auto node = part.CreateNewNode(i + 1, i, 0, 0);
        node->SetValue(NODAL_H, sizes[i]);
        node->Set(SLAVE, true);
    }
    EXPECT_DOUBLE_EQ(ContactUtilities::CalculateMaxNodalH(part), 2.0);
    EXPECT_DOUBLE_EQ(ContactUtilities::CalculateMinimalNodalH(part), 0.5);
    EXPECT_DOUBLE_EQ(ContactUtilities::CalculateMeanNodalH(part), 3.5 / 3.0);
    EXPECT_DOUBLE_EQ(ContactUtilities::CalculateRelativeSizeMesh(part), 4.0);
    EXPECT_FALSE(ContactUtilities::CheckActivity(part, false));
    EXPECT_THROW(ContactUtilities::CheckActivity(part), ConvergenceError);
    part.GetNode(2).Set(ACTIVE, true);
    EXPECT_TRUE(ContactUtilities::CheckActivity(part));
    EXPECT_FALSE(ContactUtilities::CheckModelPartHasRotationDoF(part));
    Array3 point(1, 2, 3);
    ContactUtilities::ScaleNode(point, Array3(0, 0, 1), 2.0);
    EXPECT_EQ(point, Array3(1, 2, 5));
    EXPECT_DOUBLE_EQ(ContactUtilities::DistancePoints(Array3(0, 0, 0), Array3(3, 4, 0)), 5.0);
}

TEST(ContactUtilities, test_step_jump_of_a_dynamic_node) {
    RegisterContactApplication();
    Model model;
    ModelPart& part = model.CreateModelPart("Structure", 2);
    part.AddNodalSolutionStepVariable(DISPLACEMENT);
    part.AddNodalSolutionStepVariable(VELOCITY);
    part.AddNodalSolutionStepVariable(ACCELERATION);
    auto node = part.CreateNewNode(1, 0, 0, 0);
    node->GetSolutionStepValue(VELOCITY, 0) = Array3(1, 2, 0);
    node->GetSolutionStepValue(VELOCITY, 1) = Array3(3, 0, 0);
    node->GetSolutionStepValue(ACCELERATION, 1) = Array3(0, 8, 0);
    node->Fix(DISPLACEMENT_Z);
    const double dt = 0.5;
    ContactUtilities::ComputeStepJump(part, dt, true);
    const Array3 half = 0.25 * dt * Array3(4, 2, 0) + 0.125 * dt * dt * Array3(0, 8, 0);
    EXPECT_LT((node->GetValue(DELTA_COORDINATES) - half).norm(), 1e-15);
    node->GetSolutionStepValue(VELOCITY, 0) = Array3(1, 2, 7);
    ContactUtilities::ComputeStepJump(part, dt, false);
    const Array3 full = 0.5 * dt * Array3(4, 2, 0) + 0.5 * dt * dt * Array3(0, 8, 0);  // z fixed
    EXPECT_LT((node->GetValue(DELTA_COORDINATES) - full).norm(), 1e-15);
    // Centre of a line moved by the mean of its nodal jumps (N_i = 1/2 at the centre).
    auto other = part.CreateNewNode(2, 2, 0, 0);
    other->SetValue(DELTA_COORDINATES, Array3(0, 0, 1));
    const auto line = CreateGeometry("Line2D2", {node, other});
    EXPECT_LT((ContactUtilities::GetHalfJumpCenter(*line) - (Array3(1, 0, 0) + 0.5 * (full + Array3(0, 0, 1)))).norm(),
              1e-15);
}

TEST(ContactUtilities, test_explicit_refresh_of_the_weighted_gap_of_a_pair) {
    testing::ContactPairModel pair_model;
    const double g = 0.01;
    Eigen::MatrixXd s(2, 2), m(2, 2);
    s << 3.0, 0.0, 2.0, 0.0;  // slave normal +y, length 1
    m << 2.0, g, 3.0, g;
    auto pair = pair_model.MakePair("ALMFrictionlessMortarContactCondition2D2N", s, m);
    pair_model.properties->SetValue(THICKNESS, 1.0);
    ModelPart& part = *pair_model.part;
    part.AddCondition(pair);
    pair->SetValue(NORMAL, Array3(0, 1, 0));
    for (IndexType id : {1, 2}) {
        part.GetNode(id).FastGetSolutionStepValue(NORMAL) = Array3(0, 1, 0);
        part.GetNode(id).FastGetSolutionStepValue(WEIGHTED_GAP) = 7.0;  // stale values are cleared first
        part.GetNode(id).SetValue(NODAL_AREA, 3.0);
    }
    pair->Initialize(part.GetProcessInfo());
    ContactUtilities::ComputeExplicitContributionConditions(part);
    for (IndexType id : {1, 2}) {
        EXPECT_NEAR(part.GetNode(id).FastGetSolutionStepValue(WEIGHTED_GAP), 0.5 * g, 1e-14);  // g ∫N_j over length 1
        EXPECT_NEAR(part.GetNode(id).GetValue(NODAL_AREA), 0.5, 1e-14);  // ∫N_j of the pair, every family
        EXPECT_NEAR(part.GetNode(id).GetValue(AREA_WEIGHTED_PAIR_GAP), 0.25 * g, 1e-14);
        EXPECT_NEAR(ContactUtilities::TransmittedWeightedGap(part.GetNode(id)), 0.5 * g, 1e-14);
    }
    part.GetNode(1).Set(ACTIVE, true);
    ContactUtilities::ActivateConditionWithActiveNodes(part);
    EXPECT_TRUE(pair->Is(ACTIVE));
    part.GetNode(1).Set(ACTIVE, false);
    ContactUtilities::ActivateConditionWithActiveNodes(part);
    EXPECT_FALSE(pair->Is(ACTIVE));
    ContactUtilities::CleanContactModelParts(part);
    EXPECT_EQ(part.NumberOfConditions(), 0u);
}

TEST(ContactUtilities, test_symmetry_plane_holds_the_tangential_multiplier) {
    testing::ContactPairModel pair_model;
    pair_model.part->AddNodalSolutionStepVariable(WEIGHTED_SLIP);  // a frictional interface
    Eigen::MatrixXd s(2, 2), m(2, 2);
    s << 0.0, 0.0, 1.0, 0.0;  // slave 1 at x = 0 (on the plane x = 0), slave 2 at x = 1
    m << 1.2, 0.0, -0.2, 0.0;  // master 3 at x = 1.2, master 4 at x = -0.2: none on x = 0 yet
    auto pair = pair_model.MakePair("ALMFrictionalMortarContactCondition2D2N", s, m);
    ModelPart& part = *pair_model.part;
    part.AddCondition(pair);
    Node& slave = part.GetNode(1);
    slave.FastGetSolutionStepValue(NORMAL) = Array3(0, 1, 0);
    slave.Fix(DISPLACEMENT_X);
    part.GetNode(4).Fix(DISPLACEMENT_X);
    slave.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = Array3(5, 6, 0);
    // No master node on the slave's plane x = 0: the traction may push the masters, the multiplier stays free.
    std::vector<Dof*> fixed = ContactUtilities::FixSymmetryPlaneMultipliers(part, {});
    EXPECT_TRUE(fixed.empty());
    // A held master node on the plane: a symmetry plane through the interface, no x traction there.
    part.GetNode(4).InitialCoordinates()[0] = 0.0;
    fixed = ContactUtilities::FixSymmetryPlaneMultipliers(part, fixed);
    ASSERT_EQ(fixed.size(), 1u);
    EXPECT_TRUE(slave.IsFixed(VECTOR_LAGRANGE_MULTIPLIER_X));
    EXPECT_FALSE(slave.IsFixed(VECTOR_LAGRANGE_MULTIPLIER_Y));
    EXPECT_EQ(slave.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER), Array3(0, 6, 0));
    EXPECT_FALSE(part.GetNode(2).IsFixed(VECTOR_LAGRANGE_MULTIPLIER_X));  // not held itself
    // A held component carries no traction: the slip law's trial direction leaves it out.
    EXPECT_TRUE(ContactUtilities::IsMultiplierComponentHeld(slave, 0));
    EXPECT_FALSE(ContactUtilities::IsMultiplierComponentHeld(slave, 1));
    EXPECT_FALSE(ContactUtilities::IsMultiplierComponentHeld(part.GetNode(2), 0));
    ProcessInfo& info = part.GetProcessInfo();
    info.SetValue(SCALE_FACTOR, 1.0);
    info.SetValue(TANGENT_FACTOR, 1.0);
    info.SetValue(INITIAL_PENALTY, 2.0);
    for (IndexType id : {1, 2}) {
        part.GetNode(id).FastGetSolutionStepValue(NORMAL) = Array3(0, 1, 0);
        part.GetNode(id).FastGetSolutionStepValue(WEIGHTED_SLIP) = Array3(0.5, 0, 0);
    }
    EXPECT_EQ(ActiveSetUtilities::TrialTangentialTraction(slave, info, true), Array3(0, 0, 0));
    EXPECT_EQ(ActiveSetUtilities::TrialTangentialTraction(part.GetNode(2), info, true), Array3(1, 0, 0));
    // A normal across the plane (a roller under a sloped interface): the traction has an x part, nothing is fixed.
    slave.FastGetSolutionStepValue(NORMAL) = Array3(0.2, 1, 0).normalized();
    EXPECT_TRUE(ContactUtilities::FixSymmetryPlaneMultipliers(part, fixed).empty());
    EXPECT_FALSE(slave.IsFixed(VECTOR_LAGRANGE_MULTIPLIER_X));
    slave.FastGetSolutionStepValue(NORMAL) = Array3(0, 1, 0);
    fixed = ContactUtilities::FixSymmetryPlaneMultipliers(part, {});
    ASSERT_EQ(fixed.size(), 1u);
    // The master on the plane is released: the next call frees what the last one fixed.
    part.GetNode(4).Free(DISPLACEMENT_X);
    fixed = ContactUtilities::FixSymmetryPlaneMultipliers(part, fixed);
    EXPECT_TRUE(fixed.empty());
    EXPECT_FALSE(slave.IsFixed(VECTOR_LAGRANGE_MULTIPLIER_X));
    // A multiplier the user fixed is neither reported nor freed.
    part.GetNode(4).Fix(DISPLACEMENT_X);
    slave.Fix(VECTOR_LAGRANGE_MULTIPLIER_X);
    fixed = ContactUtilities::FixSymmetryPlaneMultipliers(part, fixed);
    EXPECT_TRUE(fixed.empty());
    fixed = ContactUtilities::FixSymmetryPlaneMultipliers(part, fixed);
    EXPECT_TRUE(slave.IsFixed(VECTOR_LAGRANGE_MULTIPLIER_X));
}

}  // namespace
}  // namespace contact_app
