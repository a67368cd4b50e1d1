// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/kernel/geometries/geometry.h"

namespace contact_app {

/// Linear 6-node prism (Kratos Prism3D6) = triangle(ξ,η) × ζ∈[0,1]: nodes 1-3 at ζ = 0 ((0,0), (1,0),
/// (0,1)), nodes 4-6 above them at ζ = 1; N = L_i(ξ,η)(1−ζ) and L_i(ξ,η)ζ. Faces: two triangles, three
/// quadrilaterals.
class Prism3D6 final : public Geometry {
public:
    /// @param[in] points 6 nodes in Kratos/GiD order (shared ownership)
    /// @throws InputError if the count is not 6 or a pointer is null
    explicit Prism3D6(PointsArrayType points);
    Pointer Create(PointsArrayType points) const override;
    std::string Name() const override { return "Prism3D6"; }
    GeometryFamily Family() const override { return GeometryFamily::Prism; }
    int WorkingSpaceDimension() const override { return 3; }
    int LocalSpaceDimension() const override { return 3; }
    int DefaultIntegrationOrder() const override { return 2; }
    void ShapeFunctionsValues(Vector& rN, const Array3& local) const override;
    void ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const override;
    Matrix& PointsLocalCoordinates(Matrix& rResult) const override;
    std::vector<std::vector<std::size_t>> LocalFacesConnectivity() const override;
};

}  // namespace contact_app
