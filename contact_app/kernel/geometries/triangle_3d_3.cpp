// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/geometries/triangle_3d_3.h"

#include "contact_app/kernel/geometries/shape_functions.h"

namespace contact_app {

Triangle3D3::Triangle3D3(PointsArrayType points) : Geometry(std::move(points), 3, "Triangle3D3") {}

Geometry::Pointer Triangle3D3::Create(PointsArrayType points) const {
    return std::make_shared<Triangle3D3>(std::move(points));
}

void Triangle3D3::ShapeFunctionsValues(Vector& rN, const Array3& local) const {
    detail::LinearTriangleValues(rN, local);
}

void Triangle3D3::ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const {
    detail::LinearTriangleGradients(rDN, local);
}

Matrix& Triangle3D3::PointsLocalCoordinates(Matrix& rResult) const {
    rResult = detail::LinearTriangleNodes();
    return rResult;
}

std::vector<std::vector<std::size_t>> Triangle3D3::LocalFacesConnectivity() const {
    return detail::LinearTriangleEdges();
}

}  // namespace contact_app
