// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <vector>

#include "contact_app/kernel/types.h"

namespace contact_app {

/// Static kd-tree over points (the broad phase of the contact search: the points are the centres of the
/// master faces, as the reference's KD-tree of PointObjects). Built once per search in O(n log n): each
/// node splits its points at the median (std::nth_element) of the axis of largest extent and stores the
/// bounding box of its points; leaves hold at most `bucket_size` points. Queries prune whole subtrees by
/// their box, O(log n + k) for k results on well-spread points. Immutable after Build(); not thread-safe
/// while building, reentrant for queries.
class SearchTree {
public:
    SearchTree() = default;

    /// @brief (Re)builds the tree.
    /// @param[in] points n points (only the first 3 components); the tree keeps a copy
    /// @param[in] bucket_size maximum points per leaf (≥ 1)
    /// @throws InputError if @p bucket_size is 0
    void Build(const std::vector<Array3>& points, std::size_t bucket_size = 4);

    /// @brief Indices (into the Build() array) of the points with |p − @p center| ≤ @p radius.
    /// @param[in] center centre of the search sphere (only the first 3 components)
    /// @param[in] radius search radius (≥ 0), same length unit as the points
    /// @param[out] results cleared, then filled (unordered)
    /// @param[in] max_results stop after this many (the reference's allocation_size); 0 = no limit
    void SearchInRadius(const Array3& center, double radius, std::vector<std::size_t>& results,
                        std::size_t max_results = 0) const;

    /// @brief Indices of the points inside the closed axis-aligned box [@p min_point, @p max_point].
    /// @param[in] min_point,max_point lowest and highest corner of the box (componentwise min ≤ max)
    /// @param[out] results cleared, then filled (unordered)
    /// @param[in] max_results as SearchInRadius
    void SearchInBox(const Array3& min_point, const Array3& max_point, std::vector<std::size_t>& results,
                     std::size_t max_results = 0) const;

    std::size_t NumberOfPoints() const { return mPoints.size(); }
    std::size_t NumberOfTreeNodes() const { return mNodes.size(); }
    /// Depth of the deepest leaf (1 for a single leaf), to check the balance.
    std::size_t Depth() const;

private:
    struct TreeNode {
        Array3 min_corner, max_corner;  // box of the points below
        std::size_t begin = 0, end = 0; // range in mOrder
        std::size_t left = 0, right = 0; // children (0 = leaf; the root is node 0, never a child)
    };
    std::size_t BuildNode(std::size_t begin, std::size_t end);
    std::size_t DepthBelow(std::size_t node) const;

    std::vector<Array3> mPoints;
    std::vector<std::size_t> mOrder;  // permutation of the point indices, leaf ranges contiguous
    std::vector<TreeNode> mNodes;
    std::size_t mBucketSize = 4;
};

}  // namespace contact_app
