// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/nodal_normal_coupling.h"

#include <map>
#include <unordered_map>
#include <vector>

#include "contact_app/kernel/variables.h"
#include "contact_app/solving/schemes/scheme.h"
#include "custom_conditions/nodal_gap_coupling.h"
#include "custom_conditions/nodal_normal_coupling.h"
#include "custom_utilities/contact_utilities.h"
#include "custom_utilities/mortar_normals.h"

namespace contact_app {

namespace {

const Variable<double>* const kDisplacement[] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};

/// ∂n_m/∂x of one slave node m over the nodes its mean normal reads, with their displacement equation ids.
struct NormalDerivative {
    EquationIdVectorType ids;
    Matrix jacobian;  ///< d × ids.size()
};

/// An assembled pair of "ComputingContact" that records its normal coupling, with its equation ids.
struct CoupledPair {
    const Condition* condition;
    const NodalNormalCouplingSource* source;
    const NodalGapCouplingSource* penalty;  ///< null unless the pair reads the nodal penalty gap
    EquationIdVectorType ids;
};

/// What one build needs: the coupled pairs, ∂n/∂x of their slave nodes, and the penalty pairs by slave node.
struct NormalCouplingData {
    std::vector<CoupledPair> pairs;
    std::unordered_map<IndexType, NormalDerivative> derivatives;
    /// slave node id → (index into penalty_pairs, local index), nodes of two or more penalty pairs only
    std::map<IndexType, std::vector<std::pair<std::size_t, int>>> penalty_nodes;
    std::vector<std::size_t> penalty_pairs;  ///< indices into pairs of those that read the nodal penalty gap
};

NormalCouplingData CollectNormalCoupling(ModelPart& rModelPart, const ProcessInfo& rProcessInfo) {
    NormalCouplingData data;
    ModelPart* computing = ContactUtilities::FindContactPart(rModelPart, "ComputingContact");
    ModelPart* contact = ContactUtilities::FindContactPart(rModelPart, "Contact");
    if (computing == nullptr || contact == nullptr) return data;
    for (const auto& condition : computing->Conditions()) {
        const auto* source = dynamic_cast<const NodalNormalCouplingSource*>(condition.get());
        if (source == nullptr || !source->CouplesNodalNormals(rProcessInfo) || !IsAssembled(*condition)) continue;
        data.pairs.push_back({condition.get(), source, dynamic_cast<const NodalGapCouplingSource*>(condition.get()), {}});
        condition->EquationIdVector(data.pairs.back().ids, rProcessInfo);
    }
    if (data.pairs.empty()) return data;
    const MeanNormalDerivatives mean_normal(*contact);
    std::vector<const Node*> nodes;
    for (std::size_t p = 0; p < data.pairs.size(); ++p) {
        const Geometry& slave = data.pairs[p].condition->GetGeometry();
        for (std::size_t j = 0; j < slave.size(); ++j) {
            if (data.derivatives.count(slave[j].Id()) != 0) continue;
            NormalDerivative derivative;
            if (mean_normal.Compute(slave[j], nodes, derivative.jacobian)) {
                const auto dim = static_cast<std::size_t>(derivative.jacobian.rows());
                derivative.ids.resize(nodes.size() * dim);
                for (std::size_t k = 0; k < nodes.size(); ++k)
                    for (std::size_t c = 0; c < dim; ++c)
                        derivative.ids[k * dim + c] = nodes[k]->GetDof(*kDisplacement[c]).EquationId();
            }
            data.derivatives.emplace(slave[j].Id(), std::move(derivative));
        }
    }
    std::vector<const Condition*> penalty;
    for (std::size_t p = 0; p < data.pairs.size(); ++p)
        if (data.pairs[p].penalty != nullptr) {
            data.penalty_pairs.push_back(p);
            penalty.push_back(data.pairs[p].condition);
        }
    data.penalty_nodes = ContactUtilities::SharedSlaveNodes(penalty);
    return data;
}

/// ∂n_m/∂x of local slave node @p m of @p pair (empty ids when its faces' normals cancel).
const NormalDerivative& DerivativeOf(const NormalCouplingData& data, const CoupledPair& pair, int m) {
    return data.derivatives.at(pair.condition->GetGeometry()[static_cast<std::size_t>(m)].Id());
}

}  // namespace

void NodalNormalCoupling::AddGraph(ModelPart& rModelPart, const ProcessInfo& rProcessInfo, const BlockSink& rSink) {
    const NormalCouplingData data = CollectNormalCoupling(rModelPart, rProcessInfo);
    for (const CoupledPair& pair : data.pairs)
        for (std::size_t j = 0; j < pair.condition->GetGeometry().size(); ++j)
            rSink(pair.ids, DerivativeOf(data, pair, static_cast<int>(j)).ids, nullptr);
    // The penalty pair c of a node reads the normals of every other pair d of the node through X_j and T_j.
    for (const auto& [node_id, node_pairs] : data.penalty_nodes)
        for (const auto& [c, jc] : node_pairs)
            for (const auto& [d, jd] : node_pairs) {
                if (c == d) continue;
                const CoupledPair& pair_d = data.pairs[data.penalty_pairs[d]];
                for (std::size_t m = 0; m < pair_d.condition->GetGeometry().size(); ++m)
                    rSink(data.pairs[data.penalty_pairs[c]].ids, DerivativeOf(data, pair_d, static_cast<int>(m)).ids,
                          nullptr);
            }
}

void NodalNormalCoupling::AddLHS(ModelPart& rModelPart, const ProcessInfo& rProcessInfo, const BlockSink& rSink) {
    const NormalCouplingData data = CollectNormalCoupling(rModelPart, rProcessInfo);
    Matrix force_per_normal, block;
    // −B^c_j ∂n_j/∂x: the pair's own dependence on the normals of its slave nodes.
    for (const CoupledPair& pair : data.pairs)
        for (std::size_t j = 0; j < pair.condition->GetGeometry().size(); ++j) {
            const NormalDerivative& derivative = DerivativeOf(data, pair, static_cast<int>(j));
            if (derivative.ids.empty() || !pair.source->GetNodalNormalCoupling(static_cast<int>(j), force_per_normal))
                continue;
            block.noalias() = -force_per_normal * derivative.jacobian;
            rSink(pair.ids, derivative.ids, &block);
        }
    // −b^c_j (∂X_j/∂n_m)ᵀ ∂n_m/∂x − B^c_j ∂T_j/∂n_m ∂n_m/∂x over the slave nodes m of the other penalty pairs d of node j.
    for (const auto& [node_id, node_pairs] : data.penalty_nodes) {
        std::vector<NodalGapCouplingTerms> terms(node_pairs.size());
        std::vector<bool> coupled(node_pairs.size());
        for (std::size_t i = 0; i < node_pairs.size(); ++i) {
            const auto& [p, j] = node_pairs[i];
            coupled[i] = data.pairs[data.penalty_pairs[p]].penalty->GetNodalGapCoupling(j, terms[i]) &&
                         terms[i].gap_normal_gradient.size() > 0;
        }
        for (std::size_t c = 0; c < node_pairs.size(); ++c) {
            if (!coupled[c]) continue;
            for (std::size_t d = 0; d < node_pairs.size(); ++d) {
                if (d == c || !coupled[d]) continue;
                const CoupledPair& pair_d = data.pairs[data.penalty_pairs[node_pairs[d].first]];
                const bool reads_slip = terms[c].reads_slip && terms[d].reads_slip;
                for (std::size_t m = 0; m < pair_d.condition->GetGeometry().size(); ++m) {
                    const NormalDerivative& derivative = DerivativeOf(data, pair_d, static_cast<int>(m));
                    if (derivative.ids.empty()) continue;
                    const auto dim = derivative.jacobian.rows();
                    const auto column = static_cast<Eigen::Index>(m) * dim;
                    block.noalias() = -terms[c].force_per_gap *
                                      (terms[d].gap_normal_gradient.segment(column, dim).transpose() * derivative.jacobian);
                    if (reads_slip)
                        block.noalias() -= terms[c].force_per_slip *
                                           (terms[d].slip_normal_gradient.middleCols(column, dim) * derivative.jacobian);
                    rSink(data.pairs[data.penalty_pairs[node_pairs[c].first]].ids, derivative.ids, &block);
                }
            }
        }
    }
}

}  // namespace contact_app
