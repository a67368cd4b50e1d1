// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/structural/elements/base_solid_element.h"

namespace contact_app {

/// Small-displacement solid (Kratos SmallDisplacement): kinematics on the initial configuration only,
/// ε = B u, RHS = ∫_Ω0 (Nᵀ b − Bᵀ σ) dΩ, LHS = ∫_Ω0 Bᵀ D B dΩ (× THICKNESS in 2D), no geometric stiffness.
/// The law receives ε (USE_ELEMENT_PROVIDED_STRAIN), the PK2 measure and the "equivalent F" I + ε, which the
/// Neo-Hookean laws use (docs/theory/solid_elements.md, last paragraph: then the tangent is the law's ℂ(C_eq), exact
/// only as ε → 0).
/// Registers SmallDisplacementElement{2D3N,2D4N,2D6N,3D4N,3D8N,3D10N}.
template <int TDim, int TNumNodes>
class SmallDisplacementElement : public BaseSolidElement<TDim, TNumNodes, kSolidStrainSize<TDim>> {
public:
    using BaseType = BaseSolidElement<TDim, TNumNodes, kSolidStrainSize<TDim>>;
    using BaseType::BaseType;
    using BaseType::Create;
    using typename BaseType::Kinematics;
    using typename BaseType::StressMeasure;

    /// @brief A new SmallDisplacementElement on @p geometry (shared), with @p properties (shared).
    Element::Pointer Create(IndexType new_id, Geometry::Pointer geometry,
                            Properties::Pointer properties) const override;

protected:
    const char* FamilyName() const override { return "SmallDisplacementElement"; }
    StressMeasure GetStressMeasure() const override { return StressMeasure::PK2; }
    bool UseElementProvidedStrain() const override { return true; }
    bool UsesGeometricStiffness() const override { return false; }
    void ComputeKinematics(std::size_t point, Kinematics& rKinematics) const override;
};

#define CONTACT_APP_SMALL_DISPLACEMENT_EXTERN(TDim, TNumNodes, Geometry, Suffix) \
    extern template class SmallDisplacementElement<TDim, TNumNodes>;
CONTACT_APP_SOLID_ELEMENT_SIZES(CONTACT_APP_SMALL_DISPLACEMENT_EXTERN)
#undef CONTACT_APP_SMALL_DISPLACEMENT_EXTERN

}  // namespace contact_app
