// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/geometries/geometry_factory.h"

#include <memory>
#include <utility>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/geometries/hexahedra_3d_8.h"
#include "contact_app/kernel/geometries/line_2d_2.h"
#include "contact_app/kernel/geometries/line_2d_3.h"
#include "contact_app/kernel/geometries/line_3d_2.h"
#include "contact_app/kernel/geometries/point_3d.h"
#include "contact_app/kernel/geometries/prism_3d_6.h"
#include "contact_app/kernel/geometries/quadrilateral_2d_4.h"
#include "contact_app/kernel/geometries/quadrilateral_3d_4.h"
#include "contact_app/kernel/geometries/tetrahedra_3d_10.h"
#include "contact_app/kernel/geometries/tetrahedra_3d_4.h"
#include "contact_app/kernel/geometries/triangle_2d_3.h"
#include "contact_app/kernel/geometries/triangle_2d_6.h"
#include "contact_app/kernel/geometries/triangle_3d_3.h"
#include "contact_app/kernel/string_utilities.h"

namespace contact_app {
namespace {

using Creator = Geometry::Pointer (*)(Geometry::PointsArrayType);

template <class TGeometry>
Geometry::Pointer Make(Geometry::PointsArrayType points) {
    return std::make_shared<TGeometry>(std::move(points));
}

// The one registration table.
const std::vector<std::pair<std::string, Creator>>& Table() {
    static const std::vector<std::pair<std::string, Creator>> table{
        {"Point3D", &Make<Point3D>},
        {"Line2D2", &Make<Line2D2>},
        {"Line3D2", &Make<Line3D2>},
        {"Line2D3", &Make<Line2D3>},
        {"Triangle2D3", &Make<Triangle2D3>},
        {"Triangle3D3", &Make<Triangle3D3>},
        {"Triangle2D6", &Make<Triangle2D6>},
        {"Quadrilateral2D4", &Make<Quadrilateral2D4>},
        {"Quadrilateral3D4", &Make<Quadrilateral3D4>},
        {"Tetrahedra3D4", &Make<Tetrahedra3D4>},
        {"Tetrahedra3D10", &Make<Tetrahedra3D10>},
        {"Hexahedra3D8", &Make<Hexahedra3D8>},
        {"Prism3D6", &Make<Prism3D6>},
    };
    return table;
}

}  // namespace

Geometry::Pointer CreateGeometry(const std::string& name, Geometry::PointsArrayType points) {
    for (const auto& [registered, creator] : Table())
        if (registered == name) return creator(std::move(points));
    const std::vector<std::string> names = RegisteredGeometryNames();
    CONTACT_THROW(InputError, "unknown geometry type \"", name, "\"\n  expected: one of ", QuotedList(names),
                  "\n  fix: ", DidYouMean(name, names, "use one of the names above (Kratos spelling)"));
}

std::vector<std::string> RegisteredGeometryNames() {
    std::vector<std::string> names;
    for (const auto& entry : Table()) names.push_back(entry.first);
    return names;
}

}  // namespace contact_app
