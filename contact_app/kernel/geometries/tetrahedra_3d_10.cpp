// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/geometries/tetrahedra_3d_10.h"

#include "contact_app/kernel/geometries/shape_functions.h"

namespace contact_app {
namespace {

// Corners of mid-side nodes 4..9.
const detail::Connectivity kEdges{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};

Vector Barycentric(const Array3& local) {
    return Eigen::Vector4d(1.0 - local[0] - local[1] - local[2], local[0], local[1], local[2]);
}

Matrix BarycentricGradients() {
    Matrix result(4, 3);
    result << -1.0, -1.0, -1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0;
    return result;
}

}  // namespace

Tetrahedra3D10::Tetrahedra3D10(PointsArrayType points) : Geometry(std::move(points), 10, "Tetrahedra3D10") {}

Geometry::Pointer Tetrahedra3D10::Create(PointsArrayType points) const {
    return std::make_shared<Tetrahedra3D10>(std::move(points));
}

void Tetrahedra3D10::ShapeFunctionsValues(Vector& rN, const Array3& local) const {
    detail::QuadraticSimplexValues(rN, Barycentric(local), kEdges);
}

void Tetrahedra3D10::ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const {
    detail::QuadraticSimplexGradients(rDN, Barycentric(local), BarycentricGradients(), kEdges);
}

Matrix& Tetrahedra3D10::PointsLocalCoordinates(Matrix& rResult) const {
    rResult.resize(10, 3);
    rResult.topRows(4) << 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0;
    for (std::size_t e = 0; e < kEdges.size(); ++e)
        rResult.row(4 + static_cast<Eigen::Index>(e)) =
            0.5 * (rResult.row(static_cast<Eigen::Index>(kEdges[e][0])) +
                   rResult.row(static_cast<Eigen::Index>(kEdges[e][1])));
    return rResult;
}

std::vector<std::vector<std::size_t>> Tetrahedra3D10::LocalFacesConnectivity() const {
    return {{1, 2, 3, 5, 9, 8}, {0, 3, 2, 7, 9, 6}, {0, 1, 3, 4, 8, 7}, {0, 2, 1, 6, 5, 4}};
}

}  // namespace contact_app
