// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/geometries/triangle_2d_6.h"

#include "contact_app/kernel/geometries/shape_functions.h"

namespace contact_app {
namespace {

const detail::Connectivity kEdges{{0, 1}, {1, 2}, {2, 0}};  // corners of mid-side nodes 3, 4, 5

Vector Barycentric(const Array3& local) {
    return Eigen::Vector3d(1.0 - local[0] - local[1], local[0], local[1]);
}

Matrix BarycentricGradients() {
    Matrix result(3, 2);
    result << -1.0, -1.0, 1.0, 0.0, 0.0, 1.0;
    return result;
}

}  // namespace

Triangle2D6::Triangle2D6(PointsArrayType points) : Geometry(std::move(points), 6, "Triangle2D6") {}

Geometry::Pointer Triangle2D6::Create(PointsArrayType points) const {
    return std::make_shared<Triangle2D6>(std::move(points));
}

void Triangle2D6::ShapeFunctionsValues(Vector& rN, const Array3& local) const {
    detail::QuadraticSimplexValues(rN, Barycentric(local), kEdges);
}

void Triangle2D6::ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const {
    detail::QuadraticSimplexGradients(rDN, Barycentric(local), BarycentricGradients(), kEdges);
}

Matrix& Triangle2D6::PointsLocalCoordinates(Matrix& rResult) const {
    rResult.resize(6, 2);
    rResult << 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.5, 0.0, 0.5, 0.5, 0.0, 0.5;
    return rResult;
}

std::vector<std::vector<std::size_t>> Triangle2D6::LocalFacesConnectivity() const {
    return {{1, 2, 4}, {2, 0, 5}, {0, 1, 3}};
}

}  // namespace contact_app
