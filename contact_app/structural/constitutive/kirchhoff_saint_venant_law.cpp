// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/structural/constitutive/kirchhoff_saint_venant_law.h"

#include <memory>

#include "contact_app/kernel/variables.h"

namespace contact_app {

using detail::ElasticModel;

template <ElasticModel TModel>
ConstitutiveLaw::Pointer KirchhoffSaintVenantLaw<TModel>::Clone() const {
    return std::make_shared<KirchhoffSaintVenantLaw<TModel>>(*this);
}

template <ElasticModel TModel>
int KirchhoffSaintVenantLaw<TModel>::WorkingSpaceDimension() const {
    return TModel == ElasticModel::ThreeDimensional ? 3 : 2;
}

template <ElasticModel TModel>
int KirchhoffSaintVenantLaw<TModel>::GetStrainSize() const {
    return detail::StrainSize(TModel);
}

template <ElasticModel TModel>
void KirchhoffSaintVenantLaw<TModel>::CalculateMaterialResponse(Parameters& rValues, StressMeasure measure) {
    const std::string name = Info();
    if (measure == StressMeasure::PK1) detail::ThrowUnsupportedPK1(name);
    const auto constants = detail::ReadElasticConstants(rValues, name);
    const Matrix D = detail::LinearElasticMatrix(TModel, constants.young, constants.poisson);
    const int size = GetStrainSize();

    if (measure == StressMeasure::PK2) {
        if (rValues.use_element_provided_strain) detail::CheckStrainVectorSize(rValues.strain_vector, size, name);
        else rValues.strain_vector = detail::MaterialStrain(rValues, TModel, name);
        if (rValues.compute_stress) rValues.stress_vector = D * rValues.strain_vector;
        if (rValues.compute_constitutive_tensor) rValues.constitutive_matrix = D;
        return;
    }

    // Kirchhoff / Cauchy: spatial quantities need F, so E is always recomputed from it (docs/theory/structural.md §4).
    const Matrix F = detail::DeformationGradient(rValues, detail::TensorDimension(TModel), false, name);
    if (measure == StressMeasure::Cauchy) detail::CheckPositiveDeterminant(rValues, name);
    const double scale = measure == StressMeasure::Cauchy ? 1.0 / rValues.determinant_f : 1.0;
    const Matrix Q = detail::PushForwardMatrix(F, size);
    if (rValues.compute_stress) rValues.stress_vector = scale * (Q * (D * detail::GreenLagrangeStrainVector(F, size)));
    if (rValues.compute_constitutive_tensor) rValues.constitutive_matrix = scale * (Q * D * Q.transpose());
    if (!rValues.use_element_provided_strain) rValues.strain_vector = detail::AlmansiStrainVector(F, size);
}

template <ElasticModel TModel>
double KirchhoffSaintVenantLaw<TModel>::CalculateValue(Parameters& rValues, const Variable<double>& rThisVariable) {
    if (rThisVariable != STRAIN_ENERGY) return ConstitutiveLaw::CalculateValue(rValues, rThisVariable);
    const std::string name = Info();
    const auto constants = detail::ReadElasticConstants(rValues, name);
    const Vector strain = detail::MaterialStrain(rValues, TModel, name);
    return 0.5 * strain.dot(detail::LinearElasticMatrix(TModel, constants.young, constants.poisson) * strain);
}

template <ElasticModel TModel>
int KirchhoffSaintVenantLaw<TModel>::Check(const Properties& rMaterialProperties, const Geometry&,
                                           const ProcessInfo&) const {
    detail::CheckElasticProperties(rMaterialProperties, Info());
    return 0;
}

template <ElasticModel TModel>
std::string KirchhoffSaintVenantLaw<TModel>::Info() const {
    switch (TModel) {
        case ElasticModel::ThreeDimensional: return "KirchhoffSaintVenant3DLaw";
        case ElasticModel::PlaneStrain: return "KirchhoffSaintVenantPlaneStrain2DLaw";
        case ElasticModel::PlaneStress: return "KirchhoffSaintVenantPlaneStress2DLaw";
        default: return "KirchhoffSaintVenantLaw";
    }
}

template class KirchhoffSaintVenantLaw<ElasticModel::ThreeDimensional>;
template class KirchhoffSaintVenantLaw<ElasticModel::PlaneStrain>;
template class KirchhoffSaintVenantLaw<ElasticModel::PlaneStress>;

}  // namespace contact_app
