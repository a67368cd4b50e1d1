// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/structural/elements/base_solid_element.h"

namespace contact_app {

/// The kinematic formulations of the stateless solid elements; each has its row in kSolidFormulations and its
/// kinematics function in solid_element.cpp.
enum class SolidFormulation {
    SMALL_DISPLACEMENT,
    TOTAL_LAGRANGIAN,
    AXISYM_SMALL_DISPLACEMENT,
    AXISYM_TOTAL_LAGRANGIAN
};

/// What a formulation tells the base element (BaseSolidElement's hooks).
struct SolidFormulationTraits {
    const char* name;                           ///< registered family name without the size suffix
    ConstitutiveLaw::StressMeasure measure;     ///< stress measure of the residual
    bool element_provided_strain;               ///< the element computes the strain handed to the law
    bool geometric_stiffness;                   ///< finite strain: adds K_g
    bool constant_kinematics;                   ///< B and weights from the initial configuration only
};

// clang-format off
/// Indexed by SolidFormulation.
inline constexpr SolidFormulationTraits kSolidFormulations[] = {
    {"SmallDisplacementElement",       ConstitutiveLaw::StressMeasure::PK2, true,  false, true},
    {"TotalLagrangianElement",         ConstitutiveLaw::StressMeasure::PK2, false, true,  false},
    {"AxisymSmallDisplacementElement", ConstitutiveLaw::StressMeasure::PK2, true,  false, true},
    {"AxisymTotalLagrangianElement",   ConstitutiveLaw::StressMeasure::PK2, true,  true,  false},
};
// clang-format on

/// A solid element without state of its own between steps: BaseSolidElement with the formulation TFormulation (its
/// traits row and its kinematics, solid_element.cpp, which instantiates every registered size). The registered
/// names are the aliases below; UpdatedLagrangianElement, which keeps F0 between steps, is a class of its own.
template <SolidFormulation TFormulation, int TDim, int TNumNodes, int TStrainSize>
class SolidElement : public BaseSolidElement<TDim, TNumNodes, TStrainSize> {
public:
    using BaseType = BaseSolidElement<TDim, TNumNodes, TStrainSize>;
    using BaseType::BaseType;
    using BaseType::Create;
    using typename BaseType::Kinematics;
    using typename BaseType::StressMeasure;

    /// @param[in] new_id id of the new element
    /// @param[in] geometry its geometry (shared)
    /// @param[in] properties its properties (shared)
    /// @return a new element of this formulation
    Element::Pointer Create(IndexType new_id, Geometry::Pointer geometry,
                            Properties::Pointer properties) const override;

protected:
    static constexpr const SolidFormulationTraits& kTraits = kSolidFormulations[static_cast<int>(TFormulation)];
    const char* FamilyName() const override { return kTraits.name; }
    StressMeasure GetStressMeasure() const override { return kTraits.measure; }
    bool UseElementProvidedStrain() const override { return kTraits.element_provided_strain; }
    bool UsesGeometricStiffness() const override { return kTraits.geometric_stiffness; }
    bool HasConstantKinematics() const override { return kTraits.constant_kinematics; }
    /// The formulation's kinematics (solid_element.cpp).
    void ComputeKinematics(std::size_t point, Kinematics& rKinematics) const override;
};

/// Small-displacement solid (Kratos SmallDisplacement): kinematics on the initial configuration only,
/// ε = B u, RHS = ∫_Ω0 (Nᵀ b − Bᵀ σ) dΩ, LHS = ∫_Ω0 Bᵀ D B dΩ (× THICKNESS in 2D), no geometric stiffness.
/// The law receives ε (USE_ELEMENT_PROVIDED_STRAIN), the PK2 measure and the "equivalent F" I + ε, which the
/// Neo-Hookean laws use (docs/theory/solid_elements.md, last paragraph: then the tangent is the law's ℂ(C_eq), exact
/// only as ε → 0).
/// Registers SmallDisplacementElement{2D3N,2D4N,2D6N,3D4N,3D8N,3D10N}.
template <int TDim, int TNumNodes>
using SmallDisplacementElement =
    SolidElement<SolidFormulation::SMALL_DISPLACEMENT, TDim, TNumNodes, kSolidStrainSize<TDim>>;

/// Total-Lagrangian solid (Kratos TotalLagrangian): integrates on the initial configuration with
/// F = ∂x/∂X from the current node coordinates, E = ½(FᵀF − I), PK2 stress S from the law,
/// RHS = ∫_Ω0 (Nᵀ b − B_Lᵀ S) dΩ, LHS = ∫_Ω0 (B_Lᵀ D B_L + K_g[S]) dΩ (× THICKNESS in 2D), with the nonlinear
/// B_L (δE = B_L δu) built from F and ∂N/∂X. Nothing is stored between steps.
/// Registers TotalLagrangianElement{2D3N,2D4N,2D6N,3D4N,3D8N,3D10N}.
template <int TDim, int TNumNodes>
using TotalLagrangianElement =
    SolidElement<SolidFormulation::TOTAL_LAGRANGIAN, TDim, TNumNodes, kSolidStrainSize<TDim>>;

/// Axisymmetric small-displacement solid (Kratos AxisymSmallDisplacement), x = r, y = z, strain
/// [ε_rr, ε_zz, ε_θθ, γ_rz] with ε_θθ = u_r / R: RHS = ∫ (Nᵀ b − Bᵀ σ) 2πR dA, LHS = ∫ Bᵀ D B 2πR dA on the
/// initial configuration (THICKNESS does not enter). Needs a strain-size-4 law (LinearElasticAxisym2DLaw).
/// Registers AxisymSmallDisplacementElement2D3N/2D4N and the aliases SmallDisplacementAxisymElement2D3N/2D4N.
template <int TNumNodes>
using AxisymSmallDisplacementElement = SolidElement<SolidFormulation::AXISYM_SMALL_DISPLACEMENT, 2, TNumNodes, 4>;

/// Axisymmetric total-Lagrangian solid (Kratos AxisymTotalLagrangian, implemented consistently;
/// docs/theory/structural.md §8 D3 lists
/// the Kratos defects). x = r, y = z; F = [∂x/∂X, 0; 0, r/R] with R = Σ N_k X_k the initial and r = Σ N_k x_k the
/// current radius; E = ½(FᵀF − I) in [rr, zz, θθ, rz]; hoop row of B_L: (r/R)·N_i/R; K_g adds S_θθ N_i N_j / R².
/// RHS = ∫ (Nᵀ b − B_Lᵀ S) 2πR dA0, LHS = ∫ (B_Lᵀ D B_L + K_g[S]) 2πR dA0 (THICKNESS does not enter).
/// The law receives E (USE_ELEMENT_PROVIDED_STRAIN) and the 3×3 F. Needs a strain-size-4 law.
/// Registers AxisymTotalLagrangianElement2D3N/2D4N and the aliases TotalLagrangianAxisymElement2D3N/2D4N.
template <int TNumNodes>
using AxisymTotalLagrangianElement = SolidElement<SolidFormulation::AXISYM_TOTAL_LAGRANGIAN, 2, TNumNodes, 4>;

#define CONTACT_APP_SOLID_ELEMENT_EXTERN(TDim, TNumNodes, Geometry, Suffix)                                       \
    extern template class SolidElement<SolidFormulation::SMALL_DISPLACEMENT, TDim, TNumNodes,                 \
                                       kSolidStrainSize<TDim>>;                                                 \
    extern template class SolidElement<SolidFormulation::TOTAL_LAGRANGIAN, TDim, TNumNodes, kSolidStrainSize<TDim>>;
#define CONTACT_APP_AXISYM_SOLID_ELEMENT_EXTERN(TDim, TNumNodes, Geometry, Suffix)                 \
    extern template class SolidElement<SolidFormulation::AXISYM_SMALL_DISPLACEMENT, 2, TNumNodes, 4>; \
    extern template class SolidElement<SolidFormulation::AXISYM_TOTAL_LAGRANGIAN, 2, TNumNodes, 4>;
CONTACT_APP_SOLID_ELEMENT_SIZES(CONTACT_APP_SOLID_ELEMENT_EXTERN)
CONTACT_APP_AXISYM_SOLID_ELEMENT_SIZES(CONTACT_APP_AXISYM_SOLID_ELEMENT_EXTERN)
#undef CONTACT_APP_SOLID_ELEMENT_EXTERN
#undef CONTACT_APP_AXISYM_SOLID_ELEMENT_EXTERN

}  // namespace contact_app
