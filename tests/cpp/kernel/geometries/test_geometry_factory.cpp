// SPDX-License-Identifier: BSD-3-Clause
/// CreateGeometry: every registered name builds its class with matching dimensions; unknown names suggest.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/geometries/geometry_factory.h"
#include "geometry_test_utilities.h"

namespace contact_app {
namespace {

class RegisteredName : public ::testing::TestWithParam<std::string> {};

TEST_P(RegisteredName, BuildsItsClassWithTheDimensionsAndNodeCountInTheName) {
    const std::string& name = GetParam();
    const std::size_t nodes = testing::NodeCountFromName(name);
    const Geometry::Pointer geometry =
        CreateGeometry(name, testing::MakeNodes(std::vector<Array3>(nodes, Array3::Zero())));
    EXPECT_EQ(geometry->Name(), name);
    EXPECT_EQ(geometry->PointsNumber(), nodes);
    const std::size_t d = name.find_last_of('D');
    EXPECT_EQ(geometry->WorkingSpaceDimension(), name[d - 1] - '0')
        << "the digit before 'D' is the working dimension";
    EXPECT_LE(geometry->LocalSpaceDimension(), geometry->WorkingSpaceDimension());
}

INSTANTIATE_TEST_SUITE_P(Registered, RegisteredName, ::testing::ValuesIn(RegisteredGeometryNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(GeometryFactory, RegistersTheThirteenKratosNames) {
    const std::vector<std::string> expected{
        "Point3D",        "Line2D2",      "Line3D2",          "Line2D3",          "Triangle2D3",
        "Triangle3D3",    "Triangle2D6",  "Quadrilateral2D4", "Quadrilateral3D4", "Tetrahedra3D4",
        "Tetrahedra3D10", "Hexahedra3D8", "Prism3D6"};
    EXPECT_EQ(RegisteredGeometryNames(), expected);
}

TEST(GeometryFactory, UnknownNameThrowsInputErrorListingNamesAndSuggestingTheClosest) {
    try {
        CreateGeometry("Tetrahedra3D5", testing::MakeNodes({{0, 0, 0}}));
        FAIL() << "unknown name accepted";
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("unknown geometry type \"Tetrahedra3D5\""), std::string::npos) << message;
        EXPECT_NE(message.find("did you mean \"Tetrahedra3D4\""), std::string::npos) << message;
        EXPECT_NE(message.find("\"Hexahedra3D8\""), std::string::npos) << "valid names listed: " << message;
    }
    try {
        CreateGeometry("triangle2d3", {});
        FAIL() << "wrong case accepted";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("did you mean \"Triangle2D3\""), std::string::npos)
            << error.what();
    }
}

}  // namespace
}  // namespace contact_app
