// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/geometries/prism_3d_6.h"

namespace contact_app {

Prism3D6::Prism3D6(PointsArrayType points) : Geometry(std::move(points), 6, "Prism3D6") {}

Geometry::Pointer Prism3D6::Create(PointsArrayType points) const {
    return std::make_shared<Prism3D6>(std::move(points));
}

void Prism3D6::ShapeFunctionsValues(Vector& rN, const Array3& local) const {
    const Array3 L(1.0 - local[0] - local[1], local[0], local[1]);
    rN.resize(6);
    rN << (1.0 - local[2]) * L, local[2] * L;
}

void Prism3D6::ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const {
    constexpr double kTriangleGradients[3][2] = {{-1.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}};  // ∂L_i/∂(ξ,η)
    const Array3 L(1.0 - local[0] - local[1], local[0], local[1]);
    const double bottom = 1.0 - local[2], top = local[2];
    rDN.resize(6, 3);
    for (int i = 0; i < 3; ++i) {
        rDN.row(i) << bottom * kTriangleGradients[i][0], bottom * kTriangleGradients[i][1], -L[i];
        rDN.row(i + 3) << top * kTriangleGradients[i][0], top * kTriangleGradients[i][1], L[i];
    }
}

Matrix& Prism3D6::PointsLocalCoordinates(Matrix& rResult) const {
    rResult.resize(6, 3);
    rResult << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1;
    return rResult;
}

std::vector<std::vector<std::size_t>> Prism3D6::LocalFacesConnectivity() const {
    return {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
}

}  // namespace contact_app
