// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/structural/elements/base_solid_element.h"

namespace contact_app {

/// Total-Lagrangian solid (Kratos TotalLagrangian): integrates on the initial configuration with
/// F = ∂x/∂X from the current node coordinates, E = ½(FᵀF − I), PK2 stress S from the law,
/// RHS = ∫_Ω0 (Nᵀ b − B_Lᵀ S) dΩ, LHS = ∫_Ω0 (B_Lᵀ D B_L + K_g[S]) dΩ (× THICKNESS in 2D), with the nonlinear
/// B_L (δE = B_L δu) built from F and ∂N/∂X. Nothing is stored between steps.
/// Registers TotalLagrangianElement{2D3N,2D4N,2D6N,3D4N,3D8N,3D10N}.
template <int TDim, int TNumNodes>
class TotalLagrangianElement : public BaseSolidElement<TDim, TNumNodes, kSolidStrainSize<TDim>> {
public:
    using BaseType = BaseSolidElement<TDim, TNumNodes, kSolidStrainSize<TDim>>;
    using BaseType::BaseType;
    using BaseType::Create;
    using typename BaseType::Kinematics;
    using typename BaseType::StressMeasure;

    /// @brief A new TotalLagrangianElement on @p geometry (shared), with @p properties (shared).
    Element::Pointer Create(IndexType new_id, Geometry::Pointer geometry,
                            Properties::Pointer properties) const override;

protected:
    const char* FamilyName() const override { return "TotalLagrangianElement"; }
    StressMeasure GetStressMeasure() const override { return StressMeasure::PK2; }
    bool UseElementProvidedStrain() const override { return false; }
    bool UsesGeometricStiffness() const override { return true; }
    void ComputeKinematics(std::size_t point, Kinematics& rKinematics) const override;
};

#define CONTACT_APP_TOTAL_LAGRANGIAN_EXTERN(TDim, TNumNodes, Geometry, Suffix) \
    extern template class TotalLagrangianElement<TDim, TNumNodes>;
CONTACT_APP_SOLID_ELEMENT_SIZES(CONTACT_APP_TOTAL_LAGRANGIAN_EXTERN)
#undef CONTACT_APP_TOTAL_LAGRANGIAN_EXTERN

}  // namespace contact_app
