// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "contact_app/kernel/constitutive_law.h"
#include "contact_app/structural/constitutive/elastic_utilities.h"

namespace contact_app {

/// Kirchhoff–Saint-Venant hyperelasticity S = D E = λ tr(E) I + 2μ E (docs/theory/structural.md §4), D the
/// linear-elastic
/// matrix of the model (3D, plane strain, plane stress). PK2: E is the element's strain or E(F);
/// tangent D. Kirchhoff: E(F) always, τ = F S Fᵀ, tangent c = Q D Qᵀ (push-forward); Cauchy: both / det F.
/// For Kirchhoff/Cauchy the law writes the Almansi strain ½(I − b⁻¹) unless the element provides strain.
/// Registers KirchhoffSaintVenant3DLaw, …PlaneStrain2DLaw, …PlaneStress2DLaw. STRAIN_ENERGY = ½ Eᵀ D E.
/// PK1 is rejected (ConfigurationError). @tparam TModel ThreeDimensional, PlaneStrain or PlaneStress.
template <detail::ElasticModel TModel>
class KirchhoffSaintVenantLaw : public ConstitutiveLaw {
public:
    Pointer Clone() const override;
    /// 3 for the 3D law, 2 otherwise.
    int WorkingSpaceDimension() const override;
    /// 6 or 3.
    int GetStrainSize() const override;
    /// @brief Stress and tangent in @p measure (PK2, Kirchhoff or Cauchy), as flagged in @p rValues.
    /// @param[in,out] rValues strain_vector is read (element-provided, PK2 only) or written
    /// @param[in] measure the stress measure of the returned stress and tangent
    /// @throws InputError for missing E/ν, a wrong strain size or an unusable F; InvertedElementError for
    ///         det F ≤ 0 (Cauchy);
    ///         ConfigurationError for PK1
    void CalculateMaterialResponse(Parameters& rValues, StressMeasure measure) override;
    /// @brief STRAIN_ENERGY = ½ Eᵀ D E per unit reference volume; other variables: 0.
    double CalculateValue(Parameters& rValues, const Variable<double>& rThisVariable) override;
    /// @throws InputError as LinearElasticLaw::Check
    int Check(const Properties& rMaterialProperties, const Geometry& rElementGeometry,
              const ProcessInfo& rCurrentProcessInfo) const override;
    /// The registered name, e.g. "KirchhoffSaintVenant3DLaw".
    std::string Info() const override;
};

using KirchhoffSaintVenant3DLaw = KirchhoffSaintVenantLaw<detail::ElasticModel::ThreeDimensional>;
using KirchhoffSaintVenantPlaneStrain2DLaw = KirchhoffSaintVenantLaw<detail::ElasticModel::PlaneStrain>;
using KirchhoffSaintVenantPlaneStress2DLaw = KirchhoffSaintVenantLaw<detail::ElasticModel::PlaneStress>;

}  // namespace contact_app
