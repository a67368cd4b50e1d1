// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/alm_fast_init_process.h"

#include <iostream>
#include <unordered_map>

#include "contact_app/application.h"
#include "contact_app/kernel/model_part.h"

namespace contact_app {

namespace {

/// Historical value when stored, else the non-historical one.
template <class T>
void SetNodal(Node& node, const Variable<T>& variable, const T& value) {
    if (node.SolutionStepsDataHas(variable)) node.FastGetSolutionStepValue(variable) = value;
    else node.SetValue(variable, value);
}

/// Nodal FRICTION_COEFFICIENT = mean of the adjacent conditions' property value.
void AverageFrictionCoefficients(ModelPart& model_part) {
    std::unordered_map<Node*, std::pair<double, int>> sums;  // Σμ, number of conditions
    bool warned = false;
    for (const auto& condition : model_part.Conditions()) {
        Geometry& geometry = condition->GetGeometry();
        if (geometry.NumberOfGeometryParts() != 0) continue;
        const Properties::Pointer& properties = condition->pGetProperties();
        const bool has_mu = properties && properties->Has(FRICTION_COEFFICIENT);
        if (!has_mu && !warned) {
            std::cerr << "[WARNING] ALMFastInit: condition " << condition->Id()
                      << " has no FRICTION_COEFFICIENT in its properties; 0 is used\n";
            warned = true;
        }
        const double mu = has_mu ? properties->GetValue(FRICTION_COEFFICIENT) : 0.0;
        for (std::size_t i = 0; i < geometry.size(); ++i) {
            auto& entry = sums[&geometry[i]];
            entry.first += mu;
            entry.second += 1;
        }
    }
    for (const auto& node : model_part.Nodes()) {
        const auto found = sums.find(node.get());
        node->SetValue(FRICTION_COEFFICIENT, found == sums.end() ? 0.0 : found->second.first / found->second.second);
    }
}

}  // namespace

void ALMFastInit::Execute() {
    // Monotone renumbering: the order (hence every sorted container) is unchanged.
    IndexType next_id = 0;
    for (const auto& condition : mrModelPart.GetRootModelPart().Conditions()) condition->SetId(++next_id);

    const bool is_frictional = mrModelPart.Is(SLIP);
    const double penalty = mrModelPart.GetProcessInfo().GetValue(INITIAL_PENALTY);
    for (const auto& node : mrModelPart.Nodes()) {
        const bool is_slave = node->IsDefined(SLAVE) ? node->Is(SLAVE) : true;
        if (!is_slave) continue;
        SetNodal(*node, WEIGHTED_GAP, 0.0);
        if (is_frictional) SetNodal(*node, WEIGHTED_SLIP, Array3(Array3::Zero()));
        node->SetValue(INITIAL_PENALTY, penalty);
        node->SetValue(DYNAMIC_FACTOR, 1.0);
        node->SetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE, 0.0);
        if (is_frictional) node->SetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE, Array3(Array3::Zero()));
    }
    for (const auto& condition : mrModelPart.Conditions()) condition->SetValue(NORMAL, Array3(Array3::Zero()));
    if (is_frictional) AverageFrictionCoefficients(mrModelPart);
}

}  // namespace contact_app
