// SPDX-License-Identifier: BSD-3-Clause
/// CouplingGeometry: parts in slave/master order, points and measures of part 0, part errors.
#include <string>

#include <gtest/gtest.h>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/geometries/coupling_geometry.h"
#include "geometry_test_utilities.h"

namespace contact_app {
namespace {

using testing::MakeGeometry;

class CouplingGeometryTest : public ::testing::Test {
protected:
    Geometry::Pointer mSlave = MakeGeometry("Line2D2", {{0, 0, 0}, {2, 0, 0}});
    Geometry::Pointer mMaster = MakeGeometry("Line2D2", {{2, 0.1, 0}, {-1, 0.1, 0}});
    CouplingGeometry mCoupling{mSlave, mMaster};
};

TEST_F(CouplingGeometryTest, PartsAreSlaveThenMaster) {
    EXPECT_EQ(mCoupling.NumberOfGeometryParts(), 2u);
    EXPECT_EQ(&mCoupling.GetGeometryPart(0), mSlave.get());
    EXPECT_EQ(&mCoupling.GetGeometryPart(1), mMaster.get());
    EXPECT_EQ(mCoupling.pGetGeometryPart(1), mMaster);
    EXPECT_EQ(mCoupling.Name(), "CouplingGeometry");
}

TEST_F(CouplingGeometryTest, PointsAreThoseOfPartZero) {
    ASSERT_EQ(mCoupling.PointsNumber(), 2u);
    EXPECT_EQ(mCoupling.pGetPoint(0), mSlave->pGetPoint(0));
    EXPECT_EQ(mCoupling.pGetPoint(1), mSlave->pGetPoint(1));
}

TEST_F(CouplingGeometryTest, MeasuresNormalsAndMappingDelegateToPartZero) {
    const Array3 xi(0.3, 0, 0);
    EXPECT_EQ(mCoupling.Length(), mSlave->Length());
    EXPECT_EQ(mCoupling.DomainSize(), 2.0);
    EXPECT_EQ(mCoupling.UnitNormal(xi), mSlave->UnitNormal(xi));
    EXPECT_EQ(mCoupling.Normal(xi), mSlave->Normal(xi));
    EXPECT_EQ(mCoupling.Center(), mSlave->Center());
    EXPECT_EQ(mCoupling.GlobalCoordinates(xi), mSlave->GlobalCoordinates(xi));
    EXPECT_EQ(mCoupling.Family(), GeometryFamily::Linear);
    EXPECT_EQ(mCoupling.LocalSpaceDimension(), 1);
    EXPECT_EQ(mCoupling.WorkingSpaceDimension(), 2);
    EXPECT_EQ(mCoupling.DefaultIntegrationOrder(), 1);
    EXPECT_EQ(mCoupling.LocalFacesConnectivity(), mSlave->LocalFacesConnectivity());
    EXPECT_NEAR(mCoupling.PointLocalCoordinates(Array3(1.5, 0, 0))[0], 0.5, 1e-15);
}

TEST_F(CouplingGeometryTest, MissingOrNullPartsThrowInputError) {
    EXPECT_THROW(mCoupling.GetGeometryPart(2), InputError);
    EXPECT_THROW(mCoupling.SetGeometryPart(0, nullptr), InputError);
    EXPECT_THROW(CouplingGeometry(nullptr, mMaster), InputError);
    EXPECT_THROW(CouplingGeometry(mSlave, nullptr), InputError);
}

TEST_F(CouplingGeometryTest, SetGeometryPartZeroReplacesThePoints) {
    const Geometry::Pointer other = MakeGeometry("Line2D2", {{0, 1, 0}, {0, 4, 0}});
    mCoupling.SetGeometryPart(0, other);
    EXPECT_EQ(mCoupling.pGetPoint(0), other->pGetPoint(0));
    EXPECT_NEAR(mCoupling.Length(), 3.0, 1e-15);
    mCoupling.SetGeometryPart(1, other);
    EXPECT_EQ(mCoupling.pGetGeometryPart(1), other);
}

TEST_F(CouplingGeometryTest, CreateBuildsANewSlaveOfTheSameTypeAndKeepsTheMaster) {
    const Geometry::Pointer created = mCoupling.Create(mMaster->Points());
    EXPECT_EQ(created->Name(), "CouplingGeometry");
    EXPECT_EQ(created->GetGeometryPart(0).Name(), "Line2D2");
    EXPECT_EQ(created->pGetPoint(0), mMaster->pGetPoint(0));
    EXPECT_EQ(created->pGetGeometryPart(1), mMaster);
    EXPECT_THROW(mCoupling.Create(testing::MakeNodes({{0, 0, 0}})), InputError);
}

TEST(PlainGeometry, HasNoGeometryParts) {
    const Geometry::Pointer triangle = MakeGeometry("Triangle2D3", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    EXPECT_EQ(triangle->NumberOfGeometryParts(), 0u);
    EXPECT_THROW(triangle->GetGeometryPart(0), InputError);
}

}  // namespace
}  // namespace contact_app
