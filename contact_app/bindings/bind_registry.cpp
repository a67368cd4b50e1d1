// SPDX-License-Identifier: BSD-3-Clause
#include <algorithm>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "contact_app/bindings/bindings.h"
#include "contact_app/kernel/condition.h"
#include "contact_app/kernel/constitutive_law.h"
#include "contact_app/kernel/element.h"
#include "contact_app/kernel/geometries/geometry_factory.h"
#include "contact_app/kernel/master_slave_constraint.h"
#include "contact_app/kernel/registry.h"

namespace contact_app::bindings {

void BindRegistry(py::module_& m) {
    m.def(
        "registered_elements", [] { return Registry<Element>::Instance().Names(); }, "Sorted element names.");
    m.def(
        "registered_conditions", [] { return Registry<Condition>::Instance().Names(); }, "Sorted condition names.");
    m.def(
        "registered_constraints", [] { return Registry<MasterSlaveConstraint>::Instance().Names(); },
        "Sorted master-slave constraint names.");
    m.def(
        "registered_constitutive_laws", [] { return Registry<ConstitutiveLaw>::Instance().Names(); },
        "Sorted constitutive law names.");
    m.def(
        "registered_geometries",
        [] {
            std::vector<std::string> names = RegisteredGeometryNames();
            std::sort(names.begin(), names.end());
            return names;
        },
        "Sorted geometry type names (\"Triangle2D3\", ...).");
}

}  // namespace contact_app::bindings
