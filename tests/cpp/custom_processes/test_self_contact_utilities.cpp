// SPDX-License-Identifier: BSD-3-Clause
/// Self-contact roles: the adjacency visit order and the role rules on hand-made candidate lists.
#include <gtest/gtest.h>

#include "contact_app/kernel/condition.h"
#include "contact_app/kernel/geometries/geometry_factory.h"
#include "custom_processes/self_contact_utilities.h"

namespace contact_app {
namespace {

/// Line faces on @p pairs of node indices into a shared node pool.
struct Faces {
    explicit Faces(const std::vector<std::pair<int, int>>& pairs) {
        for (int i = 0; i < 10; ++i) nodes.push_back(std::make_shared<Node>(i + 1, i, 0.0, 0.0));
        for (std::size_t f = 0; f < pairs.size(); ++f)
            owned.push_back(std::make_shared<Condition>(
                f + 1, CreateGeometry("Line2D2", {nodes[pairs[f].first], nodes[pairs[f].second]})));
        for (const auto& c : owned) faces.push_back(c.get());
    }
    std::vector<Node::Pointer> nodes;
    std::vector<Condition::Pointer> owned;
    std::vector<Condition*> faces;
};

TEST(ContactSearchSelfContact, VisitOrderFollowsTheAdjacency) {
    // Chain 0-1-2-3-4 stored out of order, plus an isolated face (7-8).
    const Faces f({{0, 1}, {3, 4}, {7, 8}, {1, 2}, {2, 3}});
    EXPECT_EQ(SelfContactVisitOrder(f.faces), (std::vector<std::size_t>{0, 3, 4, 1, 2}));
}

TEST(ContactSearchSelfContact, RolesFromCandidatesAndDemotion) {
    // Chain 0-1-2 (faces 0, 1, 2) and a separate face 3. Face 0 sees face 2 → slave / master; face 1 sees
    // face 3 → slave / master, then face 1 is demoted (it shares a node with the master face 2).
    const Faces f({{0, 1}, {1, 2}, {2, 3}, {5, 6}});
    const auto candidates = [](std::size_t i, std::vector<std::size_t>& out) {
        out.clear();
        if (i == 0) out = {0, 1, 2};  // itself and a neighbour are ignored
        if (i == 1) out = {3};
        if (i == 3) out = {1};       // never asked: face 3 is a master by then
    };
    const auto roles = ComputeSelfContactRoles(f.faces, candidates);
    using R = SelfContactRole;
    EXPECT_EQ(roles, (std::vector<R>{R::Slave, R::Master, R::Master, R::Master}));
    // Without candidates nothing is assigned.
    const auto none = ComputeSelfContactRoles(f.faces, [](std::size_t, std::vector<std::size_t>& out) { out.clear(); });
    EXPECT_EQ(none, std::vector<R>(4, R::None));
}

}  // namespace
}  // namespace contact_app
