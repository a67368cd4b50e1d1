// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/structural/elements/base_solid_element.h"

namespace contact_app {

/// Axisymmetric total-Lagrangian solid (Kratos AxisymTotalLagrangian, implemented consistently;
/// docs/theory/structural.md §8 D3 lists
/// the Kratos defects). x = r, y = z; F = [∂x/∂X, 0; 0, r/R] with R = Σ N_k X_k the initial and r = Σ N_k x_k the
/// current radius; E = ½(FᵀF − I) in [rr, zz, θθ, rz]; hoop row of B_L: (r/R)·N_i/R; K_g adds S_θθ N_i N_j / R².
/// RHS = ∫ (Nᵀ b − B_Lᵀ S) 2πR dA0, LHS = ∫ (B_Lᵀ D B_L + K_g[S]) 2πR dA0 (THICKNESS does not enter).
/// The law receives E (USE_ELEMENT_PROVIDED_STRAIN) and the 3×3 F. Needs a strain-size-4 law.
/// Registers AxisymTotalLagrangianElement2D3N/2D4N and the aliases TotalLagrangianAxisymElement2D3N/2D4N.
template <int TNumNodes>
class AxisymTotalLagrangianElement : public BaseSolidElement<2, TNumNodes, 4> {
public:
    using BaseType = BaseSolidElement<2, TNumNodes, 4>;
    using BaseType::BaseType;
    using BaseType::Create;
    using typename BaseType::Kinematics;
    using typename BaseType::StressMeasure;

    /// @brief A new AxisymTotalLagrangianElement on @p geometry (shared), with @p properties (shared).
    Element::Pointer Create(IndexType new_id, Geometry::Pointer geometry,
                            Properties::Pointer properties) const override;

protected:
    const char* FamilyName() const override { return "AxisymTotalLagrangianElement"; }
    StressMeasure GetStressMeasure() const override { return StressMeasure::PK2; }
    bool UseElementProvidedStrain() const override { return true; }
    bool UsesGeometricStiffness() const override { return true; }
    void ComputeKinematics(std::size_t point, Kinematics& rKinematics) const override;
};

#define CONTACT_APP_AXISYM_TOTAL_LAGRANGIAN_EXTERN(TDim, TNumNodes, Geometry, Suffix) \
    extern template class AxisymTotalLagrangianElement<TNumNodes>;
CONTACT_APP_AXISYM_SOLID_ELEMENT_SIZES(CONTACT_APP_AXISYM_TOTAL_LAGRANGIAN_EXTERN)
#undef CONTACT_APP_AXISYM_TOTAL_LAGRANGIAN_EXTERN

}  // namespace contact_app
