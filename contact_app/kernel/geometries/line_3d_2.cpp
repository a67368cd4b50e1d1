// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/geometries/line_3d_2.h"

#include "contact_app/kernel/geometries/shape_functions.h"

namespace contact_app {

Line3D2::Line3D2(PointsArrayType points) : Geometry(std::move(points), 2, "Line3D2") {}

Geometry::Pointer Line3D2::Create(PointsArrayType points) const {
    return std::make_shared<Line3D2>(std::move(points));
}

void Line3D2::ShapeFunctionsValues(Vector& rN, const Array3& local) const {
    detail::LinearLineValues(rN, local);
}

void Line3D2::ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const {
    detail::LinearLineGradients(rDN, local);
}

Matrix& Line3D2::PointsLocalCoordinates(Matrix& rResult) const {
    rResult = detail::LinearLineNodes();
    return rResult;
}

std::vector<std::vector<std::size_t>> Line3D2::LocalFacesConnectivity() const {
    return detail::LinearLineFaces();
}

}  // namespace contact_app
