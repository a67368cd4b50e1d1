// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/structural/structural_registration.h"

namespace contact_app {

void RegisterStructuralMechanics() {
    static bool registered = false;
    if (registered) return;
    registered = true;
    RegisterConstitutiveLaws();
    RegisterSolidElements();
    RegisterLoadConditions();
}

}  // namespace contact_app
