// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/geometries/quadrilateral_3d_4.h"

#include "contact_app/kernel/geometries/shape_functions.h"

namespace contact_app {

Quadrilateral3D4::Quadrilateral3D4(PointsArrayType points)
    : Geometry(std::move(points), 4, "Quadrilateral3D4") {}

Geometry::Pointer Quadrilateral3D4::Create(PointsArrayType points) const {
    return std::make_shared<Quadrilateral3D4>(std::move(points));
}

void Quadrilateral3D4::ShapeFunctionsValues(Vector& rN, const Array3& local) const {
    detail::BilinearQuadrilateralValues(rN, local);
}

void Quadrilateral3D4::ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const {
    detail::BilinearQuadrilateralGradients(rDN, local);
}

Matrix& Quadrilateral3D4::PointsLocalCoordinates(Matrix& rResult) const {
    rResult = detail::BilinearQuadrilateralNodes();
    return rResult;
}

std::vector<std::vector<std::size_t>> Quadrilateral3D4::LocalFacesConnectivity() const {
    return detail::BilinearQuadrilateralEdges();
}

}  // namespace contact_app
