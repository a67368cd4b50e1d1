// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/nodal_penalty_coupling.h"

#include <map>
#include <utility>
#include <vector>

#include "contact_app/solving/schemes/scheme.h"
#include "custom_conditions/nodal_gap_coupling.h"
#include "custom_utilities/contact_utilities.h"

namespace contact_app {

namespace {

/// One pair of a slave node: the pair, its equation ids, the node's local index in it.
struct NodePair {
    const NodalGapCouplingSource* source;
    const EquationIdVectorType* ids;
    int local_index;
};

/// The assembled penalty pairs of the root's "ComputingContact" part with their equation ids (read once per call).
std::vector<std::pair<Condition*, EquationIdVectorType>> PenaltyPairs(ModelPart& rModelPart,
                                                                      const ProcessInfo& rProcessInfo) {
    std::vector<std::pair<Condition*, EquationIdVectorType>> pairs;
    ModelPart* computing = ContactUtilities::FindContactPart(rModelPart, "ComputingContact");
    if (computing == nullptr) return pairs;
    for (const auto& condition : computing->Conditions()) {
        if (dynamic_cast<const NodalGapCouplingSource*>(condition.get()) == nullptr || !IsAssembled(*condition))
            continue;
        pairs.emplace_back(condition.get(), EquationIdVectorType{});
        condition->EquationIdVector(pairs.back().second, rProcessInfo);
    }
    return pairs;
}

/// Slave node id → its pairs, for the nodes with two or more (a single pair holds its whole tangent).
std::map<IndexType, std::vector<NodePair>> PairsOfSlaveNodes(
    const std::vector<std::pair<Condition*, EquationIdVectorType>>& penalty_pairs) {
    std::map<IndexType, std::vector<NodePair>> pairs;
    for (const auto& [condition, ids] : penalty_pairs) {
        const auto* source = dynamic_cast<const NodalGapCouplingSource*>(condition);
        const Geometry& slave = condition->GetGeometry();
        for (std::size_t j = 0; j < slave.size(); ++j)
            pairs[slave[j].Id()].push_back({source, &ids, static_cast<int>(j)});
    }
    for (auto it = pairs.begin(); it != pairs.end();) it = it->second.size() < 2 ? pairs.erase(it) : std::next(it);
    return pairs;
}

}  // namespace

void NodalPenaltyCoupling::AddGraph(ModelPart& rModelPart, const ProcessInfo& rProcessInfo, const BlockSink& rSink) {
    const auto penalty_pairs = PenaltyPairs(rModelPart, rProcessInfo);
    for (const auto& [node_id, pairs] : PairsOfSlaveNodes(penalty_pairs))
        for (const NodePair& c : pairs)
            for (const NodePair& d : pairs)
                if (d.ids != c.ids) rSink(*c.ids, *d.ids, nullptr);
}

void NodalPenaltyCoupling::AddLHS(ModelPart& rModelPart, const ProcessInfo& rProcessInfo, const BlockSink& rSink) {
    const auto penalty_pairs = PenaltyPairs(rModelPart, rProcessInfo);
    Matrix block;
    for (const auto& [node_id, pairs] : PairsOfSlaveNodes(penalty_pairs)) {
        std::vector<NodalGapCouplingTerms> terms(pairs.size());
        std::vector<bool> coupled(pairs.size());
        for (std::size_t c = 0; c < pairs.size(); ++c)
            coupled[c] = pairs[c].source->GetNodalGapCoupling(pairs[c].local_index, terms[c]);
        for (std::size_t c = 0; c < pairs.size(); ++c) {
            if (!coupled[c]) continue;
            for (std::size_t d = 0; d < pairs.size(); ++d) {
                // A pair without terms (isolated now) adds nothing to G_j or T_j, so nothing to differentiate.
                if (d == c || !coupled[d]) continue;
                block = -terms[c].force_per_gap * terms[d].gap_gradient.transpose();
                // A slipping node: every pair of it slips (the flag is nodal), its direction reads T_j.
                if (terms[c].slipping && terms[d].slipping) block -= terms[c].force_per_slip * terms[d].slip_gradient;
                rSink(*pairs[c].ids, *pairs[d].ids, &block);
            }
        }
    }
}

}  // namespace contact_app
