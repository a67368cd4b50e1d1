// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "contact_app/kernel/condition.h"
#include "custom_processes/search_tree.h"

namespace contact_app {

/// @brief Signed distance t with x + t·d on the master face (line: the segment; surface: the face, through its
///        plane and an edge test), or nothing when d is parallel to the face or misses it.
/// @param[in] x point; @param[in] d direction (need not be unit: t is in units of |d|)
/// @param[in] master a line (2D) or planar convex surface (3D) face; a warped quadrilateral is taken as its mean
///            plane, with the face's NORMAL value
std::optional<double> ProjectAlong(const Array3& x, const Array3& d, const Condition& master);

/// A slave node inside the master body: behind its nearest master face, with opposed normals.
struct PenetratingNode {
    Node* node = nullptr;
    Condition* master = nullptr;  ///< the master face the node is behind (not owned)
    double depth = 0.0;           ///< distance behind that face, > 0
};

/// @brief The slave nodes that lie inside the master body, whatever their distance (the check of the contact
///        search's set-up, docs/theory/contact_search.md "Initial penetration").
///
/// For each node x the master faces whose centre can hold the closest face point are found in @p tree (radius
/// doubled from @p max_master_radius until a centre is found, then widened by 2·@p max_master_radius). Among
/// those on which x projects along the face normal, the one with the smallest |t| decides: x penetrates when it
/// is behind that face (t < 0) and the node normal opposes the face normal.
/// @param[in] nodes slave nodes (NORMAL historical, zero taken as opposed)
/// @param[in] masters master faces with their NORMAL, @p tree built over their centres in this order
/// @param[in] tree search tree over the centres of @p masters (its indices are positions in @p masters)
/// @param[in] max_master_radius largest distance from a master face centre to its nodes (> 0)
/// @param[in] same_body faces for which this is true are not looked at for that node (the node's own surface)
/// @return the penetrating nodes, in the order of @p nodes
std::vector<PenetratingNode> FindPenetratingNodes(
    const std::vector<Node*>& nodes, const std::vector<Condition*>& masters, const SearchTree& tree,
    double max_master_radius, const std::function<bool(const Node&, const Condition&)>& same_body);

}  // namespace contact_app
