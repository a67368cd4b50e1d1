// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/kernel/geometries/geometry.h"

namespace contact_app {

/// 3-node triangle in the xy-plane (Kratos Triangle2D3): nodes (0,0), (1,0), (0,1), N = (1−ξ−η, ξ, η).
class Triangle2D3 final : public Geometry {
public:
    /// @param[in] points 3 nodes in Kratos/GiD order (shared ownership)
    /// @throws InputError if the count is not 3 or a pointer is null
    explicit Triangle2D3(PointsArrayType points);
    Pointer Create(PointsArrayType points) const override;
    std::string Name() const override { return "Triangle2D3"; }
    GeometryFamily Family() const override { return GeometryFamily::Triangle; }
    int WorkingSpaceDimension() const override { return 2; }
    int LocalSpaceDimension() const override { return 2; }
    int DefaultIntegrationOrder() const override { return 1; }
    void ShapeFunctionsValues(Vector& rN, const Array3& local) const override;
    void ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const override;
    Matrix& PointsLocalCoordinates(Matrix& rResult) const override;
    std::vector<std::vector<std::size_t>> LocalFacesConnectivity() const override;
};

}  // namespace contact_app
