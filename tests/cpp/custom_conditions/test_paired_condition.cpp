// SPDX-License-Identifier: BSD-3-Clause
/// PairedCondition: slave/master roles, the three Create overloads, the paired normal and the unpaired Check().
#include "contact_condition_test_utilities.h"

#include "contact_app/kernel/exceptions.h"
#include "tests/cpp/error_test_utilities.h"

namespace contact_app::testing {
namespace {

class RegisteredPairNames : public ::testing::TestWithParam<std::string> {};

TEST_P(RegisteredPairNames, CheckWithoutMasterGeometryNamesTheCondition) {
    ContactPairModel model;
    const auto& row = DecodedName(GetParam());
    Geometry::PointsArrayType nodes;
    for (int i = 0; i < row.num_slave; ++i) {
        Eigen::VectorXd x = Eigen::VectorXd::Zero(3);
        x[0] = i;
        x[1] = i * i;
        nodes.push_back(model.part->pGetNode(model.AddNode(i + 1, x).Id()));
    }
    const auto& prototype = Registry<Condition>::Instance().Get(GetParam());
    // The .mdpa path: Create(id, nodes, properties) has no master face.
    auto condition = std::dynamic_pointer_cast<PairedCondition>(prototype.Create(7, nodes, model.properties));
    ASSERT_TRUE(condition);
    EXPECT_FALSE(condition->HasPairedGeometry());
    EXPECT_EQ(condition->GetParentGeometry().size(), static_cast<std::size_t>(row.num_slave));
    ExpectError<InputError>([&] { condition->Check(ProcessInfo{}); },
                            {"condition 7", "no paired master geometry", "fix:"});
}

TEST(PairedCondition, RolesCreateOverloadsAndPairedNormal) {
    ContactPairModel model;
    Eigen::MatrixXd s(2, 2), m(2, 2);
    s << 1.0, 0.0, 0.0, 0.0;
    m << 0.0, 0.1, 1.0, 0.1;
    auto pair = model.MakePair("ALMFrictionlessMortarContactCondition2D2N", s, m, 3);
    ASSERT_TRUE(pair->HasPairedGeometry());
    EXPECT_EQ(pair->GetParentGeometry()[0].Id(), 1u);
    EXPECT_EQ(pair->GetPairedGeometry()[0].Id(), 3u);
    // Create(id, coupling geometry, properties) keeps both faces and the class.
    auto copy = std::dynamic_pointer_cast<PairedCondition>(pair->Create(4, pair->pGetGeometry(), model.properties));
    ASSERT_TRUE(copy);
    EXPECT_EQ(copy->GetPairedGeometry()[1].Id(), 4u);
    EXPECT_EQ(typeid(*copy), typeid(*pair));
    ProcessInfo info;
    pair->Initialize(info);
    EXPECT_NEAR(pair->GetPairedNormal()[1], -1.0, 1e-14);  // master runs left to right: normal −y
    // Without normal variation the master normal is frozen inside the Newton loop ...
    model.part->GetNode(4).Coordinates()[1] = 1.1;  // tilt the master
    pair->InitializeNonLinearIteration(info);
    EXPECT_NEAR(pair->GetPairedNormal()[1], -1.0, 1e-14);
    // ... and follows the deformation with CONSIDER_NORMAL_VARIATION ≠ 0.
    info.SetValue(CONSIDER_NORMAL_VARIATION, 2);
    pair->InitializeNonLinearIteration(info);
    EXPECT_GT(pair->GetPairedNormal()[0], 0.5);
    pair->InitializeSolutionStep(ProcessInfo{});
    EXPECT_GT(pair->GetPairedNormal()[0], 0.5);
}

INSTANTIATE_TEST_SUITE_P(Registered, RegisteredPairNames, ::testing::ValuesIn(RegisteredContactNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace contact_app::testing
