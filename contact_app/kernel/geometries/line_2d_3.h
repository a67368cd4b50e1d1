// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/kernel/geometries/geometry.h"

namespace contact_app {

/// Quadratic 3-node line in the xy-plane (Kratos Line2D3): nodes at ξ = −1, +1, 0 (end, end, middle),
/// N = (ξ(ξ−1)/2, ξ(ξ+1)/2, 1−ξ²). Length by Gauss order 5 (exact when straight and evenly spaced).
class Line2D3 final : public Geometry {
public:
    /// @param[in] points 3 nodes in Kratos/GiD order (shared ownership)
    /// @throws InputError if the count is not 3 or a pointer is null
    explicit Line2D3(PointsArrayType points);
    Pointer Create(PointsArrayType points) const override;
    std::string Name() const override { return "Line2D3"; }
    GeometryFamily Family() const override { return GeometryFamily::Linear; }
    int WorkingSpaceDimension() const override { return 2; }
    int LocalSpaceDimension() const override { return 1; }
    int DefaultIntegrationOrder() const override { return 2; }
    void ShapeFunctionsValues(Vector& rN, const Array3& local) const override;
    void ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const override;
    Matrix& PointsLocalCoordinates(Matrix& rResult) const override;
    std::vector<std::vector<std::size_t>> LocalFacesConnectivity() const override;

protected:
    int MeasureIntegrationOrder() const override { return 5; }
};

}  // namespace contact_app
