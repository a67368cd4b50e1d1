// SPDX-License-Identifier: BSD-3-Clause
// Exact mortar segmentation: areas against Sutherland–Hodgman, belong tags, degenerate configurations.
#include <gtest/gtest.h>

#include <limits>

#include "custom_utilities/exact_mortar_segmentation.h"
#include "custom_utilities/mortar_geometry_math.h"
#include "custom_utilities/mortar_normals.h"
#include "tests/cpp/custom_utilities/mortar_test_utilities.h"

namespace contact_app {
namespace {

template <class TPair>
class ExactMortarSegmentationTest : public ::testing::Test {
public:
    static constexpr int D = TPair::Dim, NS = TPair::NumSlave, NM = TPair::NumMaster;
    using Segmentation = ExactMortarSegmentation<D, NS, NM, double>;
    using Cells = MortarCells<double, D>;

    static bool AllFinite(const Cells& cells) {
        for (const auto& cell : cells)
            for (const auto& v : cell.local)
                if (!v.allFinite()) return false;
        return true;
    }
    static SpatialVector<double, D> Normal(const NodeCoordinates<double, D, NS>& slave) {
        return FaceCenterUnitNormal<D, NS, double>(slave);
    }
    /// Area centroid of the union of the (3D) cells on a planar slave, from the cells' own centroids.
    static Eigen::VectorXd AreaCentroid(const NodeCoordinates<double, D, NS>& slave, const Cells& cells) {
        Eigen::VectorXd moment = Eigen::VectorXd::Zero(D);
        double area = 0.0;
        for (const auto& cell : cells) {
            std::array<Eigen::Vector3d, 3> x;
            for (int v = 0; v < 3; ++v) {
                x[v].setZero();
                x[v].head(D) = detail::FacePoint<NS, D, double, double>(slave, cell.local[v]);
            }
            const double a = 0.5 * (x[1] - x[0]).cross(x[2] - x[0]).norm();
            moment += a * ((x[0] + x[1] + x[2]) / 3.0).head(D);
            area += a;
        }
        return moment / area;
    }
};
TYPED_TEST_SUITE(ExactMortarSegmentationTest, testing::PairKinds, testing::PairKindName);

TYPED_TEST(ExactMortarSegmentationTest, test_segmentation_area_matches_sutherland_hodgman) {
    using Test = TestFixture;
    std::mt19937 rng(42);
    for (bool tessellation : {false, true}) {
        SegmentationSettings settings;
        settings.consider_tessellation = tessellation;
        const typename Test::Segmentation segmentation(settings);
        int with_overlap = 0;
        for (int sample = 0; sample < 300; ++sample) {
            const auto pair = testing::MakeRandomPair<TypeParam>(rng, 0.7);
            const auto normal = Test::Normal(pair.slave);
            typename Test::Cells cells;
            const bool found = segmentation.ComputeCells(pair.slave, normal, pair.master, cells);
            const double reference = testing::ReferenceOverlap<Test::D, Test::NS, Test::NM>(pair.slave, normal, pair.master);
            const double area = found ? segmentation.TotalArea(pair.slave, cells) : 0.0;
            ASSERT_TRUE(Test::AllFinite(cells));
            EXPECT_NEAR(area, reference, 1e-10) << "sample " << sample << " tessellation " << tessellation;
            with_overlap += found;
        }
        EXPECT_GT(with_overlap, 150);
    }
}

TYPED_TEST(ExactMortarSegmentationTest, test_segmentation_belong_tags_locate_the_vertices) {
    using Test = TestFixture;
    constexpr int B = TypeParam::BaseTag;
    std::mt19937 rng(7);
    const typename Test::Segmentation segmentation;
    int edge_vertices = 0, centroids = 0;
    for (int sample = 0; sample < 100; ++sample) {
        const auto pair = testing::MakeRandomPair<TypeParam>(rng, 0.6, false);  // slave in z = 0 (y = 0)
        typename Test::Cells cells;
        const Eigen::VectorXd n = Test::Normal(pair.slave);
        if (!segmentation.ComputeCells(pair.slave, Test::Normal(pair.slave), pair.master, cells)) continue;
        for (const auto& cell : cells) {
            for (int v = 0; v < Test::D; ++v) {
                const auto x = detail::FacePoint<Test::NS, Test::D, double, double>(pair.slave, cell.local[v]);
                const int tag = cell.belong[v];
                auto in_plane = [&](const Eigen::RowVectorXd& p) {
                    const Eigen::VectorXd q = p.transpose();  // orthogonal projection on the slave plane
                    const Eigen::VectorXd o = pair.slave.row(0).transpose();
                    return Eigen::VectorXd(q - (q - o).dot(n) * n);
                };
                if (tag == B) {  // the fan's apex: the overlap's area centroid, the same point for every cell
                    if constexpr (Test::D == 3) EXPECT_LT((x - Test::AreaCentroid(pair.slave, cells)).norm(), 1e-9);
                    ++centroids;
                } else if (tag < Test::NS) {
                    EXPECT_LT((x - in_plane(pair.slave.row(tag))).norm(), 1e-9);
                } else if (tag < B) {
                    EXPECT_LT((x - in_plane(pair.master.row(tag - Test::NS))).norm(), 1e-9);
                } else {
                    int s0, s1, m0, m1;
                    ASSERT_TRUE(DecodeEdgeIntersectionTag(tag, B, s0, s1, m0, m1));
                    EXPECT_EQ(s1, (s0 + 1) % Test::NS);
                    EXPECT_EQ(m1, (m0 + 1) % Test::NM);
                    // On both (projected) edges: collinear with each.
                    auto off_line = [&](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
                        const Eigen::VectorXd xd = x;
                        const Eigen::Vector2d u = (b - a).segment(0, 2), w = (xd - a).segment(0, 2);
                        return std::abs(u[0] * w[1] - u[1] * w[0]) / u.norm();
                    };
                    EXPECT_LT(off_line(in_plane(pair.slave.row(s0)), in_plane(pair.slave.row(s1))), 1e-9);
                    EXPECT_LT(off_line(in_plane(pair.master.row(m0)), in_plane(pair.master.row(m1))), 1e-9);
                    ++edge_vertices;
                }
            }
        }
    }
    if (Test::D == 3) EXPECT_GT(edge_vertices, 50);
    if (Test::D == 3) EXPECT_GT(centroids, 50);  // the default cells fan around the area centroid
}

TYPED_TEST(ExactMortarSegmentationTest, test_segmentation_degenerate_configurations_are_empty_or_valid) {
    using Test = TestFixture;
    std::mt19937 rng(3);
    const typename Test::Segmentation segmentation;
    const auto pair = testing::MakeRandomPair<TypeParam>(rng, 0.0, false);
    const auto normal = Test::Normal(pair.slave);
    typename Test::Cells cells;
    // No overlap: master far to the side.
    auto far = pair.master;
    far.col(0).array() += 10.0;
    EXPECT_FALSE(segmentation.ComputeCells(pair.slave, normal, far, cells));
    EXPECT_TRUE(cells.empty());
    // Touching along an edge / a point: master shifted so that it starts where the slave ends.
    // In-plane direction: x in 3D (slave in z = 0), the slave tangent in 2D.
    SpatialVector<double, Test::D> t = SpatialVector<double, Test::D>::Unit(0);
    if constexpr (Test::D == 2) t << -normal[1], normal[0];
    const Eigen::VectorXd ts = pair.slave * t, tm = pair.master * t;
    auto touching = pair.master;
    touching.rowwise() += (ts.maxCoeff() - tm.minCoeff()) * t.transpose();
    const bool touch = segmentation.ComputeCells(pair.slave, normal, touching, cells);
    EXPECT_TRUE(Test::AllFinite(cells));
    if (touch) EXPECT_LT(segmentation.TotalArea(pair.slave, cells), 1e-9);
    // Coincident (matching) faces, both orientations of the master, and an inverted slave normal.
    auto reversed = pair.slave;
    reversed = pair.slave.colwise().reverse().eval();
    const double full = testing::ReferenceOverlap<Test::D, Test::NS, Test::NS>(pair.slave, normal, pair.slave);
    for (const auto& n : {normal, SpatialVector<double, Test::D>(-normal)}) {
        for (const auto& master : {pair.slave, reversed}) {
            typename ExactMortarSegmentation<Test::D, Test::NS, Test::NS, double>::Cell dummy;
            (void)dummy;
            MortarCells<double, Test::D> matching;
            const ExactMortarSegmentation<Test::D, Test::NS, Test::NS, double> same;
            ASSERT_TRUE(same.ComputeCells(pair.slave, n, master, matching));
            EXPECT_NEAR(same.TotalArea(pair.slave, matching), full, 1e-12);
        }
    }
    // Master perpendicular to the slave (parallel to the projection direction): zero-measure projection.
    auto edge_on = pair.master;
    for (int j = 0; j < Test::NM; ++j) edge_on.row(j) = pair.slave.row(0) + 0.3 * normal.transpose() * (j % 2);
    EXPECT_FALSE(segmentation.ComputeCells(pair.slave, normal, edge_on, cells));
    // Zero normal, collapsed slave, NaN input: empty, never a NaN or a throw.
    EXPECT_FALSE(segmentation.ComputeCells(pair.slave, SpatialVector<double, Test::D>::Zero().eval(), pair.master, cells));
    auto collapsed = pair.slave;
    collapsed.rowwise() = pair.slave.row(0);
    EXPECT_FALSE(segmentation.ComputeCells(collapsed, normal, pair.master, cells));
    auto broken = pair.master;
    broken(0, 0) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(segmentation.ComputeCells(pair.slave, normal, broken, cells));
    EXPECT_TRUE(cells.empty());
}

TYPED_TEST(ExactMortarSegmentationTest, test_segmentation_distance_threshold_rejects_far_masters) {
    using Test = TestFixture;
    std::mt19937 rng(11);
    const auto pair = testing::MakeRandomPair<TypeParam>(rng, 0.0, false);
    const auto normal = Test::Normal(pair.slave);
    auto lifted = pair.master;
    lifted.col(Test::D - 1).array() += 1.0;  // 1 in front of the slave
    SegmentationSettings settings;
    settings.distance_threshold = 0.5;
    typename Test::Cells cells;
    EXPECT_FALSE(typename Test::Segmentation(settings).ComputeCells(pair.slave, normal, lifted, cells));
    EXPECT_TRUE(typename Test::Segmentation().ComputeCells(pair.slave, normal, lifted, cells));
    auto sunk = pair.master;
    sunk.col(Test::D - 1).array() -= 1.0;  // penetration is never rejected
    EXPECT_TRUE(typename Test::Segmentation(settings).ComputeCells(pair.slave, normal, sunk, cells));
}

TEST(ExactMortarSegmentation, test_isolated_rule_and_tag_decoding) {
    EXPECT_TRUE(IsMortarPairUsed(2e-5, 1.0));
    EXPECT_FALSE(IsMortarPairUsed(1e-5, 1.0));
    EXPECT_FALSE(IsMortarPairUsed(1.0, 0.0));
    int s0, s1, m0, m1;
    EXPECT_TRUE(DecodeEdgeIntersectionTag(10106, 6, s0, s1, m0, m1));  // tri/tri "0101"
    EXPECT_EQ(s0, 0);
    EXPECT_EQ(s1, 1);
    EXPECT_EQ(m0, 0);
    EXPECT_EQ(m1, 1);
    EXPECT_FALSE(DecodeEdgeIntersectionTag(6, 6, s0, s1, m0, m1));
}

}  // namespace
}  // namespace contact_app
