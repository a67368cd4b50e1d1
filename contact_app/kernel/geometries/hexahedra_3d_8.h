// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/kernel/geometries/geometry.h"

namespace contact_app {

/// Trilinear 8-node hexahedron (Kratos Hexahedra3D8) on [-1,1]³: bottom face 1-2-3-4 counter-clockwise
/// at ζ = −1 (seen from +z), top face 5-8 above it; N_k = (1+ξ_k ξ)(1+η_k η)(1+ζ_k ζ)/8.
/// Volume exact with Gauss order 2 (det J has degree ≤ 2 per direction).
class Hexahedra3D8 final : public Geometry {
public:
    /// @param[in] points 8 nodes in Kratos/GiD order (shared ownership)
    /// @throws InputError if the count is not 8 or a pointer is null
    explicit Hexahedra3D8(PointsArrayType points);
    Pointer Create(PointsArrayType points) const override;
    std::string Name() const override { return "Hexahedra3D8"; }
    GeometryFamily Family() const override { return GeometryFamily::Hexahedra; }
    int WorkingSpaceDimension() const override { return 3; }
    int LocalSpaceDimension() const override { return 3; }
    int DefaultIntegrationOrder() const override { return 2; }
    void ShapeFunctionsValues(Vector& rN, const Array3& local) const override;
    void ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const override;
    Matrix& PointsLocalCoordinates(Matrix& rResult) const override;
    std::vector<std::vector<std::size_t>> LocalFacesConnectivity() const override;
};

}  // namespace contact_app
