// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/kernel/geometries/geometry.h"

namespace contact_app {

/// Quadratic 10-node tetrahedron (Kratos Tetrahedra3D10): corners as Tetrahedra3D4, then mid-side nodes
/// 5 (1-2), 6 (2-3), 7 (3-1), 8 (1-4), 9 (2-4), 10 (3-4). Corner N = L(2L−1), mid-side N = 4 L_a L_b.
/// Faces are 6-node triangles (corners, then mid-sides). Volume exact (det J cubic, Gauss order 3).
class Tetrahedra3D10 final : public Geometry {
public:
    /// @param[in] points 10 nodes in Kratos/GiD order (shared ownership)
    /// @throws InputError if the count is not 10 or a pointer is null
    explicit Tetrahedra3D10(PointsArrayType points);
    Pointer Create(PointsArrayType points) const override;
    std::string Name() const override { return "Tetrahedra3D10"; }
    GeometryFamily Family() const override { return GeometryFamily::Tetrahedra; }
    int WorkingSpaceDimension() const override { return 3; }
    int LocalSpaceDimension() const override { return 3; }
    int DefaultIntegrationOrder() const override { return 2; }
    void ShapeFunctionsValues(Vector& rN, const Array3& local) const override;
    void ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const override;
    Matrix& PointsLocalCoordinates(Matrix& rResult) const override;
    std::vector<std::vector<std::size_t>> LocalFacesConnectivity() const override;

protected:
    int MeasureIntegrationOrder() const override { return 3; }
};

}  // namespace contact_app
