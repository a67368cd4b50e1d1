// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/structural/elements/solid_element.h"

#include <cmath>
#include <memory>
#include <utility>

#include <Eigen/Dense>

namespace contact_app {
namespace {

/// ε = B u and the "equivalent F" I + ε (3×3 in axisymmetry) the small-displacement laws read; B from the DN_DX
/// (and hoop row) already set.
template <int TDim, int TNumNodes, int TStrainSize>
void SmallStrain(const BaseSolidElement<TDim, TNumNodes, TStrainSize>& rElement,
                 SolidKinematics<TDim, TNumNodes, TStrainSize>& rKinematics) {
    rKinematics.F.setIdentity();
    FillStrainDisplacementMatrix(rKinematics);
    const auto u = rElement.NodalDisplacements(0);
    rKinematics.strain.setZero();
    for (int i = 0; i < TNumNodes; ++i)
        rKinematics.strain.noalias() += rKinematics.B.template middleCols<TDim>(i * TDim) * u.row(i).transpose();
    constexpr int f_size = SolidKinematics<TDim, TNumNodes, TStrainSize>::kFSize;
    rKinematics.F = EquivalentDeformationGradient<f_size>(rKinematics.strain);
    rKinematics.detF = rKinematics.F.determinant();
}

/// ε = B u on the initial configuration; the law gets ε and the "equivalent F" I + ε.
template <int TDim, int TNumNodes, int TStrainSize>
void SmallDisplacementKinematics(const BaseSolidElement<TDim, TNumNodes, TStrainSize>& rElement, std::size_t point,
                                 SolidKinematics<TDim, TNumNodes, TStrainSize>& rKinematics) {
    const auto& reference = rElement.GetReferencePoint(point);
    rKinematics.N = reference.N;
    rKinematics.DN_DX = reference.DN_DX0;
    SmallStrain(rElement, rKinematics);
    rKinematics.weight = reference.weight * reference.detJ0 * rElement.ThicknessFactor();
    rKinematics.body_weight = rKinematics.weight;
}

/// F = ∂x/∂X from the current coordinates, E = ½(FᵀF − I), on the initial configuration.
template <int TDim, int TNumNodes, int TStrainSize>
void TotalLagrangianKinematics(const BaseSolidElement<TDim, TNumNodes, TStrainSize>& rElement, std::size_t point,
                               SolidKinematics<TDim, TNumNodes, TStrainSize>& rKinematics) {
    using NodalMatrix = typename BaseSolidElement<TDim, TNumNodes, TStrainSize>::NodalMatrix;
    const auto& reference = rElement.GetReferencePoint(point);
    const NodalMatrix x = rElement.NodalCoordinates(Geometry::Configuration::Current);
    rKinematics.N = reference.N;
    rKinematics.DN_DX = reference.DN_DX0;
    rKinematics.F = x.transpose() * reference.DN_DX0;  // F_ij = Σ_k x_k,i ∂N_k/∂X_j
    rKinematics.detF = rKinematics.F.determinant();
    FillStrainDisplacementMatrix(rKinematics);
    rKinematics.strain = GreenLagrangeStrain<kSolidStrainSize<TDim>>(rKinematics.F);
    rKinematics.weight = reference.weight * reference.detJ0 * rElement.ThicknessFactor();
    rKinematics.body_weight = rKinematics.weight;
}

/// Axisymmetric small displacement: the initial radius R in B (hoop row N/R) and in the weight 2πR dA.
template <int TDim, int TNumNodes, int TStrainSize>
void AxisymSmallDisplacementKinematics(const BaseSolidElement<TDim, TNumNodes, TStrainSize>& rElement,
                                       std::size_t point, SolidKinematics<TDim, TNumNodes, TStrainSize>& rKinematics) {
    using NodalMatrix = typename BaseSolidElement<TDim, TNumNodes, TStrainSize>::NodalMatrix;
    const auto& reference = rElement.GetReferencePoint(point);
    const NodalMatrix X0 = rElement.NodalCoordinates(Geometry::Configuration::Initial);
    // Small-displacement theory: the radius of the initial configuration in B and in the weight (Kratos uses the
    // current radius, which makes the residual nonlinear in u without a matching tangent).
    const double radius = reference.N.dot(X0.col(0));
    rKinematics.N = reference.N;
    rKinematics.DN_DX = reference.DN_DX0;
    rKinematics.hoop = reference.N / radius;
    // docs/theory/structural.md §8 D3: Kratos writes a 3×3 pattern into a 2×2 equivalent F; the full 3×3 I + ε is
    // passed here.
    SmallStrain(rElement, rKinematics);
    rKinematics.weight = 2.0 * M_PI * radius * reference.weight * reference.detJ0;
    rKinematics.body_weight = rKinematics.weight;
}

/// Axisymmetric total Lagrangian: F_θθ = r/R, hoop row with the initial radius R, weight 2πR dA0.
template <int TDim, int TNumNodes, int TStrainSize>
void AxisymTotalLagrangianKinematics(const BaseSolidElement<TDim, TNumNodes, TStrainSize>& rElement, std::size_t point,
                                     SolidKinematics<TDim, TNumNodes, TStrainSize>& rKinematics) {
    using NodalMatrix = typename BaseSolidElement<TDim, TNumNodes, TStrainSize>::NodalMatrix;
    const auto& reference = rElement.GetReferencePoint(point);
    const NodalMatrix X0 = rElement.NodalCoordinates(Geometry::Configuration::Initial);
    const NodalMatrix x = rElement.NodalCoordinates(Geometry::Configuration::Current);
    // docs/theory/structural.md §8 D3: Kratos takes the "initial" radius from the previous step and the weight from the
    // current radius; the total-Lagrangian form uses the initial radius R for F_θθ = r/R, the hoop row and 2πR dA0.
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

}  // namespace

template <SolidFormulation TFormulation, int TDim, int TNumNodes, int TStrainSize>
Element::Pointer SolidElement<TFormulation, TDim, TNumNodes, TStrainSize>::Create(
    IndexType new_id, Geometry::Pointer geometry, Properties::Pointer properties) const {
    return std::make_shared<SolidElement>(new_id, std::move(geometry), std::move(properties));
}

template <SolidFormulation TFormulation, int TDim, int TNumNodes, int TStrainSize>
void SolidElement<TFormulation, TDim, TNumNodes, TStrainSize>::ComputeKinematics(std::size_t point,
                                                                                 Kinematics& rKinematics) const {
    if constexpr (TFormulation == SolidFormulation::SMALL_DISPLACEMENT)
        SmallDisplacementKinematics(*this, point, rKinematics);
    else if constexpr (TFormulation == SolidFormulation::TOTAL_LAGRANGIAN)
        TotalLagrangianKinematics(*this, point, rKinematics);
    else if constexpr (TFormulation == SolidFormulation::AXISYM_SMALL_DISPLACEMENT)
        AxisymSmallDisplacementKinematics(*this, point, rKinematics);
    else
        AxisymTotalLagrangianKinematics(*this, point, rKinematics);
}

#define CONTACT_APP_SOLID_ELEMENT_INSTANTIATE(TDim, TNumNodes, Geometry, Suffix)                                \
    template class SolidElement<SolidFormulation::SMALL_DISPLACEMENT, TDim, TNumNodes, kSolidStrainSize<TDim>>; \
    template class SolidElement<SolidFormulation::TOTAL_LAGRANGIAN, TDim, TNumNodes, kSolidStrainSize<TDim>>;
#define CONTACT_APP_AXISYM_SOLID_ELEMENT_INSTANTIATE(TDim, TNumNodes, Geometry, Suffix)      \
    template class SolidElement<SolidFormulation::AXISYM_SMALL_DISPLACEMENT, 2, TNumNodes, 4>; \
    template class SolidElement<SolidFormulation::AXISYM_TOTAL_LAGRANGIAN, 2, TNumNodes, 4>;
CONTACT_APP_SOLID_ELEMENT_SIZES(CONTACT_APP_SOLID_ELEMENT_INSTANTIATE)
CONTACT_APP_AXISYM_SOLID_ELEMENT_SIZES(CONTACT_APP_AXISYM_SOLID_ELEMENT_INSTANTIATE)
#undef CONTACT_APP_SOLID_ELEMENT_INSTANTIATE
#undef CONTACT_APP_AXISYM_SOLID_ELEMENT_INSTANTIATE

}  // namespace contact_app
