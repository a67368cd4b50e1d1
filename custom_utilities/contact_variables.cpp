// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/contact_variables.h"

namespace contact_app {

CONTACT_APP_CONTACT_VARIABLES(CONTACT_APP_DEFINE_VARIABLE)
CONTACT_APP_CONTACT_ARRAY3_VARIABLES(CONTACT_APP_DEFINE_ARRAY3_VARIABLE)

void RegisterContactVariables() {}

}  // namespace contact_app
