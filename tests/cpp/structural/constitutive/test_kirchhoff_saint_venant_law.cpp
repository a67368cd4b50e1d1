// SPDX-License-Identifier: BSD-3-Clause
// Kirchhoff–Saint-Venant laws: S = λ tr E I + 2μ E, τ = F S Fᵀ, Cauchy = τ/J, element strain = linear.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "contact_app/kernel/inverted_element_error.h"
#include "law_test_utilities.h"

namespace contact_app::testing {
namespace {

class KirchhoffSaintVenant : public ::testing::TestWithParam<std::string> {
protected:
    std::string LinearName() const {
        if (GetParam() == "KirchhoffSaintVenant3DLaw") return "LinearElastic3DLaw";
        if (GetParam() == "KirchhoffSaintVenantPlaneStrain2DLaw") return "LinearElasticPlaneStrain2DLaw";
        return "LinearElasticPlaneStress2DLaw";
    }
    std::shared_ptr<Properties> properties = ElasticProperties(210.0, 0.3);
    std::mt19937 rng{7};
};

TEST_P(KirchhoffSaintVenant, ElementStrainGivesLinearElasticity) {
    auto law = MakeLaw(GetParam());
    auto linear = MakeLaw(LinearName());
    const Vector strain = RandomStrain(*law, rng);
    const auto state = Evaluate(*law, ProvidedStrainState(*properties, strain), Measure::PK2);
    const auto reference = Evaluate(*linear, ProvidedStrainState(*properties, strain), Measure::PK2);
    EXPECT_LT(RelativeError(state.stress_vector, reference.stress_vector), 1e-15);
    EXPECT_LT(RelativeError(state.constitutive_matrix, reference.constitutive_matrix), 1e-15);
}

TEST_P(KirchhoffSaintVenant, PlaneAndSolidStressIsLameForm) {
    if (GetParam() == "KirchhoffSaintVenantPlaneStress2DLaw") GTEST_SKIP() << "plane stress is not λ tr E I + 2μ E";
    auto law = MakeLaw(GetParam());
    const double lambda = 210.0 * 0.3 / (1.3 * 0.4), mu = 210.0 / 2.6;
    const Matrix F = RandomDeformationGradient(*law, rng);
    const Matrix E = 0.5 * (F.transpose() * F - Matrix::Identity(F.rows(), F.cols()));
    const Matrix S = lambda * E.trace() * Matrix::Identity(F.rows(), F.cols()) + 2.0 * mu * E;
    const auto state = Evaluate(*law, KinematicState(*properties, F), Measure::PK2);
    EXPECT_LT(RelativeError(StressTensor(state.stress_vector), S), 1e-14);
}

TEST_P(KirchhoffSaintVenant, SpatialStressIsThePushForward) {
    auto law = MakeLaw(GetParam());
    const Matrix F = RandomDeformationGradient(*law, rng);
    const auto pk2 = Evaluate(*law, KinematicState(*properties, F), Measure::PK2);
    const Matrix tau = F * StressTensor(pk2.stress_vector) * F.transpose();
    const auto kirchhoff = Evaluate(*law, KinematicState(*properties, F), Measure::Kirchhoff);
    const auto cauchy = Evaluate(*law, KinematicState(*properties, F), Measure::Cauchy);
    EXPECT_LT(RelativeError(StressTensor(kirchhoff.stress_vector), tau), 1e-14);
    EXPECT_LT(RelativeError(StressTensor(cauchy.stress_vector), tau / F.determinant()), 1e-14);
    EXPECT_LT(RelativeError(cauchy.constitutive_matrix * F.determinant(), kirchhoff.constitutive_matrix), 1e-14);
    // Almansi e = F⁻ᵀ E F⁻¹ is written for spatial measures.
    const Matrix E = 0.5 * (F.transpose() * F - Matrix::Identity(F.rows(), F.cols()));
    const Matrix F_inv = F.inverse();
    EXPECT_LT(RelativeError(kirchhoff.strain_vector, StrainVoigt(F_inv.transpose() * E * F_inv, law->GetStrainSize())),
              1e-13);
}

TEST_P(KirchhoffSaintVenant, CauchyOfInvertedDeformationIsAnInvertedElementError) {
    auto law = MakeLaw(GetParam());
    const int dim = TensorDimension(*law);
    Matrix F = Matrix::Identity(dim, dim);
    F(1, 1) = -0.5;
    EXPECT_THROW(Evaluate(*law, KinematicState(*properties, F), Measure::Cauchy), InvertedElementError);
    EXPECT_NO_THROW(Evaluate(*law, KinematicState(*properties, F), Measure::PK2));  // S = D E needs no J
    EXPECT_THROW(Evaluate(*law, KinematicState(*properties, F), Measure::PK1), ConfigurationError);
}

INSTANTIATE_TEST_SUITE_P(Structural, KirchhoffSaintVenant,
                         ::testing::Values("KirchhoffSaintVenant3DLaw", "KirchhoffSaintVenantPlaneStrain2DLaw",
                                           "KirchhoffSaintVenantPlaneStress2DLaw"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace contact_app::testing
