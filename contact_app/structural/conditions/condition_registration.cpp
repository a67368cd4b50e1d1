// SPDX-License-Identifier: BSD-3-Clause
// The load-condition table: registered Kratos name → geometry → prototype.
#include <memory>
#include <string>

#include "contact_app/kernel/geometries/geometry_factory.h"
#include "contact_app/kernel/registry.h"
#include "contact_app/structural/conditions/axisym_line_load_condition_2d.h"
#include "contact_app/structural/conditions/line_load_condition_2d.h"
#include "contact_app/structural/conditions/point_load_condition.h"
#include "contact_app/structural/conditions/surface_load_condition_3d.h"
#include "contact_app/structural/structural_registration.h"

namespace contact_app {

namespace {

struct LoadConditionRow {
    const char* name;
    const char* geometry;
    std::size_t number_of_nodes;
    std::shared_ptr<const Condition> (*make)(Geometry::Pointer);
};

template <class TCondition>
std::shared_ptr<const Condition> Make(Geometry::Pointer geometry) {
    return std::make_shared<const TCondition>(0, std::move(geometry));
}

/// Prototype geometry: placeholder nodes at the origin (Create() replaces them).
Geometry::Pointer PrototypeGeometry(const std::string& geometry_name, std::size_t number_of_nodes) {
    Geometry::PointsArrayType points;
    for (std::size_t i = 0; i < number_of_nodes; ++i) points.push_back(std::make_shared<Node>(i + 1, 0.0, 0.0, 0.0));
    return CreateGeometry(geometry_name, points);
}

}  // namespace

void RegisterLoadConditions() {
    static bool registered = false;
    if (registered) return;
    registered = true;
    const LoadConditionRow table[] = {
        {"PointLoadCondition2D1N", "Point3D", 1, Make<PointLoadCondition2D1N>},
        {"PointLoadCondition3D1N", "Point3D", 1, Make<PointLoadCondition3D1N>},
        {"LineLoadCondition2D2N", "Line2D2", 2, Make<LineLoadCondition2D>},
        {"AxisymLineLoadCondition2D2N", "Line2D2", 2, Make<AxisymLineLoadCondition2D>},
        {"SurfaceLoadCondition3D3N", "Triangle3D3", 3, Make<SurfaceLoadCondition3D>},
        {"SurfaceLoadCondition3D4N", "Quadrilateral3D4", 4, Make<SurfaceLoadCondition3D>},
    };
    auto& registry = Registry<Condition>::Instance();
    for (const auto& row : table) registry.Add(row.name, row.make(PrototypeGeometry(row.geometry, row.number_of_nodes)));
}

}  // namespace contact_app
