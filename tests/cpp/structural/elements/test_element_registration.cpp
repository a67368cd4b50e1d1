// SPDX-License-Identifier: BSD-3-Clause
// The solid-element registry: every name the spec lists exists, and every registered name matches the
// dimension, node count and family of the class behind it (aliases included).
#include <algorithm>

#include <gtest/gtest.h>

#include "contact_app/kernel/registry.h"
#include "solid_element_test_utilities.h"

namespace contact_app::testing {
namespace {

TEST(SolidElementRegistration, EveryExpectedNameIsRegistered) {
    RegisterForSolidTests();
    std::vector<std::string> expected;
    for (const char* family : {"SmallDisplacementElement", "TotalLagrangianElement", "UpdatedLagrangianElement"})
        for (const char* size : {"2D3N", "2D4N", "2D6N", "3D4N", "3D8N", "3D10N"})
            expected.push_back(std::string(family) + size);
    for (const char* family : {"AxisymSmallDisplacementElement", "SmallDisplacementAxisymElement",
                               "AxisymTotalLagrangianElement", "TotalLagrangianAxisymElement"})
        for (const char* size : {"2D3N", "2D4N"}) expected.push_back(std::string(family) + size);
    for (const std::string& name : expected) EXPECT_TRUE(Registry<Element>::Instance().Has(name)) << name;
    EXPECT_EQ(SolidElements(/*include_aliases=*/true).size(), expected.size());
}

class SolidElementRegistrationTest : public ::testing::TestWithParam<ElementInfo> {};

TEST_P(SolidElementRegistrationTest, NameMatchesGeometryAndClass) {
    const ElementInfo& info = GetParam();
    SolidTestModel model(CompatibleLaws(info).front());
    Element& element = model.AddSingleElement(info);
    const Geometry& geometry = element.GetGeometry();
    EXPECT_EQ(geometry.WorkingSpaceDimension(), info.dimension);
    EXPECT_EQ(geometry.LocalSpaceDimension(), info.dimension);
    EXPECT_EQ(geometry.PointsNumber(), info.nodes);
    const std::string suffix = std::to_string(info.dimension) + "D" + std::to_string(info.nodes) + "N";
    EXPECT_EQ(element.Info(), info.family + suffix + " #1 (" + info.geometry + ")");
    // Create() on new nodes keeps the class.
    std::vector<Node::Pointer> nodes = geometry.Points();
    std::reverse(nodes.begin(), nodes.end());
    EXPECT_EQ(element.Create(7, nodes, model.pGetProperties())->Info(),
              info.family + suffix + " #7 (" + info.geometry + ")");
}

INSTANTIATE_TEST_SUITE_P(All, SolidElementRegistrationTest, ::testing::ValuesIn(SolidElements(true)), ElementName);

}  // namespace
}  // namespace contact_app::testing
