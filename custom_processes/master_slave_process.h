// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace contact_app {

class ModelPart;

/// Derives the SLAVE / MASTER flags of the interface conditions from their nodes (Kratos MasterSlaveProcess):
/// a condition is SLAVE (and not MASTER) iff all its nodes are SLAVE, otherwise MASTER (and not SLAVE). The
/// nodes of MASTER conditions that are not SLAVE become MASTER (SLAVE false), so both sides are flagged.
/// Paired (coupling) conditions are skipped: their flags belong to the search.
class MasterSlaveProcess {
public:
    /// @param[in,out] model_part the interface model part (kept by reference; must outlive the process)
    explicit MasterSlaveProcess(ModelPart& model_part) : mrModelPart(model_part) {}
    /// @brief Sets the flags on the conditions and nodes of the model part.
    void Execute();

private:
    ModelPart& mrModelPart;
};

}  // namespace contact_app
