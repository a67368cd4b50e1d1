// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "contact_app/kernel/condition.h"

namespace contact_app {

/// Role of a face of a surface that may touch itself (contact search with predefined_master_slave false).
enum class SelfContactRole { None, Slave, Master };

/// Candidates of face i: fills the indices j of the faces near face i that pass the geometric filters of
/// the search (orientation, OBB); the roles logic adds the topological ones.
using SelfContactCandidates = std::function<void(std::size_t i, std::vector<std::size_t>& candidates)>;

/// @brief Visit order of the faces: breadth-first through shared nodes, restarting at the lowest unvisited
///        index when a connected piece is exhausted (so neighbours are decided one after the other).
std::vector<std::size_t> SelfContactVisitOrder(const std::vector<Condition*>& faces);

/// @brief Master/slave roles of self contact (Kratos SelfContactUtilities::ComputeSelfContactPairing, our
///        formulation): in SelfContactVisitOrder, a face not yet MASTER whose candidates (not itself, not
///        sharing a node with it, not already SLAVE) are non-empty becomes SLAVE and the candidates MASTER;
///        then a SLAVE face sharing a node with a MASTER face becomes MASTER (its node would carry both roles).
///        Faces without candidates keep None.
/// @param[in] faces the surface faces; @param[in] candidates the geometric candidate query
std::vector<SelfContactRole> ComputeSelfContactRoles(const std::vector<Condition*>& faces,
                                                     const SelfContactCandidates& candidates);

}  // namespace contact_app
