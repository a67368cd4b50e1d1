// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace contact_app {

class ModelPart;

/// Start-of-analysis reset of the contact part (Kratos ALMFastInit, kratos_cpp_internals.md §7.2): renumbers the
/// root conditions 1..N (in id order, so every container stays sorted); on every slave node (SLAVE, or SLAVE not
/// defined) WEIGHTED_GAP = 0 (and WEIGHTED_SLIP = 0 when frictional), nodal INITIAL_PENALTY = ProcessInfo value,
/// DYNAMIC_FACTOR = 1, AUGMENTED_NORMAL_CONTACT_PRESSURE = 0 (and AUGMENTED_TANGENT_CONTACT_PRESSURE = 0); condition
/// NORMAL = 0. Frictional (the model part Is(SLIP)): nodal FRICTION_COEFFICIENT = mean over the adjacent non-paired
/// conditions of their properties' value (0 for an absent value, with a warning). Unlike the reference, each
/// condition counts once (not once per sub model part holding it) and nodes without conditions get 0, not NaN.
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
