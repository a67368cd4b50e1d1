// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/structural/constitutive/linear_elastic_law.h"

#include <memory>

#include "contact_app/kernel/variables.h"

namespace contact_app {

using detail::ElasticModel;

template <ElasticModel TModel>
ConstitutiveLaw::Pointer LinearElasticLaw<TModel>::Clone() const {
    return std::make_shared<LinearElasticLaw<TModel>>(*this);
}

template <ElasticModel TModel>
int LinearElasticLaw<TModel>::WorkingSpaceDimension() const {
    return TModel == ElasticModel::ThreeDimensional ? 3 : 2;
}

template <ElasticModel TModel>
int LinearElasticLaw<TModel>::GetStrainSize() const {
    return detail::StrainSize(TModel);
}

template <ElasticModel TModel>
void LinearElasticLaw<TModel>::CalculateMaterialResponse(Parameters& rValues, StressMeasure) {
    const std::string name = Info();
    const auto constants = detail::ReadElasticConstants(rValues, name);
    if (rValues.use_element_provided_strain) detail::CheckStrainVectorSize(rValues.strain_vector, GetStrainSize(), name);
    else rValues.strain_vector = detail::MaterialStrain(rValues, TModel, name);
    const Matrix D = detail::LinearElasticMatrix(TModel, constants.young, constants.poisson);
    if (rValues.compute_stress) rValues.stress_vector = D * rValues.strain_vector;
    if (rValues.compute_constitutive_tensor) rValues.constitutive_matrix = D;
}

template <ElasticModel TModel>
double LinearElasticLaw<TModel>::CalculateValue(Parameters& rValues, const Variable<double>& rThisVariable) {
    if (rThisVariable != STRAIN_ENERGY) return ConstitutiveLaw::CalculateValue(rValues, rThisVariable);
    const std::string name = Info();
    const auto constants = detail::ReadElasticConstants(rValues, name);
    const Vector strain = detail::MaterialStrain(rValues, TModel, name);
    return 0.5 * strain.dot(detail::LinearElasticMatrix(TModel, constants.young, constants.poisson) * strain);
}

template <ElasticModel TModel>
int LinearElasticLaw<TModel>::Check(const Properties& rMaterialProperties, const Geometry&, const ProcessInfo&) const {
    detail::CheckElasticProperties(rMaterialProperties, Info());
    return 0;
}

template <ElasticModel TModel>
std::string LinearElasticLaw<TModel>::Info() const {
    switch (TModel) {
        case ElasticModel::ThreeDimensional: return "LinearElastic3DLaw";
        case ElasticModel::PlaneStrain: return "LinearElasticPlaneStrain2DLaw";
        case ElasticModel::PlaneStress: return "LinearElasticPlaneStress2DLaw";
        case ElasticModel::Axisymmetric: return "LinearElasticAxisym2DLaw";
    }
    return "LinearElasticLaw";
}

template class LinearElasticLaw<ElasticModel::ThreeDimensional>;
template class LinearElasticLaw<ElasticModel::PlaneStrain>;
template class LinearElasticLaw<ElasticModel::PlaneStress>;
template class LinearElasticLaw<ElasticModel::Axisymmetric>;

}  // namespace contact_app
