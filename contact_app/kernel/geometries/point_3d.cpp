// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/geometries/point_3d.h"

namespace contact_app {

Point3D::Point3D(PointsArrayType points) : Geometry(std::move(points), 1, "Point3D") {}

Geometry::Pointer Point3D::Create(PointsArrayType points) const {
    return std::make_shared<Point3D>(std::move(points));
}

void Point3D::ShapeFunctionsValues(Vector& rN, const Array3& /*local*/) const { rN.setOnes(1); }

void Point3D::ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& /*local*/) const { rDN.resize(1, 0); }

Matrix& Point3D::PointsLocalCoordinates(Matrix& rResult) const {
    rResult.resize(1, 0);
    return rResult;
}

std::vector<std::vector<std::size_t>> Point3D::LocalFacesConnectivity() const { return {}; }

}  // namespace contact_app
