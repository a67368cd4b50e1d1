// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/structural/elements/axisym_total_lagrangian_element.h"

#include <cmath>
#include <memory>

#include <Eigen/Dense>

namespace contact_app {

template <int TNumNodes>
Element::Pointer AxisymTotalLagrangianElement<TNumNodes>::Create(IndexType new_id, Geometry::Pointer geometry,
                                                                 Properties::Pointer properties) const {
    return std::make_shared<AxisymTotalLagrangianElement>(new_id, std::move(geometry), std::move(properties));
}

template <int TNumNodes>
void AxisymTotalLagrangianElement<TNumNodes>::ComputeKinematics(std::size_t point, Kinematics& rKinematics) const {
    using NodalMatrix = typename BaseType::NodalMatrix;
    const auto& reference = this->GetReferencePoint(point);
    const NodalMatrix X0 = this->NodalCoordinates(Geometry::Configuration::Initial);
    const NodalMatrix x = this->NodalCoordinates(Geometry::Configuration::Current);
    // docs/theory/structural.md §8 D3: Kratos takes the "initial" radius from the previous step and the weight from the
    // current
    // radius; the total-Lagrangian form uses the initial radius R for F_θθ = r/R, the hoop row and 2πR dA0.
    const double radius0 = reference.N.dot(X0.col(0));
    const double radius = reference.N.dot(x.col(0));
    rKinematics.N = reference.N;
    rKinematics.DN_DX = reference.DN_DX0;
    rKinematics.hoop = reference.N / radius0;
    rKinematics.F.setZero();
    rKinematics.F.template topLeftCorner<2, 2>() = x.transpose() * reference.DN_DX0;
    rKinematics.F(2, 2) = radius / radius0;
    rKinematics.detF = rKinematics.F.determinant();
    FillStrainDisplacementMatrix(rKinematics);
    rKinematics.strain = GreenLagrangeStrain<4>(rKinematics.F);
    rKinematics.weight = 2.0 * M_PI * radius0 * reference.weight * reference.detJ0;
    rKinematics.body_weight = rKinematics.weight;
}

#define CONTACT_APP_AXISYM_TOTAL_LAGRANGIAN_INSTANTIATE(TDim, TNumNodes, Geometry, Suffix) \
    template class AxisymTotalLagrangianElement<TNumNodes>;
CONTACT_APP_AXISYM_SOLID_ELEMENT_SIZES(CONTACT_APP_AXISYM_TOTAL_LAGRANGIAN_INSTANTIATE)

}  // namespace contact_app
