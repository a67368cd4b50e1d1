// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/structural/elements/total_lagrangian_element.h"

#include <memory>

#include <Eigen/Dense>

namespace contact_app {

template <int TDim, int TNumNodes>
Element::Pointer TotalLagrangianElement<TDim, TNumNodes>::Create(IndexType new_id, Geometry::Pointer geometry,
                                                                 Properties::Pointer properties) const {
    return std::make_shared<TotalLagrangianElement>(new_id, std::move(geometry), std::move(properties));
}

template <int TDim, int TNumNodes>
void TotalLagrangianElement<TDim, TNumNodes>::ComputeKinematics(std::size_t point, Kinematics& rKinematics) const {
    const auto& reference = this->GetReferencePoint(point);
    const typename BaseType::NodalMatrix x = this->NodalCoordinates(Geometry::Configuration::Current);
    rKinematics.N = reference.N;
    rKinematics.DN_DX = reference.DN_DX0;
    rKinematics.F = x.transpose() * reference.DN_DX0;  // F_ij = Σ_k x_k,i ∂N_k/∂X_j
    rKinematics.detF = rKinematics.F.determinant();
    FillStrainDisplacementMatrix(rKinematics);
    rKinematics.strain = GreenLagrangeStrain<kSolidStrainSize<TDim>>(rKinematics.F);
    rKinematics.weight = reference.weight * reference.detJ0 * this->ThicknessFactor();
    rKinematics.body_weight = rKinematics.weight;
}

#define CONTACT_APP_TOTAL_LAGRANGIAN_INSTANTIATE(TDim, TNumNodes, Geometry, Suffix) \
    template class TotalLagrangianElement<TDim, TNumNodes>;
CONTACT_APP_SOLID_ELEMENT_SIZES(CONTACT_APP_TOTAL_LAGRANGIAN_INSTANTIATE)

}  // namespace contact_app
