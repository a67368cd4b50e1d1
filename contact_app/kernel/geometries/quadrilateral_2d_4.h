// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/kernel/geometries/geometry.h"

namespace contact_app {

/// Bilinear 4-node quadrilateral in the xy-plane (Kratos Quadrilateral2D4) on [-1,1]²: nodes
/// counter-clockwise from (−1,−1), N_k = (1+ξ_k ξ)(1+η_k η)/4.
class Quadrilateral2D4 final : public Geometry {
public:
    /// @param[in] points 4 nodes in Kratos/GiD order (shared ownership)
    /// @throws InputError if the count is not 4 or a pointer is null
    explicit Quadrilateral2D4(PointsArrayType points);
    Pointer Create(PointsArrayType points) const override;
    std::string Name() const override { return "Quadrilateral2D4"; }
    GeometryFamily Family() const override { return GeometryFamily::Quadrilateral; }
    int WorkingSpaceDimension() const override { return 2; }
    int LocalSpaceDimension() const override { return 2; }
    int DefaultIntegrationOrder() const override { return 2; }
    void ShapeFunctionsValues(Vector& rN, const Array3& local) const override;
    void ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const override;
    Matrix& PointsLocalCoordinates(Matrix& rResult) const override;
    std::vector<std::vector<std::size_t>> LocalFacesConnectivity() const override;
};

}  // namespace contact_app
