// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/kernel/geometries/geometry.h"

namespace contact_app {

/// Single-node geometry (Kratos Point3D) for point loads and nodal conditions: N = 1, no local
/// coordinates. DomainSize() is 0; its one-point rule (weight 1, |J| = 1) evaluates an integrand at the node.
class Point3D final : public Geometry {
public:
    /// @param[in] points 1 node in Kratos/GiD order (shared ownership)
    /// @throws InputError if the count is not 1 or a pointer is null
    explicit Point3D(PointsArrayType points);
    Pointer Create(PointsArrayType points) const override;
    std::string Name() const override { return "Point3D"; }
    GeometryFamily Family() const override { return GeometryFamily::Point; }
    int WorkingSpaceDimension() const override { return 3; }
    int LocalSpaceDimension() const override { return 0; }
    int DefaultIntegrationOrder() const override { return 1; }
    void ShapeFunctionsValues(Vector& rN, const Array3& local) const override;
    void ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const override;
    Matrix& PointsLocalCoordinates(Matrix& rResult) const override;
    std::vector<std::vector<std::size_t>> LocalFacesConnectivity() const override;
};

}  // namespace contact_app
