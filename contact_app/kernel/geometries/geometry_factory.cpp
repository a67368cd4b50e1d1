// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/geometries/geometry_factory.h"

#include <memory>
#include <utility>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/geometries/reference_geometry.h"
#include "contact_app/kernel/string_utilities.h"

namespace contact_app {

Geometry::Pointer CreateGeometry(const std::string& name, Geometry::PointsArrayType points) {
    if (const ReferenceElement* element = FindReferenceElement(name))
        return std::make_shared<ReferenceGeometry>(std::move(points), *element);
    const std::vector<std::string> names = RegisteredGeometryNames();
    CONTACT_THROW(InputError, "unknown geometry type \"", name, "\"\n  expected: one of ", QuotedList(names),
                  "\n  fix: ", DidYouMean(name, names, "use one of the names above (Kratos spelling)"));
}

std::vector<std::string> RegisteredGeometryNames() {
    std::vector<std::string> names;
    for (const auto& element : ReferenceElements()) names.push_back(element.name);
    return names;
}

}  // namespace contact_app
