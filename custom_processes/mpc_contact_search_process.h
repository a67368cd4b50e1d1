// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "custom_processes/contact_search_process.h"

namespace contact_app {

/// The contact search of the MPC route (Kratos MPCContactSearchProcess, docs/theory/contact_search.md §6): the
/// same search; each new pair condition also gets an empty "ContactMasterSlaveConstraint" from
/// Registry<MasterSlaveConstraint> (id = max constraint id + 1, ACTIVE, initialised, added to the computing
/// part), stored in the condition's CONSTRAINT_POINTER; the condition is flagged SLIP when the main part is
/// SLIP (frictional), else RIGID when the main part is RIGID, and initialised again. Erasing a pair erases its
/// constraint (the reference's removal loop indexed its id vector by the id value [BUG?]; here each erased
/// pair removes exactly the constraint it holds).
class MPCContactSearchProcess : public ContactSearchProcess {
public:
    /// @throws InputError as ContactSearchProcess (@p resume: as there)
    MPCContactSearchProcess(ModelPart& main_model_part, ContactSearchSettings settings,
                            Properties::Pointer pair_properties = nullptr, bool resume = false);

protected:
    /// @throws ConfigurationError if "ContactMasterSlaveConstraint" is not registered
    void OnPairCreated(Condition& pair) override;
    void OnPairsErased(const std::vector<Condition*>& pairs) override;
};

}  // namespace contact_app
