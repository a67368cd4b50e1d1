// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "contact_app/kernel/geometries/geometry.h"
#include "contact_app/kernel/geometries/reference_element.h"

namespace contact_app {

/// A Kratos geometry type on its nodes: the isoparametric map of one reference element (reference_element.h) onto
/// the points. Every fixed-topology type (Point3D, lines, triangles, quadrilaterals, tetrahedra, hexahedra, prisms)
/// is one of these; CreateGeometry() picks the row by name.
class ReferenceGeometry final : public Geometry {
public:
    /// @param[in] points rElement.num_points nodes in Kratos/GiD order (shared ownership)
    /// @param[in] rElement the type's row of ReferenceElements() (static storage)
    /// @throws InputError if the count is wrong or a pointer is null
    ReferenceGeometry(PointsArrayType points, const ReferenceElement& rElement);
    Pointer Create(PointsArrayType points) const override;
    std::string Name() const override { return mElement.name; }
    GeometryFamily Family() const override { return mElement.family; }
    int WorkingSpaceDimension() const override { return mElement.working_dimension; }
    int LocalSpaceDimension() const override { return mElement.local_dimension; }
    int DefaultIntegrationOrder() const override { return mElement.default_integration; }
    void ShapeFunctionsValues(Vector& rN, const Array3& local) const override {
        mElement.shape_functions.values(rN, local);
    }
    void ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const override {
        mElement.shape_functions.gradients(rDN, local);
    }
    Matrix& PointsLocalCoordinates(Matrix& rResult) const override;
    std::vector<std::vector<std::size_t>> LocalFacesConnectivity() const override {
        return mElement.shape_functions.faces();
    }

protected:
    int MeasureIntegrationOrder() const override { return mElement.measure_integration; }

private:
    const ReferenceElement& mElement;
};

}  // namespace contact_app
