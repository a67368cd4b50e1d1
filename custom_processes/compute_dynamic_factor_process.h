// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace contact_app {

class ModelPart;

/// Share of the step a slave node spends in contact (Kratos ComputeDynamicFactorProcess,
/// docs/theory/contact_strategies.md
/// §5, done right): a node that goes from open to penetrated during the step (g < 0 ≤ g_old, with g, g_old the
/// current and previous-step historical WEIGHTED_GAP) gets DYNAMIC_FACTOR = min(1, |g| / |g − g_old|), the linear
/// estimate of the fraction of the step after impact; every other slave node gets 1. The reference compares
/// g_old with itself ([BUG]) and so always leaves 1. Slave = SLAVE, or SLAVE not defined (as ALMFastInit).
class ComputeDynamicFactorProcess {
public:
    /// @param[in,out] model_part the contact part (kept by reference; must outlive the process)
    explicit ComputeDynamicFactorProcess(ModelPart& model_part) : mrModelPart(model_part) {}
    /// @brief Writes the nodal (non-historical) DYNAMIC_FACTOR.
    /// @throws InputError without historical WEIGHTED_GAP or with a buffer size below 2
    void Execute();

private:
    ModelPart& mrModelPart;
};

}  // namespace contact_app
