// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/geometries/line_2d_3.h"

namespace contact_app {

Line2D3::Line2D3(PointsArrayType points) : Geometry(std::move(points), 3, "Line2D3") {}

Geometry::Pointer Line2D3::Create(PointsArrayType points) const {
    return std::make_shared<Line2D3>(std::move(points));
}

void Line2D3::ShapeFunctionsValues(Vector& rN, const Array3& local) const {
    rN.resize(3);
    const double xi = local[0];
    rN << 0.5 * xi * (xi - 1.0), 0.5 * xi * (xi + 1.0), 1.0 - xi * xi;
}

void Line2D3::ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const {
    rDN.resize(3, 1);
    const double xi = local[0];
    rDN << xi - 0.5, xi + 0.5, -2.0 * xi;
}

Matrix& Line2D3::PointsLocalCoordinates(Matrix& rResult) const {
    rResult.resize(3, 1);
    rResult << -1.0, 1.0, 0.0;
    return rResult;
}

std::vector<std::vector<std::size_t>> Line2D3::LocalFacesConnectivity() const { return {{0}, {1}}; }

}  // namespace contact_app
