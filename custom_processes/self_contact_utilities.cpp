// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/self_contact_utilities.h"

#include <deque>
#include <unordered_map>
#include <unordered_set>

namespace contact_app {
namespace {

bool ShareANode(const Geometry& a, const Geometry& b) {
    for (std::size_t i = 0; i < a.PointsNumber(); ++i)
        for (std::size_t j = 0; j < b.PointsNumber(); ++j)
            if (&a[i] == &b[j]) return true;
    return false;
}

}  // namespace

std::vector<std::size_t> SelfContactVisitOrder(const std::vector<Condition*>& faces) {
    std::unordered_map<const Node*, std::vector<std::size_t>> faces_of_node;
    for (std::size_t i = 0; i < faces.size(); ++i) {
        const Geometry& g = faces[i]->GetGeometry();
        for (std::size_t k = 0; k < g.PointsNumber(); ++k) faces_of_node[&g[k]].push_back(i);
    }
    std::vector<std::size_t> order;
    order.reserve(faces.size());
    std::vector<bool> visited(faces.size(), false);
    std::deque<std::size_t> queue;
    for (std::size_t start = 0; start < faces.size(); ++start) {
        if (visited[start]) continue;
        visited[start] = true;
        queue.push_back(start);
        while (!queue.empty()) {
            const std::size_t i = queue.front();
            queue.pop_front();
            order.push_back(i);
            const Geometry& g = faces[i]->GetGeometry();
            for (std::size_t k = 0; k < g.PointsNumber(); ++k)
                for (const std::size_t j : faces_of_node[&g[k]])
                    if (!visited[j]) {
                        visited[j] = true;
                        queue.push_back(j);
                    }
        }
    }
    return order;
}

std::vector<SelfContactRole> ComputeSelfContactRoles(const std::vector<Condition*>& faces,
                                                     const SelfContactCandidates& candidates) {
    std::vector<SelfContactRole> role(faces.size(), SelfContactRole::None);
    std::vector<std::size_t> found;
    for (const std::size_t i : SelfContactVisitOrder(faces)) {
        if (role[i] == SelfContactRole::Master) continue;
        candidates(i, found);
        bool paired = false;
        for (const std::size_t j : found) {
            if (j == i || role[j] == SelfContactRole::Slave) continue;
            if (ShareANode(faces[i]->GetGeometry(), faces[j]->GetGeometry())) continue;
            role[j] = SelfContactRole::Master;
            paired = true;
        }
        if (paired) role[i] = SelfContactRole::Slave;
    }
    std::unordered_set<const Node*> master_nodes;
    for (std::size_t i = 0; i < faces.size(); ++i)
        if (role[i] == SelfContactRole::Master)
            for (std::size_t k = 0; k < faces[i]->GetGeometry().PointsNumber(); ++k)
                master_nodes.insert(&faces[i]->GetGeometry()[k]);
    for (std::size_t i = 0; i < faces.size(); ++i) {
        if (role[i] != SelfContactRole::Slave) continue;
        const Geometry& g = faces[i]->GetGeometry();
        for (std::size_t k = 0; k < g.PointsNumber(); ++k)
            if (master_nodes.count(&g[k]) != 0) role[i] = SelfContactRole::Master;
    }
    return role;
}

}  // namespace contact_app
