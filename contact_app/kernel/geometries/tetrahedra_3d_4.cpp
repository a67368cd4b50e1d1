// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/geometries/tetrahedra_3d_4.h"

namespace contact_app {

Tetrahedra3D4::Tetrahedra3D4(PointsArrayType points) : Geometry(std::move(points), 4, "Tetrahedra3D4") {}

Geometry::Pointer Tetrahedra3D4::Create(PointsArrayType points) const {
    return std::make_shared<Tetrahedra3D4>(std::move(points));
}

void Tetrahedra3D4::ShapeFunctionsValues(Vector& rN, const Array3& local) const {
    rN.resize(4);
    rN << 1.0 - local[0] - local[1] - local[2], local[0], local[1], local[2];
}

void Tetrahedra3D4::ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& /*local*/) const {
    rDN.resize(4, 3);
    rDN << -1.0, -1.0, -1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0;
}

Matrix& Tetrahedra3D4::PointsLocalCoordinates(Matrix& rResult) const {
    rResult.resize(4, 3);
    rResult << 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0;
    return rResult;
}

std::vector<std::vector<std::size_t>> Tetrahedra3D4::LocalFacesConnectivity() const {
    return {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
}

}  // namespace contact_app
