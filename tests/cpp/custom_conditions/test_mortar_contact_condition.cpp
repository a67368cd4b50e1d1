// SPDX-License-Identifier: BSD-3-Clause
/// MortarContactCondition base: what only the families can do raises InternalError; settings are read.
#include "contact_condition_test_utilities.h"

#include <limits>

#include "contact_app/kernel/exceptions.h"
#include "custom_conditions/mortar_contact_condition.h"

namespace contact_app::testing {
namespace {

using Base = MortarContactCondition<2, 2, FrictionalCase::FRICTIONLESS, false, 2>;

std::shared_ptr<Base> MakeBase(ContactPairModel& model) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(3);
    Geometry::PointsArrayType s, m;
    for (int i = 0; i < 4; ++i) {
        x[0] = i % 2;
        x[1] = i / 2 * 0.1;
        model.AddNode(i + 1, x);
    }
    s = {model.part->pGetNode(2), model.part->pGetNode(1)};
    m = {model.part->pGetNode(3), model.part->pGetNode(4)};
    return std::make_shared<Base>(1, CreateGeometry("Line2D2", s), model.properties, CreateGeometry("Line2D2", m));
}

TEST(MortarContactCondition, FamilyOnlyMethodsRaiseInternalError) {
    ContactPairModel model;
    auto base = MakeBase(model);
    ProcessInfo info;
    EquationIdVectorType ids;
    DofsVectorType dofs;
    Matrix lhs;
    Vector rhs;
    EXPECT_THROW(base->EquationIdVector(ids, info), InternalError);
    EXPECT_THROW(base->GetDofList(dofs, info), InternalError);
    EXPECT_THROW(base->GetActiveInactiveValue(), InternalError);
    EXPECT_THROW(base->CalculateLocalSystem(lhs, rhs, info), InternalError);
    EXPECT_EQ(Base::MatrixSize, 10);
}

TEST(MortarContactCondition, SettingsComeFromPropertiesAndProcessInfo) {
    ContactPairModel model;
    auto base = MakeBase(model);
    EXPECT_EQ(base->IntegrationSettings().integration_order, 2);
    model.properties->SetValue(INTEGRATION_ORDER_CONTACT, 4);
    model.properties->SetValue(CONSIDER_TESSELLATION, true);
    ProcessInfo info;
    info.SetValue(DISTANCE_THRESHOLD, 0.5);
    info.SetValue(ZERO_TOLERANCE_FACTOR, 3.0);
    EXPECT_EQ(base->IntegrationSettings().integration_order, 4);
    EXPECT_EQ(base->IntegrationSettings().axisymmetric_thickness, 0.0);
    const SegmentationSettings segmentation = base->SegmentationSettingsFrom(info);
    // The master line lies 0.1 in front of the slave: within 0.5, so no master node fails the rule in this step.
    EXPECT_EQ(segmentation.distance_threshold, std::numeric_limits<double>::infinity());
    EXPECT_EQ(segmentation.zero_tolerance_factor, 3.0);
    EXPECT_TRUE(segmentation.consider_tessellation);
    EXPECT_EQ(base->SegmentationSettingsFrom(ProcessInfo{}).distance_threshold, 1.0e24);
    info.SetValue(DISTANCE_THRESHOLD, 0.05);  // beyond: every master node fails it
    EXPECT_EQ(base->SegmentationSettingsFrom(info).distance_threshold, -std::numeric_limits<double>::infinity());
}

/// The distance rule is decided on the start-of-step configuration (buffer 1), so an iterate that moves the master
/// beyond the threshold, or back within it, does not switch the pair on or off inside the step (docs/theory/mortar.md
/// §1 "The distance rule").
TEST(MortarContactCondition, DistanceRuleIsDecidedOnTheStartOfStepConfiguration) {
    ContactPairModel model;
    model.part->SetBufferSize(2);
    auto base = MakeBase(model);
    ProcessInfo info;
    info.SetValue(DISTANCE_THRESHOLD, 0.15);
    const double within = std::numeric_limits<double>::infinity();
    EXPECT_EQ(base->SegmentationSettingsFrom(info).distance_threshold, within);
    // An iterate lifts the master by 0.2 (current DISPLACEMENT and coordinates): the step's verdict stands.
    for (IndexType id : {3, 4}) {
        Node& node = model.part->GetNode(id);
        node.FastGetSolutionStepValue(DISPLACEMENT)[1] = 0.2;
        node.Coordinates()[1] += 0.2;
    }
    EXPECT_EQ(base->SegmentationSettingsFrom(info).distance_threshold, within);
    // The step converges there and the next one starts from it: now the master is beyond.
    model.part->CloneTimeStep(1.0);
    EXPECT_EQ(base->SegmentationSettingsFrom(info).distance_threshold, -within);
}

}  // namespace
}  // namespace contact_app::testing
