// SPDX-License-Identifier: BSD-3-Clause
// The registered solid elements: one table, generated from the size rows of solid_element_sizes.h.
#include <memory>
#include <string>

#include "contact_app/kernel/geometries/geometry_factory.h"
#include "contact_app/kernel/node.h"
#include "contact_app/kernel/registry.h"
#include "contact_app/structural/elements/solid_element.h"
#include "contact_app/structural/elements/updated_lagrangian_element.h"
#include "contact_app/structural/structural_registration.h"

namespace contact_app {

namespace {

struct SolidElementRow {
    const char* name;
    const char* geometry;
    std::size_t nodes;
    Element::Pointer (*make)(Geometry::Pointer);
};

template <class TElement>
Element::Pointer MakePrototype(Geometry::Pointer geometry) {
    return std::make_shared<TElement>(0, std::move(geometry));
}

// clang-format off
#define CONTACT_APP_SOLID_ROWS(TDim, TNumNodes, Geometry, Suffix)                                         \
    {"SmallDisplacementElement" #Suffix, #Geometry, TNumNodes,                                            \
     &MakePrototype<SmallDisplacementElement<TDim, TNumNodes>>},                                          \
    {"TotalLagrangianElement" #Suffix, #Geometry, TNumNodes,                                              \
     &MakePrototype<TotalLagrangianElement<TDim, TNumNodes>>},                                            \
    {"UpdatedLagrangianElement" #Suffix, #Geometry, TNumNodes,                                            \
     &MakePrototype<UpdatedLagrangianElement<TDim, TNumNodes>>},

// The Kratos spelling (Axisym… first) and the alias spelled as in the issue (…AxisymElement).
#define CONTACT_APP_AXISYM_ROWS(TDim, TNumNodes, Geometry, Suffix)                                        \
    {"AxisymSmallDisplacementElement" #Suffix, #Geometry, TNumNodes,                                      \
     &MakePrototype<AxisymSmallDisplacementElement<TNumNodes>>},                                          \
    {"SmallDisplacementAxisymElement" #Suffix, #Geometry, TNumNodes,                                      \
     &MakePrototype<AxisymSmallDisplacementElement<TNumNodes>>},                                          \
    {"AxisymTotalLagrangianElement" #Suffix, #Geometry, TNumNodes,                                        \
     &MakePrototype<AxisymTotalLagrangianElement<TNumNodes>>},                                            \
    {"TotalLagrangianAxisymElement" #Suffix, #Geometry, TNumNodes,                                        \
     &MakePrototype<AxisymTotalLagrangianElement<TNumNodes>>},

const SolidElementRow kSolidElements[] = {
    CONTACT_APP_SOLID_ELEMENT_SIZES(CONTACT_APP_SOLID_ROWS)
    CONTACT_APP_AXISYM_SOLID_ELEMENT_SIZES(CONTACT_APP_AXISYM_ROWS)
};
// clang-format on

#undef CONTACT_APP_SOLID_ROWS
#undef CONTACT_APP_AXISYM_ROWS

/// Prototype geometry: placeholder nodes at the origin (Create() replaces them).
Geometry::Pointer PrototypeGeometry(const std::string& geometry_name, std::size_t number_of_nodes) {
    Geometry::PointsArrayType points;
    for (std::size_t i = 0; i < number_of_nodes; ++i) points.push_back(std::make_shared<Node>(i + 1, 0.0, 0.0, 0.0));
    return CreateGeometry(geometry_name, points);
}

}  // namespace

void RegisterSolidElements() {
    static bool registered = false;
    if (registered) return;
    registered = true;
    auto& registry = Registry<Element>::Instance();
    for (const SolidElementRow& row : kSolidElements)
        registry.Add(row.name, row.make(PrototypeGeometry(row.geometry, row.nodes)));
}

}  // namespace contact_app
