// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/constitutive_law.h"

namespace contact_app {

int ConstitutiveLaw::Check(const Properties&, const Geometry&, const ProcessInfo&) const { return 0; }

}  // namespace contact_app
