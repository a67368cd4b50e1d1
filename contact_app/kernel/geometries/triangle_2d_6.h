// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/kernel/geometries/geometry.h"

namespace contact_app {

/// Quadratic 6-node triangle in the xy-plane (Kratos Triangle2D6): corners (0,0), (1,0), (0,1), then
/// mid-side nodes 4 (1-2), 5 (2-3), 6 (3-1). Corner N = L(2L−1), mid-side N = 4 L_a L_b (L barycentric).
/// Curved edges are allowed; the area is exact (det J is quadratic, Gauss order 2).
class Triangle2D6 final : public Geometry {
public:
    /// @param[in] points 6 nodes in Kratos/GiD order (shared ownership)
    /// @throws InputError if the count is not 6 or a pointer is null
    explicit Triangle2D6(PointsArrayType points);
    Pointer Create(PointsArrayType points) const override;
    std::string Name() const override { return "Triangle2D6"; }
    GeometryFamily Family() const override { return GeometryFamily::Triangle; }
    int WorkingSpaceDimension() const override { return 2; }
    int LocalSpaceDimension() const override { return 2; }
    int DefaultIntegrationOrder() const override { return 2; }
    void ShapeFunctionsValues(Vector& rN, const Array3& local) const override;
    void ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const override;
    Matrix& PointsLocalCoordinates(Matrix& rResult) const override;
    std::vector<std::vector<std::size_t>> LocalFacesConnectivity() const override;
};

}  // namespace contact_app
