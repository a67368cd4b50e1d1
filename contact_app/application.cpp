// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/application.h"

#include "contact_app/kernel/registry.h"
#include "contact_app/structural/structural_registration.h"

namespace contact_app {

CONTACT_APP_CONTACT_VARIABLES(CONTACT_APP_DEFINE_VARIABLE)
CONTACT_APP_CONTACT_ARRAY3_VARIABLES(CONTACT_APP_DEFINE_ARRAY3_VARIABLE)

void RegisterContactApplication() {
    RegisterKernelVariables();
    RegisterKernelEntities();
    RegisterStructuralMechanics();
}

}  // namespace contact_app
