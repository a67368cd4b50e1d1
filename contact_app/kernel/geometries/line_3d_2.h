// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/kernel/geometries/geometry.h"

namespace contact_app {

/// Straight 2-node line in 3D (Kratos Line3D2), ξ∈[-1,1], N = ((1−ξ)/2, (1+ξ)/2).
/// Normal() = J × e_z (defined unless the line is parallel to z).
class Line3D2 final : public Geometry {
public:
    /// @param[in] points 2 nodes in Kratos/GiD order (shared ownership)
    /// @throws InputError if the count is not 2 or a pointer is null
    explicit Line3D2(PointsArrayType points);
    Pointer Create(PointsArrayType points) const override;
    std::string Name() const override { return "Line3D2"; }
    GeometryFamily Family() const override { return GeometryFamily::Linear; }
    int WorkingSpaceDimension() const override { return 3; }
    int LocalSpaceDimension() const override { return 1; }
    int DefaultIntegrationOrder() const override { return 1; }
    void ShapeFunctionsValues(Vector& rN, const Array3& local) const override;
    void ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const override;
    Matrix& PointsLocalCoordinates(Matrix& rResult) const override;
    std::vector<std::vector<std::size_t>> LocalFacesConnectivity() const override;
};

}  // namespace contact_app
