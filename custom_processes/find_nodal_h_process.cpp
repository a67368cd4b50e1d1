// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/find_nodal_h_process.h"

#include <algorithm>
#include <limits>
#include <unordered_map>

#include "contact_app/kernel/model_part.h"
#include "contact_app/kernel/variables.h"

namespace contact_app {

namespace {

/// Lowers the running minimum of every node of @p geometry to its shortest distance to another node of it.
void UpdateMinimumLengths(const Geometry& geometry, std::unordered_map<const Node*, double>& minimum) {
    for (std::size_t i = 0; i < geometry.size(); ++i) {
        for (std::size_t j = i + 1; j < geometry.size(); ++j) {
            const double length = (geometry[i].Coordinates() - geometry[j].Coordinates()).norm();
            for (const Node* node : {&geometry[i], &geometry[j]}) {
                auto [entry, inserted] = minimum.emplace(node, length);
                if (!inserted) entry->second = std::min(entry->second, length);
            }
        }
    }
}

}  // namespace

void FindNodalHProcess::Execute() {
    std::unordered_map<const Node*, double> minimum;
    for (const auto& element : mrModelPart.Elements()) UpdateMinimumLengths(element->GetGeometry(), minimum);
    std::unordered_map<const Node*, double> from_conditions;
    for (const auto& condition : mrModelPart.Conditions())
        if (condition->GetGeometry().NumberOfGeometryParts() == 0)
            UpdateMinimumLengths(condition->GetGeometry(), from_conditions);
    const bool historical = mrModelPart.HasNodalSolutionStepVariable(NODAL_H);
    for (const auto& node : mrModelPart.Nodes()) {
        double h = 0.0;
        if (const auto found = minimum.find(node.get()); found != minimum.end()) h = found->second;
        else if (const auto other = from_conditions.find(node.get()); other != from_conditions.end()) h = other->second;
        if (historical) node->FastGetSolutionStepValue(NODAL_H) = h;
        else node->SetValue(NODAL_H, h);
    }
}

}  // namespace contact_app
