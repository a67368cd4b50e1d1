// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "contact_app/kernel/constitutive_law.h"
#include "contact_app/structural/constitutive/elastic_utilities.h"

namespace contact_app {

/// The elastic responses the registered laws implement (elastic_law.cpp: one response and one energy function each).
enum class ElasticResponse { LINEAR, KIRCHHOFF_SAINT_VENANT, NEO_HOOKEAN };

/// An isotropic elastic law: the response TResponse on the kinematic model TModel (3D, plane strain, plane stress,
/// axisymmetric). Every law reads YOUNG_MODULUS and POISSON_RATIO from the element's properties, rejects a wrong
/// strain size or an unusable F with an InputError, and returns STRAIN_ENERGY per unit reference volume from
/// CalculateValue (other variables: 0). Only the registered combinations below are instantiated.
template <ElasticResponse TResponse, detail::ElasticModel TModel>
class ElasticLaw : public ConstitutiveLaw {
public:
    Pointer Clone() const override;
    /// 3 for the 3D models, 2 otherwise.
    int WorkingSpaceDimension() const override;
    /// 6 (3D), 3 (plane) or 4 (axisymmetric).
    int GetStrainSize() const override;
    /// @brief Stress and tangent in @p measure, as flagged in @p rValues (see the aliases for each response).
    /// @param[in,out] rValues strain_vector is read (element-provided) or written
    /// @param[in] measure the stress measure of the returned stress and tangent
    /// @throws InputError for missing E/ν, a wrong strain size or an unusable F; InvertedElementError for
    ///         det F ≤ 0 where the response needs F; ConfigurationError for PK1 (the nonlinear responses)
    void CalculateMaterialResponse(Parameters& rValues, StressMeasure measure) override;
    /// @brief STRAIN_ENERGY per unit reference volume; other variables: 0.
    double CalculateValue(Parameters& rValues, const Variable<double>& rThisVariable) override;
    /// @throws InputError for a missing or non-positive YOUNG_MODULUS, a POISSON_RATIO outside
    ///         [−0.999, 0.499] or a negative DENSITY
    int Check(const Properties& rMaterialProperties, const Geometry& rElementGeometry,
              const ProcessInfo& rCurrentProcessInfo) const override;
    /// The registered name, e.g. "LinearElastic3DLaw".
    std::string Info() const override;
    /// True for the linear response (σ = D ε, no state).
    bool IsLinear() const override { return TResponse == ElasticResponse::LINEAR; }
};

/// Isotropic linear elasticity σ = D ε (docs/theory/structural.md §4), D of the model (3D, plane strain, plane stress,
/// axisymmetric [rr, zz, θθ, rz]). Every StressMeasure returns the same σ = D ε and tangent D, as Kratos.
/// ε is the element's strain (use_element_provided_strain) or the Green–Lagrange E = ½(FᵀF − I), which is
/// then written to strain_vector. Registers LinearElastic3DLaw, LinearElasticPlaneStrain2DLaw,
/// LinearElasticPlaneStress2DLaw, LinearElasticAxisym2DLaw. STRAIN_ENERGY = ½ εᵀ D ε.
template <detail::ElasticModel TModel>
using LinearElasticLaw = ElasticLaw<ElasticResponse::LINEAR, TModel>;
using LinearElastic3DLaw = LinearElasticLaw<detail::ElasticModel::ThreeDimensional>;
using LinearElasticPlaneStrain2DLaw = LinearElasticLaw<detail::ElasticModel::PlaneStrain>;
using LinearElasticPlaneStress2DLaw = LinearElasticLaw<detail::ElasticModel::PlaneStress>;
using LinearElasticAxisym2DLaw = LinearElasticLaw<detail::ElasticModel::Axisymmetric>;

/// Kirchhoff–Saint-Venant hyperelasticity S = D E = λ tr(E) I + 2μ E (docs/theory/structural.md §4), D the
/// linear-elastic
/// matrix of the model (3D, plane strain, plane stress). PK2: E is the element's strain or E(F);
/// tangent D. Kirchhoff: E(F) always, τ = F S Fᵀ, tangent c = Q D Qᵀ (push-forward); Cauchy: both / det F.
/// For Kirchhoff/Cauchy the law writes the Almansi strain ½(I − b⁻¹) unless the element provides strain.
/// Registers KirchhoffSaintVenant3DLaw, …PlaneStrain2DLaw, …PlaneStress2DLaw. STRAIN_ENERGY = ½ Eᵀ D E.
/// PK1 is rejected (ConfigurationError).
template <detail::ElasticModel TModel>
using KirchhoffSaintVenantLaw = ElasticLaw<ElasticResponse::KIRCHHOFF_SAINT_VENANT, TModel>;
using KirchhoffSaintVenant3DLaw = KirchhoffSaintVenantLaw<detail::ElasticModel::ThreeDimensional>;
using KirchhoffSaintVenantPlaneStrain2DLaw = KirchhoffSaintVenantLaw<detail::ElasticModel::PlaneStrain>;
using KirchhoffSaintVenantPlaneStress2DLaw = KirchhoffSaintVenantLaw<detail::ElasticModel::PlaneStress>;

/// Compressible Neo-Hookean law (docs/theory/structural.md §4): W = λ/2 (ln J)² − μ ln J + μ/2 (tr C − 3), J =
/// determinant_f
/// as passed by the element, λ and μ the 3D Lamé constants.
/// PK2: S = λ ln J C⁻¹ + μ (I − C⁻¹), ℂ = λ C⁻¹⊗C⁻¹ + (μ − λ ln J)(C⁻¹ ⊙ C⁻¹ sym.), E(F) written to strain_vector.
/// Kirchhoff: τ = λ ln J I + μ (b − I), c = λ I⊗I + (μ − λ ln J)(2 𝕀); Cauchy: both / J; the Almansi strain
/// is written unless the element provides strain (docs/theory/structural.md §8 D4).
/// Plane strain: 2×2 F, F₃₃ = 1, strain size 3. Registers HyperElastic3DLaw,
/// HyperElasticPlaneStrain2DLaw. The element's strain vector is never used for the stress (the law reads F).
/// PK1 is rejected (ConfigurationError).
using HyperElastic3DLaw = ElasticLaw<ElasticResponse::NEO_HOOKEAN, detail::ElasticModel::ThreeDimensional>;
using HyperElasticPlaneStrain2DLaw = ElasticLaw<ElasticResponse::NEO_HOOKEAN, detail::ElasticModel::PlaneStrain>;

}  // namespace contact_app
