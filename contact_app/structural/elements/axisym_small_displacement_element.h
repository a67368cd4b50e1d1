// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/structural/elements/base_solid_element.h"

namespace contact_app {

/// Axisymmetric small-displacement solid (Kratos AxisymSmallDisplacement), x = r, y = z, strain
/// [ε_rr, ε_zz, ε_θθ, γ_rz] with ε_θθ = u_r / R: RHS = ∫ (Nᵀ b − Bᵀ σ) 2πR dA, LHS = ∫ Bᵀ D B 2πR dA on the
/// initial configuration (THICKNESS does not enter). Needs a strain-size-4 law (LinearElasticAxisym2DLaw).
/// Registers AxisymSmallDisplacementElement2D3N/2D4N and the aliases SmallDisplacementAxisymElement2D3N/2D4N.
template <int TNumNodes>
class AxisymSmallDisplacementElement : public BaseSolidElement<2, TNumNodes, 4> {
public:
    using BaseType = BaseSolidElement<2, TNumNodes, 4>;
    using BaseType::BaseType;
    using BaseType::Create;
    using typename BaseType::Kinematics;
    using typename BaseType::StressMeasure;

    /// @brief A new AxisymSmallDisplacementElement on @p geometry (shared), with @p properties (shared).
    Element::Pointer Create(IndexType new_id, Geometry::Pointer geometry,
                            Properties::Pointer properties) const override;

protected:
    const char* FamilyName() const override { return "AxisymSmallDisplacementElement"; }
    StressMeasure GetStressMeasure() const override { return StressMeasure::PK2; }
    bool UseElementProvidedStrain() const override { return true; }
    bool UsesGeometricStiffness() const override { return false; }
    void ComputeKinematics(std::size_t point, Kinematics& rKinematics) const override;
};

#define CONTACT_APP_AXISYM_SMALL_DISPLACEMENT_EXTERN(TDim, TNumNodes, Geometry, Suffix) \
    extern template class AxisymSmallDisplacementElement<TNumNodes>;
CONTACT_APP_AXISYM_SOLID_ELEMENT_SIZES(CONTACT_APP_AXISYM_SMALL_DISPLACEMENT_EXTERN)
#undef CONTACT_APP_AXISYM_SMALL_DISPLACEMENT_EXTERN

}  // namespace contact_app
