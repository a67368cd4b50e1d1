// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/search_tree.h"

#include <algorithm>
#include <numeric>

#include "contact_app/kernel/exceptions.h"

namespace contact_app {
namespace {

/// Squared distance from @p point to the box [lo, hi] (0 inside).
double SquaredDistanceToBox(const Array3& point, const Array3& lo, const Array3& hi) {
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double excess = std::max({lo[k] - point[k], 0.0, point[k] - hi[k]});
        sum += excess * excess;
    }
    return sum;
}

bool BoxesOverlap(const Array3& lo_a, const Array3& hi_a, const Array3& lo_b, const Array3& hi_b) {
    for (int k = 0; k < 3; ++k)
        if (hi_a[k] < lo_b[k] || hi_b[k] < lo_a[k]) return false;
    return true;
}

bool Inside(const Array3& point, const Array3& lo, const Array3& hi) {
    for (int k = 0; k < 3; ++k)
        if (point[k] < lo[k] || point[k] > hi[k]) return false;
    return true;
}

}  // namespace

void SearchTree::Build(const std::vector<Array3>& points, std::size_t bucket_size) {
    CONTACT_CHECK(bucket_size > 0, InputError, "SearchTree: bucket_size must be ≥ 1 (got 0)",
                  "\n  fix: set search_parameters.bucket_size to a positive value (default 4)");
    mPoints = points;
    mBucketSize = bucket_size;
    mOrder.resize(points.size());
    std::iota(mOrder.begin(), mOrder.end(), std::size_t(0));
    mNodes.clear();
    // A balanced binary tree with leaves of ≥ bucket_size/2 points has < 4n/bucket_size + 1 nodes.
    mNodes.reserve(4 * points.size() / bucket_size + 2);
    if (!points.empty()) BuildNode(0, points.size());
}

std::size_t SearchTree::BuildNode(std::size_t begin, std::size_t end) {
    const std::size_t index = mNodes.size();
    mNodes.emplace_back();
    Array3 lo = mPoints[mOrder[begin]], hi = lo;
    for (std::size_t i = begin + 1; i < end; ++i) {
        lo = lo.cwiseMin(mPoints[mOrder[i]]);
        hi = hi.cwiseMax(mPoints[mOrder[i]]);
    }
    mNodes[index].min_corner = lo;
    mNodes[index].max_corner = hi;
    mNodes[index].begin = begin;
    mNodes[index].end = end;
    if (end - begin <= mBucketSize) return index;
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    if (hi[axis] - lo[axis] <= 0.0) return index;  // coincident points: keep them in one leaf
    const std::size_t middle = begin + (end - begin) / 2;
    std::nth_element(mOrder.begin() + begin, mOrder.begin() + middle, mOrder.begin() + end,
                     [&](std::size_t a, std::size_t b) { return mPoints[a][axis] < mPoints[b][axis]; });
    const std::size_t left = BuildNode(begin, middle);
    const std::size_t right = BuildNode(middle, end);
    mNodes[index].left = left;  // mNodes may have reallocated: index, not reference
    mNodes[index].right = right;
    return index;
}

void SearchTree::SearchInRadius(const Array3& center, double radius, std::vector<std::size_t>& results,
                                std::size_t max_results) const {
    results.clear();
    if (mNodes.empty() || radius < 0.0) return;
    const double radius2 = radius * radius;
    std::size_t stack[128];
    std::size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const TreeNode& node = mNodes[stack[--top]];
        if (SquaredDistanceToBox(center, node.min_corner, node.max_corner) > radius2) continue;
        if (node.left == 0) {
            for (std::size_t i = node.begin; i < node.end; ++i) {
                if ((mPoints[mOrder[i]] - center).squaredNorm() > radius2) continue;
                results.push_back(mOrder[i]);
                if (max_results != 0 && results.size() >= max_results) return;
            }
            continue;
        }
        stack[top++] = node.left;
        stack[top++] = node.right;
    }
}

void SearchTree::SearchInBox(const Array3& min_point, const Array3& max_point, std::vector<std::size_t>& results,
                             std::size_t max_results) const {
    results.clear();
    if (mNodes.empty()) return;
    std::size_t stack[128];
    std::size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const TreeNode& node = mNodes[stack[--top]];
        if (!BoxesOverlap(node.min_corner, node.max_corner, min_point, max_point)) continue;
        if (node.left == 0) {
            for (std::size_t i = node.begin; i < node.end; ++i) {
                if (!Inside(mPoints[mOrder[i]], min_point, max_point)) continue;
                results.push_back(mOrder[i]);
                if (max_results != 0 && results.size() >= max_results) return;
            }
            continue;
        }
        stack[top++] = node.left;
        stack[top++] = node.right;
    }
}

std::size_t SearchTree::Depth() const { return mNodes.empty() ? 0 : DepthBelow(0); }

std::size_t SearchTree::DepthBelow(std::size_t node) const {
    const TreeNode& n = mNodes[node];
    if (n.left == 0) return 1;
    return 1 + std::max(DepthBelow(n.left), DepthBelow(n.right));
}

}  // namespace contact_app
