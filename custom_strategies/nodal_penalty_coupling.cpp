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

/// The assembled penalty pairs of the root's "ComputingContact" part and their equation ids (read once per call).
struct PenaltyPairs {
    std::vector<const Condition*> conditions;
    std::vector<EquationIdVectorType> ids;
};

PenaltyPairs CollectPenaltyPairs(ModelPart& rModelPart, const ProcessInfo& rProcessInfo) {
    PenaltyPairs pairs;
    ModelPart* computing = ContactUtilities::FindContactPart(rModelPart, "ComputingContact");
    if (computing == nullptr) return pairs;
    for (const auto& condition : computing->Conditions()) {
        if (dynamic_cast<const NodalGapCouplingSource*>(condition.get()) == nullptr || !IsAssembled(*condition))
            continue;
        pairs.conditions.push_back(condition.get());
        pairs.ids.emplace_back();
        condition->EquationIdVector(pairs.ids.back(), rProcessInfo);
    }
    return pairs;
}

}  // namespace

void NodalPenaltyCoupling::AddGraph(ModelPart& rModelPart, const ProcessInfo& rProcessInfo, const BlockSink& rSink) {
    const PenaltyPairs pairs = CollectPenaltyPairs(rModelPart, rProcessInfo);
    for (const auto& [node_id, node_pairs] : ContactUtilities::SharedSlaveNodes(pairs.conditions))
        for (const auto& [c, jc] : node_pairs)
            for (const auto& [d, jd] : node_pairs)
                if (d != c) rSink(pairs.ids[c], pairs.ids[d], nullptr);
}

void NodalPenaltyCoupling::AddLHS(ModelPart& rModelPart, const ProcessInfo& rProcessInfo, const BlockSink& rSink) {
    const PenaltyPairs pairs = CollectPenaltyPairs(rModelPart, rProcessInfo);
    Matrix block;
    for (const auto& [node_id, node_pairs] : ContactUtilities::SharedSlaveNodes(pairs.conditions)) {
        std::vector<NodalGapCouplingTerms> terms(node_pairs.size());
        std::vector<bool> coupled(node_pairs.size());
        for (std::size_t i = 0; i < node_pairs.size(); ++i) {
            const auto& [p, j] = node_pairs[i];
            coupled[i] = dynamic_cast<const NodalGapCouplingSource&>(*pairs.conditions[p]).GetNodalGapCoupling(j, terms[i]);
        }
        for (std::size_t c = 0; c < node_pairs.size(); ++c) {
            if (!coupled[c]) continue;
            for (std::size_t d = 0; d < node_pairs.size(); ++d) {
                // A pair without terms (isolated now) adds nothing to G_j or T_j, so nothing to differentiate.
                if (d == c || !coupled[d]) continue;
                block = -terms[c].force_per_gap * terms[d].gap_gradient.transpose();
                // A frictional node: every pair of it reads T_j (stick traction or slip direction; the state is nodal).
                if (terms[c].reads_slip && terms[d].reads_slip) block -= terms[c].force_per_slip * terms[d].slip_gradient;
                rSink(pairs.ids[node_pairs[c].first], pairs.ids[node_pairs[d].first], &block);
            }
        }
    }
}

}  // namespace contact_app
