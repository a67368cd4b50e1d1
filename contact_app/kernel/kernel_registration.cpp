// SPDX-License-Identifier: BSD-3-Clause
#include <cctype>
#include <memory>
#include <string>
#include <vector>

#include "contact_app/kernel/condition.h"
#include "contact_app/kernel/element.h"
#include "contact_app/kernel/geometries/geometry_factory.h"
#include "contact_app/kernel/linear_master_slave_constraint.h"
#include "contact_app/kernel/node.h"
#include "contact_app/kernel/registry.h"

namespace contact_app {

namespace {

/// Registered name -> geometry of the geometry-only ("mesh") entities of the Kratos core.
struct MeshEntityRow {
    const char* name;
    const char* geometry;
};

constexpr MeshEntityRow kMeshElements[] = {
    {"Element2D2N", "Line2D2"},          {"Element2D3N", "Triangle2D3"},     {"Element2D4N", "Quadrilateral2D4"},
    {"Element2D6N", "Triangle2D6"},      {"Element3D2N", "Line3D2"},         {"Element3D3N", "Triangle3D3"},
    {"Element3D4N", "Tetrahedra3D4"},    {"Element3D6N", "Prism3D6"},        {"Element3D8N", "Hexahedra3D8"},
    {"Element3D10N", "Tetrahedra3D10"},
};

constexpr MeshEntityRow kMeshConditions[] = {
    {"PointCondition2D1N", "Point3D"},        {"PointCondition3D1N", "Point3D"},
    {"LineCondition2D2N", "Line2D2"},         {"LineCondition2D3N", "Line2D3"},
    {"LineCondition3D2N", "Line3D2"},         {"SurfaceCondition3D3N", "Triangle3D3"},
    {"SurfaceCondition3D4N", "Quadrilateral3D4"}, {"Condition2D", "Line2D2"},
    {"Condition3D", "Triangle3D3"},
};

/// Prototype geometry: placeholder nodes at the origin (Create() replaces them).
Geometry::Pointer PrototypeGeometry(const std::string& geometry_name, std::size_t number_of_nodes) {
    Geometry::PointsArrayType points;
    for (std::size_t i = 0; i < number_of_nodes; ++i) points.push_back(std::make_shared<Node>(i + 1, 0.0, 0.0, 0.0));
    return CreateGeometry(geometry_name, points);
}

std::size_t NodeCount(const std::string& entity_name) {
    // Names end in "<n>N" (Element2D4N); Condition2D / Condition3D are 2- and 3-node.
    if (entity_name == "Condition2D") return 2;
    if (entity_name == "Condition3D") return 3;
    const std::size_t end = entity_name.size() - 1;
    std::size_t begin = end;
    while (begin > 0 && std::isdigit(static_cast<unsigned char>(entity_name[begin - 1]))) --begin;
    return std::stoul(entity_name.substr(begin, end - begin));
}

}  // namespace

void RegisterKernelEntities() {
    static bool registered = false;
    if (registered) return;
    registered = true;
    auto& elements = Registry<Element>::Instance();
    for (const auto& row : kMeshElements)
        elements.Add(row.name, std::make_shared<Element>(0, PrototypeGeometry(row.geometry, NodeCount(row.name))));
    auto& conditions = Registry<Condition>::Instance();
    for (const auto& row : kMeshConditions)
        conditions.Add(row.name, std::make_shared<Condition>(0, PrototypeGeometry(row.geometry, NodeCount(row.name))));
    Registry<MasterSlaveConstraint>::Instance().Add("LinearMasterSlaveConstraint",
                                                    std::make_shared<LinearMasterSlaveConstraint>());
}

}  // namespace contact_app
