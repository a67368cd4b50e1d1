// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/geometries/triangle_2d_3.h"

#include "contact_app/kernel/geometries/shape_functions.h"

namespace contact_app {

Triangle2D3::Triangle2D3(PointsArrayType points) : Geometry(std::move(points), 3, "Triangle2D3") {}

Geometry::Pointer Triangle2D3::Create(PointsArrayType points) const {
    return std::make_shared<Triangle2D3>(std::move(points));
}

void Triangle2D3::ShapeFunctionsValues(Vector& rN, const Array3& local) const {
    detail::LinearTriangleValues(rN, local);
}

void Triangle2D3::ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const {
    detail::LinearTriangleGradients(rDN, local);
}

Matrix& Triangle2D3::PointsLocalCoordinates(Matrix& rResult) const {
    rResult = detail::LinearTriangleNodes();
    return rResult;
}

std::vector<std::vector<std::size_t>> Triangle2D3::LocalFacesConnectivity() const {
    return detail::LinearTriangleEdges();
}

}  // namespace contact_app
