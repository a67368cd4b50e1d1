// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/variables.h"

namespace contact_app {

CONTACT_APP_KERNEL_VARIABLES(CONTACT_APP_DEFINE_VARIABLE)
CONTACT_APP_KERNEL_ARRAY3_VARIABLES(CONTACT_APP_DEFINE_ARRAY3_VARIABLE)

void RegisterKernelVariables() {}

}  // namespace contact_app
