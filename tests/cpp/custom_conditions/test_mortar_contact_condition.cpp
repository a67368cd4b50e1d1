// SPDX-License-Identifier: BSD-3-Clause
/// MortarContactCondition base: what only the families can do raises InternalError; settings are read.
#include "contact_condition_test_utilities.h"

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
    EXPECT_EQ(segmentation.distance_threshold, 0.5);
    EXPECT_EQ(segmentation.zero_tolerance_factor, 3.0);
    EXPECT_TRUE(segmentation.consider_tessellation);
    EXPECT_EQ(base->SegmentationSettingsFrom(ProcessInfo{}).distance_threshold, 1.0e24);
}

}  // namespace
}  // namespace contact_app::testing
