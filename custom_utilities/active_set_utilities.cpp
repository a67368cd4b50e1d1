// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/active_set_utilities.h"

#include <limits>
#include <vector>

#include "contact_app/application.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/model_part.h"

namespace contact_app::ActiveSetUtilities {

namespace {

constexpr double kMachineEpsilon = std::numeric_limits<double>::epsilon();

/// The SLAVE nodes to update, or none when the set is frozen (simplified semi-smooth Newton after iteration 1).
std::vector<Node*> SlaveNodesToUpdate(ModelPart& model_part) {
    std::vector<Node*> nodes;
    const bool update = model_part.Is(INTERACTION) ||
                        model_part.GetProcessInfo().GetValue(NL_ITERATION_NUMBER) == 1;
    if (!update) return nodes;
    ModelPart& contact = model_part.HasSubModelPart("Contact") ? model_part.GetSubModelPart("Contact") : model_part;
    for (const auto& node : contact.Nodes())
        if (node->Is(SLAVE)) nodes.push_back(node.get());
    return nodes;
}

double Penalty(const Node& node, const ProcessInfo& process_info) {
    return node.Has(INITIAL_PENALTY) ? node.GetValue(INITIAL_PENALTY) : process_info.GetValue(INITIAL_PENALTY);
}

double ScaleFactor(const ProcessInfo& process_info, const char* function) {
    CONTACT_CHECK(process_info.Has(SCALE_FACTOR), InputError, function,
                  ": SCALE_FACTOR is not set in the ProcessInfo\n  fix: run ALMVariablesCalculationProcess or set",
                  " ProcessInfo[SCALE_FACTOR] before updating the active set");
    return process_info.GetValue(SCALE_FACTOR);
}

/// Historical value when stored (as the conditions write it), else the non-historical one.
template <class T>
T& NodalValue(Node& node, const Variable<T>& variable) {
    return node.SolutionStepsDataHas(variable) ? node.FastGetSolutionStepValue(variable)
                                               : node.GetOrCreateValue(variable);
}

/// Sets ACTIVE to @p active; returns 1 if it changed.
std::size_t UpdateActive(Node& node, bool active) {
    const bool changed = node.Is(ACTIVE) != active;
    node.Set(ACTIVE, active);
    return changed ? 1 : 0;
}

/// Sets SLIP to @p slip; returns 1 if it changed.
std::size_t UpdateSlip(Node& node, bool slip) {
    const bool changed = node.Is(SLIP) != slip;
    node.Set(SLIP, slip);
    return changed ? 1 : 0;
}

/// v/|v|, or the zero vector for a zero v.
Array3 Direction(const Array3& v) {
    const double norm = v.norm();
    return norm > 0.0 ? Array3(v / norm) : Array3(Array3::Zero());
}

}  // namespace

std::size_t ComputePenaltyFrictionlessActiveSet(ModelPart& model_part) {
    const ProcessInfo& process_info = model_part.GetProcessInfo();
    std::size_t flips = 0;
    for (Node* node : SlaveNodesToUpdate(model_part)) {
        const double augmented_normal = Penalty(*node, process_info) * NodalValue(*node, WEIGHTED_GAP);
        node->SetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE, augmented_normal);
        flips += UpdateActive(*node, augmented_normal < 0.0);
    }
    return flips;
}

std::size_t ComputeALMFrictionlessActiveSet(ModelPart& model_part) {
    const ProcessInfo& process_info = model_part.GetProcessInfo();
    const double k = ScaleFactor(process_info, "ComputeALMFrictionlessActiveSet");
    std::size_t flips = 0;
    for (Node* node : SlaveNodesToUpdate(model_part)) {
        double& lambda = NodalValue(*node, LAGRANGE_MULTIPLIER_CONTACT_PRESSURE);
        const double augmented_normal = k * lambda + Penalty(*node, process_info) * NodalValue(*node, WEIGHTED_GAP);
        node->SetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE, augmented_normal);
        const bool active = augmented_normal < 0.0;
        if (active && node->IsNot(ACTIVE)) lambda = augmented_normal / k;
        flips += UpdateActive(*node, active);
    }
    return flips;
}

std::size_t ComputeALMFrictionlessComponentsActiveSet(ModelPart& model_part) {
    const ProcessInfo& process_info = model_part.GetProcessInfo();
    const double k = ScaleFactor(process_info, "ComputeALMFrictionlessComponentsActiveSet");
    std::size_t flips = 0;
    for (Node* node : SlaveNodesToUpdate(model_part)) {
        Array3& lambda = NodalValue(*node, VECTOR_LAGRANGE_MULTIPLIER);
        const Array3 normal = NodalValue(*node, NORMAL);
        const double augmented_normal =
            k * normal.dot(lambda) + Penalty(*node, process_info) * NodalValue(*node, WEIGHTED_GAP);
        node->SetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE, augmented_normal);
        const bool active = augmented_normal < 0.0;
        if (active && node->IsNot(ACTIVE)) lambda = normal * (augmented_normal / k);
        flips += UpdateActive(*node, active);
    }
    return flips;
}

std::array<std::size_t, 2> ComputePenaltyFrictionalActiveSet(ModelPart& model_part, bool pure_slip) {
    const ProcessInfo& process_info = model_part.GetProcessInfo();
    const double tangent_factor = process_info.GetValue(TANGENT_FACTOR);
    std::array<std::size_t, 2> flips{0, 0};
    for (Node* node : SlaveNodesToUpdate(model_part)) {
        const double penalty = Penalty(*node, process_info);
        const double augmented_normal = penalty * NodalValue(*node, WEIGHTED_GAP);
        node->SetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE, augmented_normal);
        Array3& weighted_slip = NodalValue(*node, WEIGHTED_SLIP);
        const bool active = augmented_normal < 0.0;
        flips[0] += UpdateActive(*node, active);
        if (!active) {  // the deactivation is the counted change; the stick/slip state is just reset
            weighted_slip.setZero();
            node->Set(SLIP, pure_slip);
            continue;
        }
        const double mu = node->GetValue(FRICTION_COEFFICIENT);
        Array3 augmented_tangent = tangent_factor * penalty * weighted_slip;
        const bool slip = pure_slip || augmented_tangent.norm() > -mu * augmented_normal;
        // Slip traction along ũτ, as the stick one (the reference flips its sign: [BUG?] B10).
        if (slip) augmented_tangent = -mu * augmented_normal * Direction(weighted_slip);
        node->SetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE, augmented_tangent);
        const std::size_t changed = UpdateSlip(*node, slip);
        if (!pure_slip) flips[1] += changed;
    }
    return flips;
}

std::array<std::size_t, 2> ComputeALMFrictionalActiveSet(ModelPart& model_part, bool pure_slip) {
    const ProcessInfo& process_info = model_part.GetProcessInfo();
    const double k = ScaleFactor(process_info, "ComputeALMFrictionalActiveSet");
    const double tangent_factor = process_info.GetValue(TANGENT_FACTOR);
    const double slip_augmentation = process_info.GetValue(SLIP_AUGMENTATION_COEFFICIENT);
    const double slip_threshold = process_info.GetValue(SLIP_THRESHOLD);
    std::array<std::size_t, 2> flips{0, 0};
    for (Node* node : SlaveNodesToUpdate(model_part)) {
        const double penalty = Penalty(*node, process_info);
        Array3& lambda = NodalValue(*node, VECTOR_LAGRANGE_MULTIPLIER);
        Array3& weighted_slip = NodalValue(*node, WEIGHTED_SLIP);
        const Array3 normal = NodalValue(*node, NORMAL);
        const double lambda_normal = normal.dot(lambda);
        const Array3 lambda_tangent = lambda - lambda_normal * normal;
        const double augmented_normal = k * lambda_normal + penalty * NodalValue(*node, WEIGHTED_GAP);
        node->SetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE, augmented_normal);
        const bool was_slip = node->Is(SLIP);
        const double c = was_slip ? slip_augmentation : 1.0;
        const Array3 augmented_tangent = k * lambda_tangent + c * tangent_factor * penalty * weighted_slip;
        const bool active = augmented_normal < 0.0;
        if (!active) {  // the deactivation is the counted change; the stick/slip state is just reset
            weighted_slip.setZero();
            flips[0] += UpdateActive(*node, false);
            node->Set(SLIP, pure_slip);
            continue;
        }
        const double mu = node->GetValue(FRICTION_COEFFICIENT);
        if (node->IsNot(ACTIVE))
            lambda = normal * (augmented_normal / k) + (mu < kMachineEpsilon ? Array3(Array3::Zero())
                                                                              : Array3(augmented_tangent / k));
        flips[0] += UpdateActive(*node, true);
        // Coulomb test with hysteresis. A frictionless node slips (the test would be 0/0 and flip between states).
        const double threshold = was_slip ? 1.0 - slip_threshold : 1.0;
        const bool slip = pure_slip || mu < kMachineEpsilon ||
                          augmented_tangent.norm() / (-mu * augmented_normal) > threshold;
        if (slip) {
            // Along λτ as the reference; when λτ vanishes (first activation) along λ̄τ instead of NaN.
            const Array3 direction = lambda_tangent.norm() > 0.0 ? Direction(lambda_tangent) : Direction(augmented_tangent);
            node->SetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE, Array3(-mu * augmented_normal * direction));
        } else {
            node->SetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE, augmented_tangent);
        }
        const std::size_t changed = UpdateSlip(*node, slip);
        if (!pure_slip) flips[1] += changed;
    }
    return flips;
}

}  // namespace contact_app::ActiveSetUtilities
