// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/geometries/reference_geometry.h"

#include <memory>
#include <utility>

namespace contact_app {

ReferenceGeometry::ReferenceGeometry(PointsArrayType points, const ReferenceElement& rElement)
    : Geometry(std::move(points), rElement.num_points, rElement.name), mElement(rElement) {}

Geometry::Pointer ReferenceGeometry::Create(PointsArrayType points) const {
    return std::make_shared<ReferenceGeometry>(std::move(points), mElement);
}

Matrix& ReferenceGeometry::PointsLocalCoordinates(Matrix& rResult) const {
    rResult = mElement.shape_functions.nodes();
    return rResult;
}

}  // namespace contact_app
