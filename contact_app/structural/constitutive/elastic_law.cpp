// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/structural/constitutive/elastic_law.h"

#include <cmath>
#include <memory>

#include <Eigen/LU>

#include "contact_app/kernel/variables.h"

namespace contact_app {
namespace {

using detail::ElasticModel;
using StressMeasure = ConstitutiveLaw::StressMeasure;

double Delta(int i, int j) { return i == j ? 1.0 : 0.0; }

/// σ = D ε for every measure: ε is the element's strain or E(F), which is then written.
void LinearResponse(ConstitutiveLaw::Parameters& rValues, ElasticModel model, const std::string& name) {
    const auto constants = detail::ReadElasticConstants(rValues, name);
    if (rValues.use_element_provided_strain)
        detail::CheckStrainVectorSize(rValues.strain_vector, detail::StrainSize(model), name);
    else
        rValues.strain_vector = detail::MaterialStrain(rValues, model, name);
    const Matrix D = detail::LinearElasticMatrix(model, constants.young, constants.poisson);
    if (rValues.compute_stress) rValues.stress_vector = D * rValues.strain_vector;
    if (rValues.compute_constitutive_tensor) rValues.constitutive_matrix = D;
}

/// S = D E (PK2), or its push-forward with E(F) (Kirchhoff, Cauchy: / det F).
void SaintVenantResponse(ConstitutiveLaw::Parameters& rValues, StressMeasure measure, ElasticModel model,
                         const std::string& name) {
    if (measure == StressMeasure::PK1) detail::ThrowUnsupportedPK1(name);
    if (measure == StressMeasure::PK2) return LinearResponse(rValues, model, name);
    const auto constants = detail::ReadElasticConstants(rValues, name);
    const Matrix D = detail::LinearElasticMatrix(model, constants.young, constants.poisson);
    const int size = detail::StrainSize(model);
    // Kirchhoff / Cauchy: spatial quantities need F, so E is always recomputed from it (docs/theory/structural.md §4).
    const Matrix F = detail::DeformationGradient(rValues, detail::TensorDimension(model), false, name);
    if (measure == StressMeasure::Cauchy) detail::CheckPositiveDeterminant(rValues, name);
    const double scale = measure == StressMeasure::Cauchy ? 1.0 / rValues.determinant_f : 1.0;
    const Matrix Q = detail::PushForwardMatrix(F, size);
    if (rValues.compute_stress) rValues.stress_vector = scale * (Q * (D * detail::GreenLagrangeStrainVector(F, size)));
    if (rValues.compute_constitutive_tensor) rValues.constitutive_matrix = scale * (Q * D * Q.transpose());
    if (!rValues.use_element_provided_strain) rValues.strain_vector = detail::AlmansiStrainVector(F, size);
}

/// Compressible Neo-Hookean: S, ℂ from C (PK2) or τ, c from b (Kirchhoff, Cauchy: / J).
void NeoHookeanResponse(ConstitutiveLaw::Parameters& rValues, StressMeasure measure, ElasticModel model,
                        const std::string& name) {
    if (measure == StressMeasure::PK1) detail::ThrowUnsupportedPK1(name);
    const auto constants = detail::ReadElasticConstants(rValues, name);
    detail::CheckPositiveDeterminant(rValues, name);
    const int dim = detail::TensorDimension(model);
    const Matrix F = detail::DeformationGradient(rValues, dim, false, name);
    const int size = detail::StrainSize(model);
    const double lambda = constants.lambda;
    const double log_j = std::log(rValues.determinant_f);
    const double shear = constants.mu - lambda * log_j;  // μ − λ ln J
    const Matrix I = Matrix::Identity(dim, dim);

    if (measure == StressMeasure::PK2) {
        const Matrix C_inv = (F.transpose() * F).inverse();
        if (rValues.compute_stress)
            rValues.stress_vector =
                detail::StressTensorToVector(lambda * log_j * C_inv + constants.mu * (I - C_inv), size);
        if (rValues.compute_constitutive_tensor) {
            rValues.constitutive_matrix = detail::VoigtTangent(size, [&](int i, int j, int k, int l) {
                return lambda * C_inv(i, j) * C_inv(k, l) +
                       shear * (C_inv(i, k) * C_inv(j, l) + C_inv(i, l) * C_inv(j, k));
            });
        }
        if (!rValues.use_element_provided_strain) rValues.strain_vector = detail::GreenLagrangeStrainVector(F, size);
        return;
    }

    const double scale = measure == StressMeasure::Cauchy ? 1.0 / rValues.determinant_f : 1.0;
    if (rValues.compute_stress) {
        const Matrix kirchhoff = lambda * log_j * I + constants.mu * (F * F.transpose() - I);
        rValues.stress_vector = scale * detail::StressTensorToVector(kirchhoff, size);
    }
    if (rValues.compute_constitutive_tensor) {
        rValues.constitutive_matrix = scale * detail::VoigtTangent(size, [&](int i, int j, int k, int l) {
            return lambda * Delta(i, j) * Delta(k, l) + shear * (Delta(i, k) * Delta(j, l) + Delta(i, l) * Delta(j, k));
        });
    }
    if (!rValues.use_element_provided_strain) rValues.strain_vector = detail::AlmansiStrainVector(F, size);
}

/// ½ Eᵀ D E, E the material strain (the linear law's ½ εᵀ D ε).
double QuadraticEnergy(ConstitutiveLaw::Parameters& rValues, ElasticModel model, const std::string& name) {
    const auto constants = detail::ReadElasticConstants(rValues, name);
    const Vector strain = detail::MaterialStrain(rValues, model, name);
    return 0.5 * strain.dot(detail::LinearElasticMatrix(model, constants.young, constants.poisson) * strain);
}

/// W = λ/2 (ln J)² − μ ln J + μ/2 (tr C − 3).
double NeoHookeanEnergy(ConstitutiveLaw::Parameters& rValues, ElasticModel model, const std::string& name) {
    const auto constants = detail::ReadElasticConstants(rValues, name);
    detail::CheckPositiveDeterminant(rValues, name);
    const int dim = detail::TensorDimension(model);
    const Matrix F = detail::DeformationGradient(rValues, dim, false, name);
    // Plane strain: C₃₃ = 1 adds 1 to the in-plane trace.
    const double trace_c = (F.transpose() * F).trace() + (dim == 2 ? 1.0 : 0.0);
    const double log_j = std::log(rValues.determinant_f);
    return 0.5 * constants.lambda * log_j * log_j - constants.mu * log_j + 0.5 * constants.mu * (trace_c - 3.0);
}

/// The registered names, [response][model].
constexpr const char* kNames[3][4] = {
    {"LinearElastic3DLaw", "LinearElasticPlaneStrain2DLaw", "LinearElasticPlaneStress2DLaw",
     "LinearElasticAxisym2DLaw"},
    {"KirchhoffSaintVenant3DLaw", "KirchhoffSaintVenantPlaneStrain2DLaw", "KirchhoffSaintVenantPlaneStress2DLaw", ""},
    {"HyperElastic3DLaw", "HyperElasticPlaneStrain2DLaw", "", ""},
};

}  // namespace

template <ElasticResponse TResponse, ElasticModel TModel>
ConstitutiveLaw::Pointer ElasticLaw<TResponse, TModel>::Clone() const {
    return std::make_shared<ElasticLaw>(*this);
}

template <ElasticResponse TResponse, ElasticModel TModel>
int ElasticLaw<TResponse, TModel>::WorkingSpaceDimension() const {
    return TModel == ElasticModel::ThreeDimensional ? 3 : 2;
}

template <ElasticResponse TResponse, ElasticModel TModel>
int ElasticLaw<TResponse, TModel>::GetStrainSize() const {
    return detail::StrainSize(TModel);
}

template <ElasticResponse TResponse, ElasticModel TModel>
void ElasticLaw<TResponse, TModel>::CalculateMaterialResponse(Parameters& rValues, StressMeasure measure) {
    if constexpr (TResponse == ElasticResponse::LINEAR)
        LinearResponse(rValues, TModel, Info());
    else if constexpr (TResponse == ElasticResponse::KIRCHHOFF_SAINT_VENANT)
        SaintVenantResponse(rValues, measure, TModel, Info());
    else
        NeoHookeanResponse(rValues, measure, TModel, Info());
}

template <ElasticResponse TResponse, ElasticModel TModel>
double ElasticLaw<TResponse, TModel>::CalculateValue(Parameters& rValues, const Variable<double>& rThisVariable) {
    if (rThisVariable != STRAIN_ENERGY) return ConstitutiveLaw::CalculateValue(rValues, rThisVariable);
    if constexpr (TResponse == ElasticResponse::NEO_HOOKEAN)
        return NeoHookeanEnergy(rValues, TModel, Info());
    else
        return QuadraticEnergy(rValues, TModel, Info());
}

template <ElasticResponse TResponse, ElasticModel TModel>
int ElasticLaw<TResponse, TModel>::Check(const Properties& rMaterialProperties, const Geometry&,
                                         const ProcessInfo&) const {
    detail::CheckElasticProperties(rMaterialProperties, Info());
    return 0;
}

template <ElasticResponse TResponse, ElasticModel TModel>
std::string ElasticLaw<TResponse, TModel>::Info() const {
    return kNames[static_cast<int>(TResponse)][static_cast<int>(TModel)];
}

template class ElasticLaw<ElasticResponse::LINEAR, ElasticModel::ThreeDimensional>;
template class ElasticLaw<ElasticResponse::LINEAR, ElasticModel::PlaneStrain>;
template class ElasticLaw<ElasticResponse::LINEAR, ElasticModel::PlaneStress>;
template class ElasticLaw<ElasticResponse::LINEAR, ElasticModel::Axisymmetric>;
template class ElasticLaw<ElasticResponse::KIRCHHOFF_SAINT_VENANT, ElasticModel::ThreeDimensional>;
template class ElasticLaw<ElasticResponse::KIRCHHOFF_SAINT_VENANT, ElasticModel::PlaneStrain>;
template class ElasticLaw<ElasticResponse::KIRCHHOFF_SAINT_VENANT, ElasticModel::PlaneStress>;
template class ElasticLaw<ElasticResponse::NEO_HOOKEAN, ElasticModel::ThreeDimensional>;
template class ElasticLaw<ElasticResponse::NEO_HOOKEAN, ElasticModel::PlaneStrain>;

}  // namespace contact_app
