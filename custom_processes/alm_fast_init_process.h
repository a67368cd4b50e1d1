// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace contact_app {

class ModelPart;

/// Start-of-analysis reset of the contact part (Kratos ALMFastInit, docs/theory/contact_strategies.md §5): renumbers
/// the
/// root conditions 1..N (in id order, so every container stays sorted); on every slave node (SLAVE, or SLAVE not
/// defined) WEIGHTED_GAP = 0 (and WEIGHTED_SLIP = 0 when frictional), nodal INITIAL_PENALTY = ProcessInfo value,
/// DYNAMIC_FACTOR = 1, AUGMENTED_NORMAL_CONTACT_PRESSURE = 0 (and AUGMENTED_TANGENT_CONTACT_PRESSURE = 0); condition
/// NORMAL = 0. Frictional (the model part Is(SLIP)): nodal FRICTION_COEFFICIENT = mean over the adjacent non-paired
/// conditions of μ from the pair properties of their ContactSub<key> part (where the contact process puts its
/// "friction_coefficients"), else from their own properties. Unlike the reference, each condition counts once (not
/// once per sub model part holding it), nodes without conditions get 0, not NaN, and a condition without any μ or
/// with a negative or non-finite one is an InputError (the reference warns and uses 0, which silently ignored the
/// process setting when the interface conditions had properties of their own).
class ALMFastInit {
public:
    /// @param[in,out] model_part the contact part (kept by reference; must outlive the process)
    explicit ALMFastInit(ModelPart& model_part) : mrModelPart(model_part) {}
    /// @brief Applies the reset.
    void Execute();

private:
    ModelPart& mrModelPart;
};

}  // namespace contact_app
