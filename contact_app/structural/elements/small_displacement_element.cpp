// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/structural/elements/small_displacement_element.h"

#include <memory>

#include <Eigen/Dense>

namespace contact_app {

template <int TDim, int TNumNodes>
Element::Pointer SmallDisplacementElement<TDim, TNumNodes>::Create(IndexType new_id, Geometry::Pointer geometry,
                                                                   Properties::Pointer properties) const {
    return std::make_shared<SmallDisplacementElement>(new_id, std::move(geometry), std::move(properties));
}

template <int TDim, int TNumNodes>
void SmallDisplacementElement<TDim, TNumNodes>::ComputeKinematics(std::size_t point, Kinematics& rKinematics) const {
    const auto& reference = this->GetReferencePoint(point);
    rKinematics.N = reference.N;
    rKinematics.DN_DX = reference.DN_DX0;
    rKinematics.F.setIdentity();
    FillStrainDisplacementMatrix(rKinematics);
    const typename BaseType::NodalMatrix u = this->NodalDisplacements(0);
    rKinematics.strain.setZero();
    for (int i = 0; i < TNumNodes; ++i)
        rKinematics.strain.noalias() += rKinematics.B.template middleCols<TDim>(i * TDim) * u.row(i).transpose();
    rKinematics.F = EquivalentDeformationGradient<Kinematics::kFSize>(rKinematics.strain);
    rKinematics.detF = rKinematics.F.determinant();
    rKinematics.weight = reference.weight * reference.detJ0 * this->ThicknessFactor();
    rKinematics.body_weight = rKinematics.weight;
}

#define CONTACT_APP_SMALL_DISPLACEMENT_INSTANTIATE(TDim, TNumNodes, Geometry, Suffix) \
    template class SmallDisplacementElement<TDim, TNumNodes>;
CONTACT_APP_SOLID_ELEMENT_SIZES(CONTACT_APP_SMALL_DISPLACEMENT_INSTANTIATE)

}  // namespace contact_app
