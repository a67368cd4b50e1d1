// SPDX-License-Identifier: BSD-3-Clause
/// The kd-tree of the contact search against brute force, its balance, and the OBB separating-axis test.
#include <algorithm>
#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/geometries/geometry_factory.h"
#include "custom_processes/oriented_bounding_box.h"
#include "custom_processes/search_tree.h"

namespace contact_app {
namespace {

std::vector<Array3> RandomPoints(std::size_t n, unsigned seed, bool flat) {
    std::mt19937 generator(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::vector<Array3> points(n);
    for (auto& p : points) p = Array3(uniform(generator), uniform(generator), flat ? 0.0 : uniform(generator));
    return points;
}

std::vector<std::size_t> Sorted(std::vector<std::size_t> v) {
    std::sort(v.begin(), v.end());
    return v;
}

TEST(SearchTree, InRadiusMatchesBruteForce) {
    for (const bool flat : {false, true}) {
        const auto points = RandomPoints(2000, 7, flat);
        SearchTree tree;
        tree.Build(points, 4);
        const auto queries = RandomPoints(200, 11, flat);
        std::vector<std::size_t> found;
        std::size_t total = 0;
        for (const auto& q : queries) {
            const double radius = 0.15;
            tree.SearchInRadius(q, radius, found);
            std::vector<std::size_t> expected;
            for (std::size_t i = 0; i < points.size(); ++i)
                if ((points[i] - q).norm() <= radius) expected.push_back(i);
            EXPECT_EQ(Sorted(found), expected);
            total += expected.size();
        }
        EXPECT_GT(total, 200u);  // the queries do find points
    }
}

TEST(SearchTree, InBoxMatchesBruteForce) {
    const auto points = RandomPoints(3000, 3, false);
    SearchTree tree;
    tree.Build(points, 1);
    const auto corners = RandomPoints(100, 5, false);
    std::vector<std::size_t> found;
    std::size_t total = 0;
    for (const auto& c : corners) {
        const Array3 lo = c, hi = c + Array3(0.3, 0.2, 0.4);
        tree.SearchInBox(lo, hi, found);
        std::vector<std::size_t> expected;
        for (std::size_t i = 0; i < points.size(); ++i)
            if ((points[i].array() >= lo.array()).all() && (points[i].array() <= hi.array()).all()) expected.push_back(i);
        EXPECT_EQ(Sorted(found), expected);
        total += expected.size();
    }
    EXPECT_GT(total, 100u);
}

TEST(SearchTree, BalancedAndLimited) {
    const auto points = RandomPoints(1 << 14, 9, false);
    SearchTree tree;
    tree.Build(points, 4);
    // Median splits: depth = ⌈log2(n / bucket)⌉ + 1.
    EXPECT_EQ(tree.Depth(), static_cast<std::size_t>(std::ceil(std::log2(points.size() / 4.0))) + 1);
    std::vector<std::size_t> found;
    tree.SearchInRadius(Array3::Zero(), 10.0, found, 17);
    EXPECT_EQ(found.size(), 17u);
    tree.SearchInRadius(Array3::Zero(), 10.0, found);
    EXPECT_EQ(found.size(), points.size());
}

TEST(SearchTree, CoincidentPointsAndEmptyTree) {
    SearchTree tree;
    std::vector<std::size_t> found;
    tree.Build({}, 4);
    tree.SearchInRadius(Array3::Zero(), 1.0, found);
    EXPECT_TRUE(found.empty());
    tree.Build(std::vector<Array3>(50, Array3(1.0, 2.0, 3.0)), 2);
    tree.SearchInRadius(Array3(1.0, 2.0, 3.0), 0.0, found);
    EXPECT_EQ(found.size(), 50u);
    EXPECT_THROW(tree.Build({Array3::Zero()}, 0), InputError);
}

std::array<Array3, 3> RotatedZ(double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return {Array3(c, s, 0.0), Array3(-s, c, 0.0), Array3(0.0, 0.0, 1.0)};
}

TEST(SearchTreeOBB, SeparatingAxis2DRotatedSquares) {
    // Unit half-size squares, the second turned 45°: they touch when the centre distance is 1 + √2.
    const OrientedBoundingBox a(2, Array3::Zero(), RotatedZ(0.0), Array3(1.0, 1.0, 0.0));
    const double touch = 1.0 + std::sqrt(2.0);
    const OrientedBoundingBox near(2, Array3(touch - 1e-9, 0.0, 0.0), RotatedZ(M_PI / 4), Array3(1.0, 1.0, 0.0));
    const OrientedBoundingBox far(2, Array3(touch + 1e-9, 0.0, 0.0), RotatedZ(M_PI / 4), Array3(1.0, 1.0, 0.0));
    EXPECT_TRUE(a.HasIntersection(near));
    EXPECT_TRUE(near.HasIntersection(a));
    EXPECT_FALSE(a.HasIntersection(far));
    EXPECT_FALSE(far.HasIntersection(a));
}

TEST(SearchTreeOBB, SeparatingAxis3DEdgeEdge) {
    // Two crossed rods along (1,1,0)/√2 and (1,−1,0)/√2, each turned 45° about its own axis: the diamond cross
    // sections reach 0.1·√2 in z, so only the edge×edge axis e_z separates them when the offset exceeds 0.2·√2.
    const auto rod = [](const Array3& axis, double z) {
        const Array3 u = axis.normalized();
        const Array3 w0 = Array3(0.0, 0.0, 1.0), v0 = w0.cross(u);
        const double c = std::cos(M_PI / 4), s = std::sin(M_PI / 4);
        return OrientedBoundingBox(3, Array3(0.0, 0.0, z), {u, c * v0 + s * w0, -s * v0 + c * w0},
                                   Array3(1.0, 0.1, 0.1));
    };
    const auto a = rod(Array3(1.0, 1.0, 0.0), 0.0);
    const double touch = 0.2 * std::sqrt(2.0);
    EXPECT_TRUE(a.HasIntersection(rod(Array3(1.0, -1.0, 0.0), touch - 1e-9)));
    EXPECT_FALSE(a.HasIntersection(rod(Array3(1.0, -1.0, 0.0), touch + 1e-9)));
    EXPECT_FALSE(rod(Array3(1.0, -1.0, 0.0), touch + 1e-9).HasIntersection(a));
}

TEST(SearchTreeOBB, FaceBoxesUseTheThickness) {
    // Parallel faces at gap g intersect iff 2·thickness ≥ g; 2D lines and 3D quads.
    const double gap = 0.05;
    auto node = [](IndexType id, double x, double y, double z) { return std::make_shared<Node>(id, x, y, z); };
    auto lower = CreateGeometry("Line2D2", {node(1, 1.0, 0.0, 0.0), node(2, 0.0, 0.0, 0.0)});
    auto upper = CreateGeometry("Line2D2", {node(3, 0.2, gap, 0.0), node(4, 0.8, gap, 0.0)});
    EXPECT_TRUE(OrientedBoundingBox(*lower, 0.026).HasIntersection(OrientedBoundingBox(*upper, 0.026)));
    EXPECT_FALSE(OrientedBoundingBox(*lower, 0.024).HasIntersection(OrientedBoundingBox(*upper, 0.024)));
    auto quad_lower = CreateGeometry("Quadrilateral3D4", {node(1, 0, 0, 0), node(2, 1, 0, 0), node(3, 1, 1, 0), node(4, 0, 1, 0)});
    auto quad_upper = CreateGeometry("Quadrilateral3D4", {node(5, 0.5, 0.5, gap), node(6, 0.5, 1.5, gap),
                                                          node(7, 1.5, 1.5, gap), node(8, 1.5, 0.5, gap)});
    EXPECT_TRUE(OrientedBoundingBox(*quad_lower, 0.026).HasIntersection(OrientedBoundingBox(*quad_upper, 0.026)));
    EXPECT_FALSE(OrientedBoundingBox(*quad_lower, 0.024).HasIntersection(OrientedBoundingBox(*quad_upper, 0.024)));
    // Side by side in the plane (no overlap): never, whatever the thickness.
    auto quad_beside = CreateGeometry("Quadrilateral3D4", {node(9, 1.1, 0, gap), node(10, 1.1, 1, gap),
                                                           node(11, 2, 1, gap), node(12, 2, 0, gap)});
    EXPECT_FALSE(OrientedBoundingBox(*quad_lower, 0.5).HasIntersection(OrientedBoundingBox(*quad_beside, 0.5)));
}

}  // namespace
}  // namespace contact_app
