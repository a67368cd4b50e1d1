// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/kernel/geometries/geometry.h"

namespace contact_app {

/// Linear 4-node tetrahedron (Kratos Tetrahedra3D4) on the unit simplex: nodes (0,0,0), (1,0,0),
/// (0,1,0), (0,0,1), N = (1−ξ−η−ζ, ξ, η, ζ). Positive volume when node 4 is on the side of
/// (x_2 − x_1) × (x_3 − x_1).
class Tetrahedra3D4 final : public Geometry {
public:
    /// @param[in] points 4 nodes in Kratos/GiD order (shared ownership)
    /// @throws InputError if the count is not 4 or a pointer is null
    explicit Tetrahedra3D4(PointsArrayType points);
    Pointer Create(PointsArrayType points) const override;
    std::string Name() const override { return "Tetrahedra3D4"; }
    GeometryFamily Family() const override { return GeometryFamily::Tetrahedra; }
    int WorkingSpaceDimension() const override { return 3; }
    int LocalSpaceDimension() const override { return 3; }
    int DefaultIntegrationOrder() const override { return 1; }
    void ShapeFunctionsValues(Vector& rN, const Array3& local) const override;
    void ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const override;
    Matrix& PointsLocalCoordinates(Matrix& rResult) const override;
    std::vector<std::vector<std::size_t>> LocalFacesConnectivity() const override;
};

}  // namespace contact_app
