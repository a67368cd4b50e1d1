// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/constitutive_law.h"

namespace contact_app {

double ConstitutiveLaw::CalculateValue(Parameters&, const Variable<double>&) { return 0.0; }

void ConstitutiveLaw::InitializeMaterial(const Properties&, const Geometry&, const Vector&) {}

void ConstitutiveLaw::InitializeMaterialResponse(Parameters&, StressMeasure) {}

void ConstitutiveLaw::FinalizeMaterialResponse(Parameters&, StressMeasure) {}

int ConstitutiveLaw::Check(const Properties&, const Geometry&, const ProcessInfo&) const { return 0; }

}  // namespace contact_app
