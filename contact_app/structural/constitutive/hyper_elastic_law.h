// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "contact_app/kernel/constitutive_law.h"

namespace contact_app {

/// Compressible Neo-Hookean law (docs/theory/structural.md §4): W = λ/2 (ln J)² − μ ln J + μ/2 (tr C − 3), J =
/// determinant_f
/// as passed by the element, λ and μ the 3D Lamé constants.
/// PK2: S = λ ln J C⁻¹ + μ (I − C⁻¹), ℂ = λ C⁻¹⊗C⁻¹ + (μ − λ ln J)(C⁻¹ ⊙ C⁻¹ sym.), E(F) written to strain_vector.
/// Kirchhoff: τ = λ ln J I + μ (b − I), c = λ I⊗I + (μ − λ ln J)(2 𝕀); Cauchy: both / J; the Almansi strain
/// is written unless the element provides strain (docs/theory/structural.md §8 D4).
/// TDim = 2 is plane strain (2×2 F, F₃₃ = 1, strain size 3). Registers HyperElastic3DLaw,
/// HyperElasticPlaneStrain2DLaw. The element's strain vector is never used for the stress (the law reads F).
/// PK1 is rejected (ConfigurationError). @tparam TDim 2 or 3.
template <int TDim>
class HyperElasticLaw : public ConstitutiveLaw {
public:
    Pointer Clone() const override;
    /// TDim.
    int WorkingSpaceDimension() const override;
    /// 6 (3D) or 3 (plane strain).
    int GetStrainSize() const override;
    /// @brief Stress and tangent in @p measure (PK2, Kirchhoff or Cauchy), as flagged in @p rValues.
    /// @throws InputError for missing E/ν or an unusable F; InvertedElementError for det F ≤ 0;
    ///         ConfigurationError for PK1
    void CalculateMaterialResponse(Parameters& rValues, StressMeasure measure) override;
    /// @brief STRAIN_ENERGY = W(F, J) per unit reference volume; other variables: 0.
    /// @throws InvertedElementError for det F ≤ 0
    double CalculateValue(Parameters& rValues, const Variable<double>& rThisVariable) override;
    /// @throws InputError as LinearElasticLaw::Check
    int Check(const Properties& rMaterialProperties, const Geometry& rElementGeometry,
              const ProcessInfo& rCurrentProcessInfo) const override;
    /// The registered name, e.g. "HyperElastic3DLaw".
    std::string Info() const override;
};

using HyperElastic3DLaw = HyperElasticLaw<3>;
using HyperElasticPlaneStrain2DLaw = HyperElasticLaw<2>;

}  // namespace contact_app
