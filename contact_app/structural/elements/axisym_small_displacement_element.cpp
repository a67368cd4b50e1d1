// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/structural/elements/axisym_small_displacement_element.h"

#include <cmath>
#include <memory>

#include <Eigen/Dense>

namespace contact_app {

template <int TNumNodes>
Element::Pointer AxisymSmallDisplacementElement<TNumNodes>::Create(IndexType new_id, Geometry::Pointer geometry,
                                                                   Properties::Pointer properties) const {
    return std::make_shared<AxisymSmallDisplacementElement>(new_id, std::move(geometry), std::move(properties));
}

template <int TNumNodes>
void AxisymSmallDisplacementElement<TNumNodes>::ComputeKinematics(std::size_t point, Kinematics& rKinematics) const {
    const auto& reference = this->GetReferencePoint(point);
    const typename BaseType::NodalMatrix X0 = this->NodalCoordinates(Geometry::Configuration::Initial);
    // Small-displacement theory: the radius of the initial configuration in B and in the weight (Kratos uses the
    // current radius, which makes the residual nonlinear in u without a matching tangent).
    const double radius = reference.N.dot(X0.col(0));
    rKinematics.N = reference.N;
    rKinematics.DN_DX = reference.DN_DX0;
    rKinematics.hoop = reference.N / radius;
    rKinematics.F.setIdentity();
    FillStrainDisplacementMatrix(rKinematics);
    const typename BaseType::NodalMatrix u = this->NodalDisplacements(0);
    rKinematics.strain.setZero();
    for (int i = 0; i < TNumNodes; ++i)
        rKinematics.strain.noalias() += rKinematics.B.template middleCols<2>(i * 2) * u.row(i).transpose();
    // docs/theory/structural.md §8 D3: Kratos writes a 3×3 pattern into a 2×2 equivalent F; the full 3×3 I + ε is
    // passed here.
    rKinematics.F = EquivalentDeformationGradient<3>(rKinematics.strain);
    rKinematics.detF = rKinematics.F.determinant();
    rKinematics.weight = 2.0 * M_PI * radius * reference.weight * reference.detJ0;
    rKinematics.body_weight = rKinematics.weight;
}

#define CONTACT_APP_AXISYM_SMALL_DISPLACEMENT_INSTANTIATE(TDim, TNumNodes, Geometry, Suffix) \
    template class AxisymSmallDisplacementElement<TNumNodes>;
CONTACT_APP_AXISYM_SOLID_ELEMENT_SIZES(CONTACT_APP_AXISYM_SMALL_DISPLACEMENT_INSTANTIATE)

}  // namespace contact_app
