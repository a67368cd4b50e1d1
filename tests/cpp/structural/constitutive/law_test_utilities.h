// SPDX-License-Identifier: BSD-3-Clause
/// Helpers shared by the constitutive-law tests: properties, random kinematic states, evaluations, FD.
#pragma once

#include <memory>
#include <random>
#include <string>

#include <Eigen/Dense>

#include "contact_app/kernel/constitutive_law.h"
#include "contact_app/kernel/properties.h"
#include "contact_app/kernel/registry.h"
#include "contact_app/kernel/variables.h"
#include "contact_app/structural/structural_registration.h"

namespace contact_app::testing {

using Measure = ConstitutiveLaw::StressMeasure;

/// Properties @p id with E and ν (and nothing else).
inline std::shared_ptr<Properties> ElasticProperties(double young = 210.0, double poisson = 0.3, IndexType id = 1) {
    auto properties = std::make_shared<Properties>(id);
    properties->SetValue(YOUNG_MODULUS, young);
    properties->SetValue(POISSON_RATIO, poisson);
    return properties;
}

/// A fresh law of registered name @p name.
inline ConstitutiveLaw::Pointer MakeLaw(const std::string& name) {
    RegisterConstitutiveLaws();
    return Registry<ConstitutiveLaw>::Instance().Get(name).Clone();
}

/// Dimension of the deformation gradient a law is given: 2 for plane laws, 3 for 3D and axisymmetric.
inline int TensorDimension(const ConstitutiveLaw& law) { return law.GetStrainSize() == 3 ? 2 : 3; }

/// A random F = I + amplitude·R with det F > 0.3; axisymmetric (strain size 4) F has no r-θ / z-θ coupling.
inline Matrix RandomDeformationGradient(const ConstitutiveLaw& law, std::mt19937& rng, double amplitude = 0.25) {
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    const int dim = TensorDimension(law);
    while (true) {
        Matrix F = Matrix::Identity(dim, dim);
        for (int i = 0; i < dim; ++i)
            for (int j = 0; j < dim; ++j) F(i, j) += amplitude * uniform(rng);
        if (law.GetStrainSize() == 4) F(0, 2) = F(2, 0) = F(1, 2) = F(2, 1) = 0.0;
        if (F.determinant() > 0.3) return F;
    }
}

/// A random Voigt strain of the law's size, components in [−amplitude, amplitude].
inline Vector RandomStrain(const ConstitutiveLaw& law, std::mt19937& rng, double amplitude = 0.05) {
    std::uniform_real_distribution<double> uniform(-amplitude, amplitude);
    Vector strain(law.GetStrainSize());
    for (Eigen::Index i = 0; i < strain.size(); ++i) strain[i] = uniform(rng);
    return strain;
}

/// Parameters with F (and det F = det(F)) or with an element-provided strain.
inline ConstitutiveLaw::Parameters KinematicState(const Properties& properties, const Matrix& F) {
    ConstitutiveLaw::Parameters values;
    values.material_properties = &properties;
    values.deformation_gradient = F;
    values.determinant_f = F.determinant();
    return values;
}
inline ConstitutiveLaw::Parameters ProvidedStrainState(const Properties& properties, const Vector& strain) {
    ConstitutiveLaw::Parameters values;
    values.material_properties = &properties;
    values.use_element_provided_strain = true;
    values.strain_vector = strain;
    return values;
}

/// Runs the law on @p values in @p measure and returns the evaluated parameters.
inline ConstitutiveLaw::Parameters Evaluate(ConstitutiveLaw& law, ConstitutiveLaw::Parameters values, Measure measure) {
    law.CalculateMaterialResponse(values, measure);
    return values;
}

/// max |a − b| / max(max |b|, floor).
inline double RelativeError(const Matrix& a, const Matrix& b, double floor = 1e-12) {
    return (a - b).cwiseAbs().maxCoeff() / std::max(b.cwiseAbs().maxCoeff(), floor);
}

/// Voigt form of a symmetric strain tensor with engineering shear (written out independently of the law).
inline Vector StrainVoigt(const Matrix& E, int strain_size) {
    if (strain_size == 3) return (Vector(3) << E(0, 0), E(1, 1), 2.0 * E(0, 1)).finished();
    if (strain_size == 4) return (Vector(4) << E(0, 0), E(1, 1), E(2, 2), 2.0 * E(0, 1)).finished();
    return (Vector(6) << E(0, 0), E(1, 1), E(2, 2), 2.0 * E(0, 1), 2.0 * E(1, 2), 2.0 * E(0, 2)).finished();
}

/// Green–Lagrange strain ½(FᵀF − I) in Voigt form.
inline Vector GreenLagrangeVoigt(const Matrix& F, int strain_size) {
    return StrainVoigt(0.5 * (F.transpose() * F - Matrix::Identity(F.rows(), F.cols())), strain_size);
}

/// Symmetric tensor from a Voigt stress vector (plain shear), independently of the law.
inline Matrix StressTensor(const Vector& voigt) {
    if (voigt.size() == 3) return (Matrix(2, 2) << voigt[0], voigt[2], voigt[2], voigt[1]).finished();
    if (voigt.size() == 4)
        return (Matrix(3, 3) << voigt[0], voigt[3], 0, voigt[3], voigt[1], 0, 0, 0, voigt[2]).finished();
    return (Matrix(3, 3) << voigt[0], voigt[3], voigt[5], voigt[3], voigt[1], voigt[4], voigt[5], voigt[4], voigt[2])
        .finished();
}

/// Voigt vector (plain components) of a symmetric tensor, the inverse of StressTensor.
inline Vector StressVoigt(const Matrix& T, int strain_size) {
    if (strain_size == 3) return (Vector(3) << T(0, 0), T(1, 1), T(0, 1)).finished();
    if (strain_size == 4) return (Vector(4) << T(0, 0), T(1, 1), T(2, 2), T(0, 1)).finished();
    return (Vector(6) << T(0, 0), T(1, 1), T(2, 2), T(0, 1), T(1, 2), T(0, 2)).finished();
}

}  // namespace contact_app::testing
