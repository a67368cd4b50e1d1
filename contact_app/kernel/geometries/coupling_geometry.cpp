// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/geometries/coupling_geometry.h"

#include "contact_app/kernel/exceptions.h"

namespace contact_app {
namespace {

Geometry::Pointer CheckedPart(Geometry::Pointer part, std::size_t index) {
    CONTACT_CHECK(part != nullptr, InputError, "CouplingGeometry: geometry part ", index, " (",
                  (index == 0 ? "slave/parent" : "master/paired"),
                  ") is null\n  fix: pass both the slave and the master geometry");
    return part;
}

}  // namespace

CouplingGeometry::CouplingGeometry(Geometry::Pointer slave, Geometry::Pointer master)
    : Geometry(CheckedPart(slave, 0)->Points(), slave ? slave->PointsNumber() : 0, "CouplingGeometry"),
      mParts{std::move(slave), CheckedPart(std::move(master), 1)} {}

Geometry::Pointer CouplingGeometry::Create(PointsArrayType points) const {
    return std::make_shared<CouplingGeometry>(mParts[0]->Create(std::move(points)), mParts[1]);
}

double CouplingGeometry::ShapeFunctionValue(std::size_t i, const Array3& local) const {
    return mParts[0]->ShapeFunctionValue(i, local);
}

void CouplingGeometry::ShapeFunctionsValues(Vector& rN, const Array3& local) const {
    mParts[0]->ShapeFunctionsValues(rN, local);
}

void CouplingGeometry::ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const {
    mParts[0]->ShapeFunctionsLocalGradients(rDN, local);
}

Matrix& CouplingGeometry::PointsLocalCoordinates(Matrix& rResult) const {
    return mParts[0]->PointsLocalCoordinates(rResult);
}

std::vector<std::vector<std::size_t>> CouplingGeometry::LocalFacesConnectivity() const {
    return mParts[0]->LocalFacesConnectivity();
}

Geometry::Pointer CouplingGeometry::pGetGeometryPart(std::size_t index) const {
    CONTACT_CHECK(index < mParts.size(), InputError, "CouplingGeometry with nodes ", NodeIdsString(),
                  " has no geometry part ", index, "\n  expected: 0 (slave/parent) or 1 (master/paired)",
                  "\n  fix: use index 0 or 1");
    return mParts[index];
}

void CouplingGeometry::SetGeometryPart(std::size_t index, Geometry::Pointer part) {
    pGetGeometryPart(index);  // range check with the explanatory message
    mParts[index] = CheckedPart(std::move(part), index);
    if (index == 0) SetPoints(mParts[0]->Points());
}

}  // namespace contact_app
