// SPDX-License-Identifier: BSD-3-Clause
// The constitutive-law table: registered Kratos name → prototype.
#include <memory>

#include "contact_app/kernel/registry.h"
#include "contact_app/structural/constitutive/elastic_law.h"
#include "contact_app/structural/structural_registration.h"

namespace contact_app {

namespace {

struct LawRow {
    const char* name;
    std::shared_ptr<const ConstitutiveLaw> (*make)();
};

template <class TLaw>
std::shared_ptr<const ConstitutiveLaw> Make() {
    return std::make_shared<const TLaw>();
}

}  // namespace

void RegisterConstitutiveLaws() {
    static bool registered = false;
    if (registered) return;
    registered = true;
    const LawRow table[] = {
        {"LinearElastic3DLaw", Make<LinearElastic3DLaw>},
        {"LinearElasticPlaneStrain2DLaw", Make<LinearElasticPlaneStrain2DLaw>},
        {"LinearElasticPlaneStress2DLaw", Make<LinearElasticPlaneStress2DLaw>},
        {"LinearElasticAxisym2DLaw", Make<LinearElasticAxisym2DLaw>},
        {"HyperElastic3DLaw", Make<HyperElastic3DLaw>},
        {"HyperElasticPlaneStrain2DLaw", Make<HyperElasticPlaneStrain2DLaw>},
        {"KirchhoffSaintVenant3DLaw", Make<KirchhoffSaintVenant3DLaw>},
        {"KirchhoffSaintVenantPlaneStrain2DLaw", Make<KirchhoffSaintVenantPlaneStrain2DLaw>},
        {"KirchhoffSaintVenantPlaneStress2DLaw", Make<KirchhoffSaintVenantPlaneStress2DLaw>},
    };
    auto& registry = Registry<ConstitutiveLaw>::Instance();
    for (const auto& row : table) registry.Add(row.name, row.make());
}

}  // namespace contact_app
