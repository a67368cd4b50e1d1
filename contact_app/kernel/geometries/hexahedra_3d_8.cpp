// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/geometries/hexahedra_3d_8.h"

namespace contact_app {
namespace {

// Local coordinates of the nodes: bottom face counter-clockwise at ζ = −1, then the top face.
constexpr double kNodes[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                 {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

}  // namespace

Hexahedra3D8::Hexahedra3D8(PointsArrayType points) : Geometry(std::move(points), 8, "Hexahedra3D8") {}

Geometry::Pointer Hexahedra3D8::Create(PointsArrayType points) const {
    return std::make_shared<Hexahedra3D8>(std::move(points));
}

void Hexahedra3D8::ShapeFunctionsValues(Vector& rN, const Array3& local) const {
    rN.resize(8);
    for (int k = 0; k < 8; ++k)
        rN[k] = 0.125 * (1.0 + kNodes[k][0] * local[0]) * (1.0 + kNodes[k][1] * local[1]) *
                (1.0 + kNodes[k][2] * local[2]);
}

void Hexahedra3D8::ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const {
    rDN.resize(8, 3);
    for (int k = 0; k < 8; ++k) {
        const Array3 f(1.0 + kNodes[k][0] * local[0], 1.0 + kNodes[k][1] * local[1],
                       1.0 + kNodes[k][2] * local[2]);
        rDN(k, 0) = 0.125 * kNodes[k][0] * f[1] * f[2];
        rDN(k, 1) = 0.125 * kNodes[k][1] * f[0] * f[2];
        rDN(k, 2) = 0.125 * kNodes[k][2] * f[0] * f[1];
    }
}

Matrix& Hexahedra3D8::PointsLocalCoordinates(Matrix& rResult) const {
    rResult.resize(8, 3);
    for (int k = 0; k < 8; ++k) rResult.row(k) << kNodes[k][0], kNodes[k][1], kNodes[k][2];
    return rResult;
}

std::vector<std::vector<std::size_t>> Hexahedra3D8::LocalFacesConnectivity() const {
    return {{0, 3, 2, 1}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}, {4, 5, 6, 7}};
}

}  // namespace contact_app
