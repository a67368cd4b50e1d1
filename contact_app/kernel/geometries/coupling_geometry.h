// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/kernel/geometries/geometry.h"

namespace contact_app {

/// Two geometries paired for contact (Kratos CouplingGeometry): part 0 is the parent/slave geometry,
/// part 1 the paired/master one. The points, shape functions, mapping, measures and normals are those of
/// part 0 (the master only travels with it). Registered name "CouplingGeometry"; not in CreateGeometry()
/// because it is built from two geometries, not from nodes.
/// Ownership: both parts are shared (std::shared_ptr) with the conditions/model parts that hold them.
class CouplingGeometry final : public Geometry {
public:
    /// @param[in] slave part 0 (not null); its nodes become this geometry's points
    /// @param[in] master part 1 (not null)
    /// @throws InputError if either part is null
    CouplingGeometry(Geometry::Pointer slave, Geometry::Pointer master);

    /// @brief A coupling geometry whose part 0 is part 0's type on @p points; part 1 is shared unchanged.
    /// @throws InputError if the node count does not fit part 0
    Pointer Create(PointsArrayType points) const override;
    std::string Name() const override { return "CouplingGeometry"; }
    GeometryFamily Family() const override { return mParts[0]->Family(); }
    int WorkingSpaceDimension() const override { return mParts[0]->WorkingSpaceDimension(); }
    int LocalSpaceDimension() const override { return mParts[0]->LocalSpaceDimension(); }
    int DefaultIntegrationOrder() const override { return mParts[0]->DefaultIntegrationOrder(); }

    double ShapeFunctionValue(std::size_t i, const Array3& local) const override;
    void ShapeFunctionsValues(Vector& rN, const Array3& local) const override;
    void ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const override;
    Matrix& PointsLocalCoordinates(Matrix& rResult) const override;

    double Length() const override { return mParts[0]->Length(); }
    double Area() const override { return mParts[0]->Area(); }
    double Volume() const override { return mParts[0]->Volume(); }
    double DomainSize() const override { return mParts[0]->DomainSize(); }
    Array3 Center() const override { return mParts[0]->Center(); }
    Array3 Normal(const Array3& local) const override { return mParts[0]->Normal(local); }
    Array3 UnitNormal(const Array3& local) const override { return mParts[0]->UnitNormal(local); }
    std::vector<std::vector<std::size_t>> LocalFacesConnectivity() const override;

    std::size_t NumberOfGeometryParts() const override { return mParts.size(); }
    /// @brief Part @p index: 0 slave/parent, 1 master/paired. @throws InputError if @p index > 1
    Pointer pGetGeometryPart(std::size_t index) const override;
    /// @brief Replaces part @p index (0 also replaces this geometry's points).
    /// @throws InputError if @p index > 1 or @p part is null
    void SetGeometryPart(std::size_t index, Geometry::Pointer part);

private:
    std::vector<Geometry::Pointer> mParts;  // always two, never null
};

}  // namespace contact_app
