// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/structural/constitutive/hyper_elastic_law.h"

#include <cmath>
#include <memory>

#include <Eigen/LU>

#include "contact_app/kernel/variables.h"
#include "contact_app/structural/constitutive/elastic_utilities.h"

namespace contact_app {

namespace {

constexpr int StrainSizeOf(int dim) { return dim == 3 ? 6 : 3; }

double Delta(int i, int j) { return i == j ? 1.0 : 0.0; }

}  // namespace

template <int TDim>
ConstitutiveLaw::Pointer HyperElasticLaw<TDim>::Clone() const {
    return std::make_shared<HyperElasticLaw<TDim>>(*this);
}

template <int TDim>
int HyperElasticLaw<TDim>::WorkingSpaceDimension() const {
    return TDim;
}

template <int TDim>
int HyperElasticLaw<TDim>::GetStrainSize() const {
    return StrainSizeOf(TDim);
}

template <int TDim>
void HyperElasticLaw<TDim>::CalculateMaterialResponse(Parameters& rValues, StressMeasure measure) {
    const std::string name = Info();
    if (measure == StressMeasure::PK1) detail::ThrowUnsupportedPK1(name);
    const auto constants = detail::ReadElasticConstants(rValues, name);
    detail::CheckPositiveDeterminant(rValues, name);
    const Matrix F = detail::DeformationGradient(rValues, TDim, false, name);
    const int size = GetStrainSize();
    const double lambda = constants.lambda;
    const double log_j = std::log(rValues.determinant_f);
    const double shear = constants.mu - lambda * log_j;  // μ − λ ln J
    const Matrix I = Matrix::Identity(TDim, TDim);

    if (measure == StressMeasure::PK2) {
        const Matrix C_inv = (F.transpose() * F).inverse();
        if (rValues.compute_stress)
            rValues.stress_vector = detail::StressTensorToVector(lambda * log_j * C_inv + constants.mu * (I - C_inv), size);
        if (rValues.compute_constitutive_tensor) {
            rValues.constitutive_matrix = detail::VoigtTangent(size, [&](int i, int j, int k, int l) {
                return lambda * C_inv(i, j) * C_inv(k, l) + shear * (C_inv(i, k) * C_inv(j, l) + C_inv(i, l) * C_inv(j, k));
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

template <int TDim>
double HyperElasticLaw<TDim>::CalculateValue(Parameters& rValues, const Variable<double>& rThisVariable) {
    if (rThisVariable != STRAIN_ENERGY) return ConstitutiveLaw::CalculateValue(rValues, rThisVariable);
    const std::string name = Info();
    const auto constants = detail::ReadElasticConstants(rValues, name);
    detail::CheckPositiveDeterminant(rValues, name);
    const Matrix F = detail::DeformationGradient(rValues, TDim, false, name);
    // Plane strain: C₃₃ = 1 adds 1 to the in-plane trace.
    const double trace_c = (F.transpose() * F).trace() + (TDim == 2 ? 1.0 : 0.0);
    const double log_j = std::log(rValues.determinant_f);
    return 0.5 * constants.lambda * log_j * log_j - constants.mu * log_j + 0.5 * constants.mu * (trace_c - 3.0);
}

template <int TDim>
int HyperElasticLaw<TDim>::Check(const Properties& rMaterialProperties, const Geometry&, const ProcessInfo&) const {
    detail::CheckElasticProperties(rMaterialProperties, Info());
    return 0;
}

template <int TDim>
std::string HyperElasticLaw<TDim>::Info() const {
    return TDim == 3 ? "HyperElastic3DLaw" : "HyperElasticPlaneStrain2DLaw";
}

template class HyperElasticLaw<2>;
template class HyperElasticLaw<3>;

}  // namespace contact_app
