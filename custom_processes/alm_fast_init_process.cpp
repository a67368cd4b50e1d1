// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/alm_fast_init_process.h"

#include <cmath>
#include <unordered_map>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/model_part.h"

namespace contact_app {

namespace {

/// Historical value when stored, else the non-historical one.
template <class T>
void SetNodal(Node& node, const Variable<T>& variable, const T& value) {
    if (node.SolutionStepsDataHas(variable)) node.FastGetSolutionStepValue(variable) = value;
    else node.SetValue(variable, value);
}

/// The μ a pair sub model part (ContactSub<key>) prescribes: that of its pair properties (the contact process puts
/// the "friction_coefficients" setting, or the body's material value, there), if it holds exactly one with μ.
const Properties* PairFrictionProperties(const ModelPart& pair_part) {
    const Properties* found = nullptr;
    for (const auto& properties : pair_part.PropertiesArray()) {
        if (!properties->Has(FRICTION_COEFFICIENT)) continue;
        if (found != nullptr) return nullptr;  // ambiguous: fall back to the conditions' own properties
        found = properties.get();
    }
    return found;
}

/// Nodal FRICTION_COEFFICIENT = mean over the adjacent interface conditions of μ, taken from the pair properties of
/// the ContactSub<key> part holding the condition, else from the condition's own properties.
/// @throws InputError naming the condition when neither gives μ (a frictional run must not silently use 0)
void AverageFrictionCoefficients(ModelPart& model_part) {
    std::unordered_map<const Condition*, const Properties*> pair_properties;
    for (const ModelPart* sub : model_part.SubModelParts())
        if (const Properties* properties = PairFrictionProperties(*sub))
            for (const auto& condition : sub->Conditions()) pair_properties.emplace(condition.get(), properties);
    std::unordered_map<Node*, std::pair<double, int>> sums;  // Σμ, number of conditions
    for (const auto& condition : model_part.Conditions()) {
        Geometry& geometry = condition->GetGeometry();
        if (geometry.NumberOfGeometryParts() != 0) continue;
        const auto pair = pair_properties.find(condition.get());
        const Properties* properties = pair != pair_properties.end() ? pair->second : condition->pGetProperties().get();
        CONTACT_CHECK(properties != nullptr && properties->Has(FRICTION_COEFFICIENT), InputError,
                      "ALMFastInit: interface condition ", condition->Id(), " of model part ", model_part.FullName(),
                      " has no friction coefficient: neither its pair properties nor its own properties (id ",
                      condition->pGetProperties() ? condition->pGetProperties()->Id() : 0,
                      ") define FRICTION_COEFFICIENT\n  expected: μ ≥ 0 for a frictional contact",
                      "\n  fix: set \"friction_coefficients\" of the contact process for this pair, or FRICTION_COEFFICIENT in",
                      " the materials of the interface");
        const double mu = properties->GetValue(FRICTION_COEFFICIENT);
        CONTACT_CHECK(std::isfinite(mu) && mu >= 0.0, InputError, "ALMFastInit: interface condition ", condition->Id(),
                      " has FRICTION_COEFFICIENT ", mu, " (properties ", properties->Id(), ")",
                      "\n  expected: a finite μ ≥ 0\n  fix: correct \"friction_coefficients\" or the materials file");
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
