// SPDX-License-Identifier: BSD-3-Clause
// The top of the package: every registration, below it nothing registers anything else.
#include "contact_app/application.h"

#include "contact_app/kernel/registry.h"
#include "contact_app/structural/structural_registration.h"
#include "custom_conditions/contact_condition_registration.h"
#include "custom_strategies/contact_master_slave_constraint.h"
#include "custom_utilities/contact_restart_codecs.h"
#include "custom_utilities/contact_variables.h"

namespace contact_app {

void RegisterContactApplication() {
    RegisterKernelVariables();
    RegisterKernelEntities();
    RegisterStructuralMechanics();
    RegisterContactVariables();
    RegisterContactConditions();
    RegisterContactMasterSlaveConstraints();
    RegisterContactRestartCodecs();
}

}  // namespace contact_app
