// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/mpc_contact_search_process.h"

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/registry.h"

namespace contact_app {

MPCContactSearchProcess::MPCContactSearchProcess(ModelPart& main_model_part, ContactSearchSettings settings,
                                                 Properties::Pointer pair_properties, bool resume)
    : ContactSearchProcess(main_model_part, std::move(settings), std::move(pair_properties), resume) {}

void MPCContactSearchProcess::OnPairCreated(Condition& pair) {
    const auto& registry = Registry<MasterSlaveConstraint>::Instance();
    CONTACT_CHECK(registry.Has("ContactMasterSlaveConstraint"), ConfigurationError,
                  "MPCContactSearchProcess: the constraint \"ContactMasterSlaveConstraint\" is not registered",
                  "\n  where:    pair condition ", pair.Id(), " of ", GetComputingModelPart().FullName(),
                  "\n  expected: Registry<MasterSlaveConstraint> to hold it (the Python module registers it)",
                  "\n  fix:      call RegisterContactMasterSlaveConstraints() before the search");
    ModelPart& root = MainModelPart().GetRootModelPart();
    auto constraint = registry.Get("ContactMasterSlaveConstraint")
                          .Create(root.MasterSlaveConstraints().MaxId() + 1, {}, {}, Matrix(0, 0), Vector(0));
    constraint->Set(ACTIVE, true);
    constraint->Initialize(root.GetProcessInfo());
    GetComputingModelPart().AddMasterSlaveConstraint(constraint);
    pair.SetValue(CONSTRAINT_POINTER, constraint);
    if (MainModelPart().Is(SLIP)) pair.Set(SLIP, true);
    else if (MainModelPart().Is(RIGID)) pair.Set(RIGID, true);
    pair.Initialize(root.GetProcessInfo());
}

void MPCContactSearchProcess::OnPairsErased(const std::vector<Condition*>& pairs) {
    ModelPart& root = MainModelPart().GetRootModelPart();
    for (const Condition* pair : pairs)
        if (const auto constraint = pair->GetValue(CONSTRAINT_POINTER)) root.RemoveMasterSlaveConstraint(constraint->Id());
}

}  // namespace contact_app
