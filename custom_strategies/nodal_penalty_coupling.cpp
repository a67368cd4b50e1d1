// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/nodal_penalty_coupling.h"

#include <map>
#include <vector>

#include "contact_app/solving/schemes/scheme.h"
#include "custom_conditions/nodal_gap_coupling.h"
#include "custom_utilities/contact_utilities.h"

namespace contact_app {

namespace {

/// One pair of a slave node: the pair, the node's local index in it.
struct NodePair {
    Condition* condition;
    NodalGapCouplingSource* source;
    int local_index;
};

/// Slave node id → its assembled penalty pairs, for the nodes with two or more (a single pair holds its whole tangent).
std::map<IndexType, std::vector<NodePair>> PairsOfSlaveNodes(ModelPart& rModelPart) {
    std::map<IndexType, std::vector<NodePair>> pairs;
    ModelPart* computing = ContactUtilities::FindContactPart(rModelPart, "ComputingContact");
    if (computing == nullptr) return pairs;
    for (const auto& condition : computing->Conditions()) {
        auto* source = dynamic_cast<NodalGapCouplingSource*>(condition.get());
        if (source == nullptr || !IsAssembled(*condition)) continue;
        const Geometry& slave = condition->GetGeometry();
        for (std::size_t j = 0; j < slave.size(); ++j)
            pairs[slave[j].Id()].push_back({condition.get(), source, static_cast<int>(j)});
    }
    for (auto it = pairs.begin(); it != pairs.end();) it = it->second.size() < 2 ? pairs.erase(it) : std::next(it);
    return pairs;
}

}  // namespace

void NodalPenaltyCoupling::AddGraph(ModelPart& rModelPart, const ProcessInfo& rProcessInfo, const BlockSink& rSink) {
    EquationIdVectorType rows, columns;
    for (const auto& [node_id, pairs] : PairsOfSlaveNodes(rModelPart)) {
        for (const NodePair& c : pairs) {
            c.condition->EquationIdVector(rows, rProcessInfo);
            for (const NodePair& d : pairs) {
                if (d.condition == c.condition) continue;
                d.condition->EquationIdVector(columns, rProcessInfo);
                rSink(rows, columns, nullptr);
            }
        }
    }
}

void NodalPenaltyCoupling::AddLHS(ModelPart& rModelPart, const ProcessInfo& rProcessInfo, const BlockSink& rSink) {
    EquationIdVectorType rows, columns;
    Matrix block;
    for (const auto& [node_id, pairs] : PairsOfSlaveNodes(rModelPart)) {
        std::vector<NodalGapCouplingTerms> terms(pairs.size());
        std::vector<bool> coupled(pairs.size());
        for (std::size_t c = 0; c < pairs.size(); ++c)
            coupled[c] = pairs[c].source->GetNodalGapCoupling(pairs[c].local_index, terms[c]);
        for (std::size_t c = 0; c < pairs.size(); ++c) {
            if (!coupled[c]) continue;
            pairs[c].condition->EquationIdVector(rows, rProcessInfo);
            for (std::size_t d = 0; d < pairs.size(); ++d) {
                // A pair without terms (isolated now) adds nothing to G_j, so nothing to differentiate.
                if (d == c || !coupled[d]) continue;
                pairs[d].condition->EquationIdVector(columns, rProcessInfo);
                block = -terms[c].force_per_gap * terms[d].gap_gradient.transpose();
                rSink(rows, columns, &block);
            }
        }
    }
}

}  // namespace contact_app
