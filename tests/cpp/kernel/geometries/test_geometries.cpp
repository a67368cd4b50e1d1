// SPDX-License-Identifier: BSD-3-Clause
/// Invariants of every registered geometry (shape functions, mapping, measures, faces) and hand-computed
/// cases.
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "contact_app/kernel/exceptions.h"
#include "geometry_test_utilities.h"

namespace contact_app {
namespace {

using testing::DistortedGeometry;
using testing::MakeGeometry;
using testing::MakeNodes;
using testing::ReferenceNodes;
using testing::SampleLocalPoints;

// Sample points plus the nodes: the invariants must hold on the boundary too.
std::vector<Array3> LocalPointsWithNodes(const Geometry& geometry) {
    std::vector<Array3> points = SampleLocalPoints(geometry.Family());
    for (const Array3& node : ReferenceNodes(geometry.Name())) points.push_back(node);
    return points;
}

void ExpectThrowsContaining(const std::function<void()>& action, const std::vector<std::string>& parts) {
    try {
        action();
        ADD_FAILURE() << "no InputError thrown";
    } catch (const InputError& error) {
        const std::string message = error.what();
        for (const std::string& part : parts) EXPECT_NE(message.find(part), std::string::npos) << message;
    }
}

class EveryGeometry : public ::testing::TestWithParam<std::string> {
protected:
    Geometry::Pointer mGeometry = DistortedGeometry(GetParam());
};

TEST_P(EveryGeometry, ShapeFunctionsFormAPartitionOfUnity) {
    Vector N;
    Matrix DN;
    for (const Array3& xi : LocalPointsWithNodes(*mGeometry)) {
        mGeometry->ShapeFunctionsValues(N, xi);
        mGeometry->ShapeFunctionsLocalGradients(DN, xi);
        ASSERT_EQ(N.size(), static_cast<Eigen::Index>(mGeometry->PointsNumber()));
        ASSERT_EQ(DN.rows(), N.size());
        ASSERT_EQ(DN.cols(), mGeometry->LocalSpaceDimension());
        EXPECT_NEAR(N.sum(), 1.0, 1e-14);
        if (DN.cols() > 0) {
            EXPECT_LT(DN.colwise().sum().cwiseAbs().maxCoeff(), 1e-14);
        }
    }
}

TEST_P(EveryGeometry, ShapeFunctionIsKroneckerDeltaAtTheNodes) {
    const std::vector<Array3> nodes = ReferenceNodes(GetParam());
    Vector N;
    for (std::size_t j = 0; j < nodes.size(); ++j) {
        mGeometry->ShapeFunctionsValues(N, nodes[j]);
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            EXPECT_NEAR(N[static_cast<Eigen::Index>(i)], i == j ? 1.0 : 0.0, 1e-15)
                << "N_" << i << " at node " << j;
            EXPECT_EQ(mGeometry->ShapeFunctionValue(i, nodes[j]), N[static_cast<Eigen::Index>(i)]);
        }
    }
}

TEST_P(EveryGeometry, LocalGradientsMatchCentralDifferences) {
    const double h = 1e-6;
    Vector plus, minus;
    Matrix DN;
    for (const Array3& xi : LocalPointsWithNodes(*mGeometry)) {
        mGeometry->ShapeFunctionsLocalGradients(DN, xi);
        for (int j = 0; j < mGeometry->LocalSpaceDimension(); ++j) {
            mGeometry->ShapeFunctionsValues(plus, xi + h * Array3::Unit(j));
            mGeometry->ShapeFunctionsValues(minus, xi - h * Array3::Unit(j));
            const Vector fd = (plus - minus) / (2 * h);
            EXPECT_LT((fd - DN.col(j)).norm(), 1e-7 * std::max(1.0, DN.col(j).norm())) << "direction " << j;
        }
    }
}

TEST_P(EveryGeometry, JacobianMatchesCentralDifferencesOfGlobalCoordinates) {
    const double h = 1e-6;
    Matrix J;
    for (const Array3& xi : SampleLocalPoints(mGeometry->Family())) {
        mGeometry->Jacobian(J, xi);
        ASSERT_EQ(J.rows(), mGeometry->WorkingSpaceDimension());
        ASSERT_EQ(J.cols(), mGeometry->LocalSpaceDimension());
        for (int j = 0; j < J.cols(); ++j) {
            const Array3 fd = (mGeometry->GlobalCoordinates(xi + h * Array3::Unit(j)) -
                               mGeometry->GlobalCoordinates(xi - h * Array3::Unit(j))) /
                              (2 * h);
            EXPECT_LT((fd.head(J.rows()) - J.col(j)).norm(), 1e-8);
        }
    }
}

TEST_P(EveryGeometry, GlobalToLocalRoundTripRecoversLocalCoordinates) {
    for (const Array3& xi : LocalPointsWithNodes(*mGeometry)) {
        const Array3 local = mGeometry->PointLocalCoordinates(mGeometry->GlobalCoordinates(xi));
        EXPECT_LT((local - xi).norm(), 1e-12)
            << "local " << xi.transpose() << " came back as " << local.transpose();
    }
}

TEST_P(EveryGeometry, NodesMapToTheirCoordinates) {
    const std::vector<Array3> nodes = ReferenceNodes(GetParam());
    for (std::size_t k = 0; k < nodes.size(); ++k)
        EXPECT_LT((mGeometry->GlobalCoordinates(nodes[k]) - (*mGeometry)[k].Coordinates()).norm(), 1e-14);
}

TEST_P(EveryGeometry, IsInsideAcceptsInteriorPointsAndRejectsOutsidePoints) {
    Array3 local;
    for (const Array3& xi : SampleLocalPoints(mGeometry->Family())) {
        EXPECT_TRUE(mGeometry->IsInside(mGeometry->GlobalCoordinates(xi), local));
        EXPECT_LT((local - xi).norm(), 1e-12);
    }
    const Array3 outside = mGeometry->LocalSpaceDimension() == 0
                               ? Array3((*mGeometry)[0].Coordinates() + Array3(1.0, 0.0, 0.0))
                               : mGeometry->GlobalCoordinates(testing::OutsideLocalPoint(mGeometry->Family()));
    EXPECT_FALSE(mGeometry->IsInside(outside, local));
    EXPECT_FALSE(mGeometry->IsInside(Array3(40.0, -35.0, 50.0), local));
}

TEST_P(EveryGeometry, DomainSizeAgreesWithTheOrderFiveIntegralOfDetJ) {
    if (mGeometry->LocalSpaceDimension() == 0) {
        EXPECT_EQ(mGeometry->DomainSize(), 0.0);
        return;
    }
    double reference = 0.0;
    for (const auto& point : mGeometry->IntegrationPoints(5))
        reference += point.weight * mGeometry->DeterminantOfJacobian(point.local);
    EXPECT_GT(mGeometry->DomainSize(), 0.0);
    EXPECT_NEAR(mGeometry->DomainSize(), reference, 1e-13 * reference);
    const double measure = mGeometry->LocalSpaceDimension() == 1   ? mGeometry->Length()
                           : mGeometry->LocalSpaceDimension() == 2 ? mGeometry->Area()
                                                                   : mGeometry->Volume();
    EXPECT_EQ(measure, mGeometry->DomainSize());
}

TEST_P(EveryGeometry, CenterIsTheAverageOfTheNodeCoordinates) {
    Array3 sum = Array3::Zero();
    for (const auto& node : mGeometry->Points()) sum += node->Coordinates();
    EXPECT_LT((mGeometry->Center() - sum / mGeometry->PointsNumber()).norm(), 1e-15);
}

TEST_P(EveryGeometry, InitialConfigurationIgnoresNodeMotion) {
    const Array3 xi = SampleLocalPoints(mGeometry->Family()).front();
    const Array3 before = mGeometry->GlobalCoordinates(xi);
    for (const auto& node : mGeometry->Points()) node->Coordinates() += Array3(0.3, -0.2, 0.0);
    EXPECT_LT((mGeometry->GlobalCoordinates(xi, Geometry::Configuration::Initial) - before).norm(), 1e-15);
    EXPECT_LT((mGeometry->GlobalCoordinates(xi) - before - Array3(0.3, -0.2, 0.0)).norm(), 1e-14);
}

TEST_P(EveryGeometry, CreateWithWrongNodeCountThrowsInputErrorNamingTypeAndCounts) {
    const std::size_t n = mGeometry->PointsNumber();
    const std::string expected =
        GetParam() + " needs " + std::to_string(n) + " nodes, got " + std::to_string(n + 1);
    ExpectThrowsContaining([&] { mGeometry->Create(MakeNodes(std::vector<Array3>(n + 1, Array3::Zero()))); },
                           {expected});
    ExpectThrowsContaining(
        [&] { CreateGeometry(GetParam(), MakeNodes(std::vector<Array3>(n + 1, Array3::Zero()))); }, {expected});
}

TEST_P(EveryGeometry, CreateReturnsTheSameTypeSharingTheNodes) {
    const Geometry::Pointer copy = mGeometry->Create(mGeometry->Points());
    EXPECT_EQ(copy->Name(), GetParam());
    EXPECT_EQ(copy->pGetPoint(0), mGeometry->pGetPoint(0));
    EXPECT_THROW(copy->pGetPoint(copy->PointsNumber()), InputError);
}

TEST_P(EveryGeometry, IntegrationPointsAreTheFamilyRuleAndDefaultOrderIsKratos) {
    const std::map<std::string, int> kratos_default{
        {"Point3D", 1},          {"Line2D2", 1},       {"Line3D2", 1},        {"Line2D3", 2},
        {"Triangle2D3", 1},      {"Triangle3D3", 1},   {"Triangle2D6", 2},    {"Quadrilateral2D4", 2},
        {"Quadrilateral3D4", 2}, {"Tetrahedra3D4", 1}, {"Tetrahedra3D10", 2}, {"Hexahedra3D8", 2},
        {"Prism3D6", 2}};
    EXPECT_EQ(mGeometry->DefaultIntegrationOrder(), kratos_default.at(GetParam()));
    EXPECT_EQ(&mGeometry->IntegrationPoints(3), &GaussRule(mGeometry->Family(), 3));
}

TEST_P(EveryGeometry, FaceNormalsPointOutward) {
    const int local_dim = mGeometry->LocalSpaceDimension();
    const auto faces = mGeometry->LocalFacesConnectivity();
    EXPECT_EQ(mGeometry->FacesNumber(), faces.size());
    if (local_dim < 2) return;  // points have no faces, lines have their end points
    const Array3 center = mGeometry->Center();
    const auto x = [&](std::size_t k) { return (*mGeometry)[k].Coordinates(); };
    // Surfaces: the edge normal is the tangent rotated clockwise about the surface normal (e_z in 2D).
    const Array3 surface_normal =
        local_dim == 2 ? mGeometry->UnitNormal(SampleLocalPoints(mGeometry->Family()).front()) : Array3::Zero();
    for (const auto& face : faces) {
        const Array3 outward = local_dim == 2
                                   ? Array3((x(face[1]) - x(face[0])).cross(surface_normal))
                                   : Array3((x(face[1]) - x(face[0])).cross(x(face[2]) - x(face[0])));
        Array3 face_center = Array3::Zero();
        for (std::size_t k : face) face_center += x(k) / static_cast<double>(face.size());
        EXPECT_GT(outward.dot(face_center - center), 0.0) << "face starting at local node " << face[0];
    }
}

INSTANTIATE_TEST_SUITE_P(Registered, EveryGeometry, ::testing::ValuesIn(RegisteredGeometryNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

// -- Hand-computed cases --

TEST(Tetrahedra, ShearedTetrahedronHasTheMapAsJacobianAndExactVolume) {
    Eigen::Matrix3d A;
    A << 2.0, 1.0, 0.0, 0.0, 3.0, 0.5, 0.0, 0.0, 1.5;  // det 9
    const Array3 b(1.0, -2.0, 0.5);
    for (const std::string name : {"Tetrahedra3D4", "Tetrahedra3D10"}) {
        std::vector<Array3> x;
        for (const Array3& xi : ReferenceNodes(name)) x.push_back(A * xi + b);
        const Geometry::Pointer tet = MakeGeometry(name, x);
        Matrix J, inverse;
        tet->Jacobian(J, Array3(0.1, 0.2, 0.3));
        EXPECT_LT((J - Matrix(A)).norm(), 1e-14) << name;
        EXPECT_NEAR(tet->DeterminantOfJacobian(Array3(0.3, 0.1, 0.2)), 9.0, 1e-13);
        EXPECT_NEAR(tet->Volume(), 1.5, 1e-14);
        tet->InverseOfJacobian(inverse, Array3(0.2, 0.2, 0.2));
        EXPECT_LT((inverse - Matrix(A.inverse())).norm(), 1e-14);
    }
}

TEST(Hexahedra, AffineHexahedronHasTheMapAsJacobianAndVolumeEightDetA) {
    Eigen::Matrix3d A;
    A << 1.5, 0.2, 0.1, -0.3, 0.8, 0.0, 0.2, 0.1, 2.0;
    std::vector<Array3> x;
    for (const Array3& xi : ReferenceNodes("Hexahedra3D8")) x.push_back(A * xi + Array3(3, 2, 1));
    const Geometry::Pointer hex = MakeGeometry("Hexahedra3D8", x);
    Matrix J;
    hex->Jacobian(J, Array3(0.3, -0.7, 0.1));
    EXPECT_LT((J - Matrix(A)).norm(), 1e-14);
    EXPECT_NEAR(hex->Volume(), 8.0 * A.determinant(), 1e-13);
    EXPECT_LT((hex->Center() - Array3(3, 2, 1)).norm(), 1e-14);
}

TEST(Hexahedra, DistortedHexahedronVolumeIsExactWithOrderTwo) {
    // Unit cube with one corner pulled out: V = 1 + the pyramid-like bulge, computed on a fine Gauss rule.
    std::vector<Array3> x{{0, 0, 0}, {1, 0, 0}, {1, 1, 0},       {0, 1, 0},
                          {0, 0, 1}, {1, 0, 1}, {1.4, 1.3, 1.5}, {0, 1, 1}};
    const Geometry::Pointer hex = MakeGeometry("Hexahedra3D8", x);
    double fine = 0.0;
    for (const auto& p : hex->IntegrationPoints(5)) fine += p.weight * hex->DeterminantOfJacobian(p.local);
    EXPECT_NEAR(hex->Volume(), fine, 1e-14);
    const Array3 xi(0.3, -0.8, 0.6);
    EXPECT_LT((hex->PointLocalCoordinates(hex->GlobalCoordinates(xi)) - xi).norm(), 1e-12);
}

TEST(Triangle3D3, TiltedTriangleHasHandAreaAndUnitNormal) {
    const Geometry::Pointer triangle = MakeGeometry("Triangle3D3", {{0, 0, 0}, {2, 0, 0}, {0, 1, 1}});
    EXPECT_NEAR(triangle->Area(), std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(triangle->DeterminantOfJacobian(Array3(0.2, 0.2, 0)), 2.0 * std::sqrt(2.0), 1e-15);
    EXPECT_LT((triangle->UnitNormal(Array3(0.1, 0.1, 0)) - Array3(0, -1, 1) / std::sqrt(2.0)).norm(), 1e-15);
    EXPECT_LT((triangle->Normal(Array3(0.1, 0.1, 0)) - Array3(0, -2, 2)).norm(), 1e-15);
}

TEST(Triangle3D3, PointLocalCoordinatesProjectsAPointOffTheSurface) {
    const Geometry::Pointer triangle = MakeGeometry("Triangle3D3", {{0, 0, 0}, {2, 0, 0}, {0, 1, 1}});
    const Array3 xi(0.25, 0.4, 0.0);
    const Array3 off = triangle->GlobalCoordinates(xi) + 0.7 * triangle->UnitNormal(xi);
    Array3 local;
    EXPECT_TRUE(triangle->IsInside(off, local));
    EXPECT_LT((local - xi).norm(), 1e-14);
}

TEST(Quadrilateral3D4, TiltedPlanarQuadrilateralHasHandAreaAndNormal) {
    // A 2 × 3 rectangle in the plane spanned by e1 = (1,0,0) and e2 = (0,0.6,0.8), then a trapezoid.
    const Array3 e1(1, 0, 0), e2(0, 0.6, 0.8);
    const Geometry::Pointer rectangle =
        MakeGeometry("Quadrilateral3D4", {{0, 0, 0}, 2 * e1, 2 * e1 + 3 * e2, 3 * e2});
    EXPECT_NEAR(rectangle->Area(), 6.0, 1e-14);
    EXPECT_LT((rectangle->UnitNormal(Array3(0.3, -0.2, 0)) - e1.cross(e2)).norm(), 1e-15);
    const Geometry::Pointer trapezoid =
        MakeGeometry("Quadrilateral3D4", {{0, 0, 0}, 4 * e1, 3 * e1 + 2 * e2, 1 * e1 + 2 * e2});
    EXPECT_NEAR(trapezoid->Area(), 0.5 * (4.0 + 2.0) * 2.0, 1e-14);
}

TEST(Quadrilateral3D4, WarpedQuadrilateralAreaMatchesAFineReferenceIntegral) {
    // x = (ξ, η, c ξ η): area = ∫∫ sqrt(1 + c²(ξ² + η²)) dξ dη, here by composite Simpson (error ~1e-12).
    const double c = 0.6;
    const Geometry::Pointer quad =
        MakeGeometry("Quadrilateral3D4", {{-1, -1, c}, {1, -1, -c}, {1, 1, c}, {-1, 1, -c}});
    const int n = 400;
    double simpson = 0.0;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            const auto weight = [&](int k) { return k == 0 || k == n ? 1.0 : (k % 2 ? 4.0 : 2.0); };
            const double xi = -1.0 + 2.0 * i / n, eta = -1.0 + 2.0 * j / n;
            simpson += weight(i) * weight(j) * std::sqrt(1.0 + c * c * (xi * xi + eta * eta));
        }
    simpson *= (2.0 / (3 * n)) * (2.0 / (3 * n));
    EXPECT_NEAR(quad->Area(), simpson, 1e-6 * simpson);
    EXPECT_GT(quad->Area(), 4.0);
}

TEST(Triangle2D6, CurvedTriangleAreaMatchesTheParabolicSegment) {
    // Right triangle with the hypotenuse's mid-node pushed out by d along (1,1): the quadratic edge
    // bulges by a parabolic segment of area (2/3)·chord·sagitta = (2/3)·√2·(d√2) = 4d/3.
    const double d = 0.1;
    const Geometry::Pointer triangle = MakeGeometry(
        "Triangle2D6", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0, 0}, {0.5 + d, 0.5 + d, 0}, {0, 0.5, 0}});
    EXPECT_NEAR(triangle->Area(), 0.5 + 4.0 * d / 3.0, 1e-15);
}

TEST(Line2D2, NormalIsTheTangentRotatedClockwise) {
    const Geometry::Pointer along_x = MakeGeometry("Line2D2", {{0, 0, 0}, {2, 0, 0}});
    EXPECT_LT((along_x->UnitNormal(Array3::Zero()) - Array3(0, -1, 0)).norm(), 1e-15);
    EXPECT_LT((along_x->Normal(Array3::Zero()) - Array3(0, -1, 0)).norm(), 1e-15);  // |J| = L/2 = 1
    const Geometry::Pointer along_y = MakeGeometry("Line2D2", {{1, 1, 0}, {1, 5, 0}});
    EXPECT_LT((along_y->UnitNormal(Array3(0.4, 0, 0)) - Array3(1, 0, 0)).norm(), 1e-15);
    EXPECT_LT((along_y->Normal(Array3(0.4, 0, 0)) - Array3(2, 0, 0)).norm(), 1e-15);
    EXPECT_NEAR(along_y->Length(), 4.0, 1e-15);
    EXPECT_NEAR(along_y->DeterminantOfJacobian(Array3::Zero()), 2.0, 1e-15);
}

TEST(Line3D2, LengthAndNormalInSpace) {
    const Geometry::Pointer line = MakeGeometry("Line3D2", {{0, 0, 0}, {1, 2, 2}});
    EXPECT_NEAR(line->Length(), 3.0, 1e-15);
    const Array3 n = line->UnitNormal(Array3::Zero());
    EXPECT_NEAR(n.norm(), 1.0, 1e-15);
    EXPECT_NEAR(n.dot(Array3(1, 2, 2)), 0.0, 1e-15);
    EXPECT_LT((n - Array3(2, -1, 0) / std::sqrt(5.0)).norm(), 1e-15);
}

TEST(Line2D3, StraightEvenlySpacedLineHasExactLength) {
    const Geometry::Pointer line = MakeGeometry("Line2D3", {{0, 0, 0}, {3, 4, 0}, {1.5, 2, 0}});
    EXPECT_NEAR(line->Length(), 5.0, 1e-14);
}

TEST(Triangle2D3, IsInsideTrueAndFalseCases) {
    const Geometry::Pointer triangle = MakeGeometry("Triangle2D3", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    Array3 local;
    EXPECT_TRUE(triangle->IsInside(Array3(0.2, 0.3, 0), local));
    EXPECT_LT((local - Array3(0.2, 0.3, 0)).norm(), 1e-15);
    EXPECT_TRUE(triangle->IsInside(Array3(0.5, 0.5, 0), local));          // on the hypotenuse
    EXPECT_TRUE(triangle->IsInside(Array3(1.0 + 1e-12, 0.0, 0), local));  // within the tolerance
    EXPECT_FALSE(triangle->IsInside(Array3(0.6, 0.6, 0), local));
    EXPECT_FALSE(triangle->IsInside(Array3(1.01, 0.0, 0), local));
    EXPECT_FALSE(triangle->IsInside(Array3(-0.01, 0.5, 0), local));
    EXPECT_TRUE(triangle->IsInside(Array3(1.01, 0.0, 0), local, 0.02));
}

TEST(Point3D, SingleNodeHasUnitShapeFunctionAndZeroDomainSize) {
    const Geometry::Pointer point = MakeGeometry("Point3D", {{1, 2, 3}});
    Vector N;
    point->ShapeFunctionsValues(N, Array3::Zero());
    EXPECT_EQ(N, Vector::Ones(1));
    EXPECT_EQ(point->DeterminantOfJacobian(Array3::Zero()), 1.0);
    EXPECT_EQ(point->DomainSize(), 0.0);
    EXPECT_LT((point->GlobalCoordinates(Array3::Zero()) - Array3(1, 2, 3)).norm(), 1e-15);
    Array3 local;
    EXPECT_TRUE(point->IsInside(Array3(1, 2, 3), local));
    EXPECT_THROW(point->UnitNormal(Array3::Zero()), InputError);
}

// -- Errors --

TEST(GeometryErrors, DegenerateGeometryLocalCoordinatesThrowInputErrorWithNodeIds) {
    const Geometry::Pointer flat =
        CreateGeometry("Triangle2D3", MakeNodes({{0, 0, 0}, {1, 1, 0}, {2, 2, 0}}, 7));
    ExpectThrowsContaining([&] { flat->PointLocalCoordinates(Array3(0.5, 0.2, 0)); },
                           {"Triangle2D3", "[7, 8, 9]", "singular", "(0.5, 0.20000000000000001, 0)"});
    Array3 local;
    ExpectThrowsContaining([&] { flat->IsInside(Array3(0.5, 0.2, 0), local); }, {"[7, 8, 9]"});
    const Geometry::Pointer coplanar =
        MakeGeometry("Tetrahedra3D4", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
    ExpectThrowsContaining([&] { coplanar->PointLocalCoordinates(Array3(0.2, 0.2, 0.1)); },
                           {"Tetrahedra3D4", "[1, 2, 3, 4]"});
}

TEST(GeometryErrors, InverseOfJacobianRejectsInvertedAndNonSquareGeometries) {
    Matrix inverse;
    const Geometry::Pointer clockwise =
        CreateGeometry("Triangle2D3", MakeNodes({{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}, 4));
    ExpectThrowsContaining([&] { clockwise->InverseOfJacobian(inverse, Array3(0.2, 0.2, 0)); },
                           {"inverted", "[4, 5, 6]", "reorder"});
    const Geometry::Pointer surface = MakeGeometry("Triangle3D3", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    ExpectThrowsContaining([&] { surface->InverseOfJacobian(inverse, Array3(0.2, 0.2, 0)); }, {"square"});
}

TEST(GeometryErrors, MeasureOfTheWrongDimensionAndSolidNormalsThrowInputError) {
    const Geometry::Pointer triangle = MakeGeometry("Triangle2D3", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    ExpectThrowsContaining([&] { triangle->Length(); }, {"Length", "Triangle2D3", "DomainSize()"});
    ExpectThrowsContaining([&] { triangle->Volume(); }, {"Volume"});
    const Geometry::Pointer tet = DistortedGeometry("Tetrahedra3D4");
    ExpectThrowsContaining([&] { tet->UnitNormal(Array3(0.2, 0.2, 0.2)); }, {"Normal", "Tetrahedra3D4"});
    const Geometry::Pointer vertical = MakeGeometry("Line3D2", {{0, 0, 0}, {0, 0, 1}});
    ExpectThrowsContaining([&] { vertical->UnitNormal(Array3::Zero()); }, {"zero normal", "[1, 2]"});
}

TEST(GeometryErrors, NullNodeAndBadIndicesThrowInputError) {
    Geometry::PointsArrayType nodes = MakeNodes({{0, 0, 0}, {1, 0, 0}});
    nodes[1] = nullptr;
    ExpectThrowsContaining([&] { CreateGeometry("Line2D2", nodes); }, {"Line2D2", "null"});
    const Geometry::Pointer line = MakeGeometry("Line2D2", {{0, 0, 0}, {1, 0, 0}});
    EXPECT_THROW(line->ShapeFunctionValue(2, Array3::Zero()), InputError);
    EXPECT_THROW(line->IntegrationPoints(0), InputError);
}

}  // namespace
}  // namespace contact_app
