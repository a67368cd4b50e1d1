// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "contact_app/kernel/constitutive_law.h"
#include "contact_app/structural/constitutive/elastic_utilities.h"

namespace contact_app {

/// Isotropic linear elasticity σ = D ε (docs/theory/structural.md §4), D of the model (3D, plane strain, plane stress,
/// axisymmetric [rr, zz, θθ, rz]). Every StressMeasure returns the same σ = D ε and tangent D, as Kratos.
/// ε is the element's strain (use_element_provided_strain) or the Green–Lagrange E = ½(FᵀF − I), which is
/// then written to strain_vector. Registers LinearElastic3DLaw, LinearElasticPlaneStrain2DLaw,
/// LinearElasticPlaneStress2DLaw, LinearElasticAxisym2DLaw. STRAIN_ENERGY = ½ εᵀ D ε.
/// @tparam TModel the kinematic model; instantiated for the four registered laws only.
template <detail::ElasticModel TModel>
class LinearElasticLaw : public ConstitutiveLaw {
public:
    Pointer Clone() const override;
    /// 3 for the 3D law, 2 otherwise.
    int WorkingSpaceDimension() const override;
    /// 6, 3 or 4 (axisymmetric).
    int GetStrainSize() const override;
    /// @brief σ = D ε into stress_vector, D into constitutive_matrix (as flagged), for any @p measure.
    /// @param[in,out] rValues strain_vector is read (element-provided) or written (E from F)
    /// @param[in] measure the stress measure asked for; it does not change the result here
    /// @throws InputError for missing E/ν, a wrong strain size or an unusable F
    void CalculateMaterialResponse(Parameters& rValues, StressMeasure measure) override;
    /// @brief STRAIN_ENERGY = ½ εᵀ D ε (energy per unit reference volume); other variables: 0.
    double CalculateValue(Parameters& rValues, const Variable<double>& rThisVariable) override;
    /// @throws InputError for a missing or non-positive YOUNG_MODULUS, a POISSON_RATIO outside
    ///         [−0.999, 0.499] or a negative DENSITY
    int Check(const Properties& rMaterialProperties, const Geometry& rElementGeometry,
              const ProcessInfo& rCurrentProcessInfo) const override;
    /// The registered name, e.g. "LinearElastic3DLaw".
    std::string Info() const override;
};

using LinearElastic3DLaw = LinearElasticLaw<detail::ElasticModel::ThreeDimensional>;
using LinearElasticPlaneStrain2DLaw = LinearElasticLaw<detail::ElasticModel::PlaneStrain>;
using LinearElasticPlaneStress2DLaw = LinearElasticLaw<detail::ElasticModel::PlaneStress>;
using LinearElasticAxisym2DLaw = LinearElasticLaw<detail::ElasticModel::Axisymmetric>;

}  // namespace contact_app
