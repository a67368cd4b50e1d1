// SPDX-License-Identifier: BSD-3-Clause
// Compressible Neo-Hookean laws: analytic uniaxial stretch, small-strain limit, measures, errors.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "contact_app/kernel/inverted_element_error.h"
#include "law_test_utilities.h"

namespace contact_app::testing {
namespace {

constexpr double kYoung = 210.0;
constexpr double kPoisson = 0.3;
const double kLambda = kYoung * kPoisson / ((1 + kPoisson) * (1 - 2 * kPoisson));
const double kMu = kYoung / (2 * (1 + kPoisson));

// F = diag(λ1, λ2, λ3): C = diag(λi²), C⁻¹ = diag(1/λi²), J = λ1λ2λ3, so
// S11 = λ ln J / λ1² + μ (1 − 1/λ1²) and the Kirchhoff τ11 = F11 S11 F11 = λ ln J + μ (λ1² − 1).
double AnalyticS11(double l1, double l2, double l3) {
    const double log_j = std::log(l1 * l2 * l3);
    return kLambda * log_j / (l1 * l1) + kMu * (1.0 - 1.0 / (l1 * l1));
}

TEST(HyperElastic3DLaw, UniaxialStretchMatchesAnalyticStress) {
    auto law = MakeLaw("HyperElastic3DLaw");
    const auto properties = ElasticProperties(kYoung, kPoisson);
    const double l1 = 1.3, l2 = 0.9, l3 = 0.95;
    const Matrix F = Eigen::Vector3d(l1, l2, l3).asDiagonal();
    const auto pk2 = Evaluate(*law, KinematicState(*properties, F), Measure::PK2);
    EXPECT_NEAR(pk2.stress_vector[0], AnalyticS11(l1, l2, l3), 1e-12 * kYoung);
    EXPECT_NEAR(pk2.stress_vector[1], AnalyticS11(l2, l1, l3), 1e-12 * kYoung);
    EXPECT_NEAR(pk2.stress_vector.tail<3>().norm(), 0.0, 1e-14);
    const auto cauchy = Evaluate(*law, KinematicState(*properties, F), Measure::Cauchy);
    const double J = l1 * l2 * l3;
    EXPECT_NEAR(cauchy.stress_vector[0], l1 * l1 * AnalyticS11(l1, l2, l3) / J, 1e-12 * kYoung);
    const auto kirchhoff = Evaluate(*law, KinematicState(*properties, F), Measure::Kirchhoff);
    EXPECT_NEAR(kirchhoff.stress_vector[0], kLambda * std::log(J) + kMu * (l1 * l1 - 1.0), 1e-12 * kYoung);
}

TEST(HyperElasticPlaneStrain2DLaw, UniaxialStretchMatchesAnalyticStress) {
    auto law = MakeLaw("HyperElasticPlaneStrain2DLaw");
    const auto properties = ElasticProperties(kYoung, kPoisson);
    const Matrix F = Eigen::Vector2d(1.2, 0.97).asDiagonal();
    const auto pk2 = Evaluate(*law, KinematicState(*properties, F), Measure::PK2);
    EXPECT_NEAR(pk2.stress_vector[0], AnalyticS11(1.2, 0.97, 1.0), 1e-12 * kYoung);
    EXPECT_NEAR(pk2.stress_vector[2], 0.0, 1e-14);
    // W with the implicit C33 = 1: λ/2 ln²J − μ ln J + μ/2 (λ1² + λ2² + 1 − 3).
    auto values = KinematicState(*properties, F);
    const double log_j = std::log(1.2 * 0.97);
    const double energy = 0.5 * kLambda * log_j * log_j - kMu * log_j + 0.5 * kMu * (1.44 + 0.97 * 0.97 - 2.0);
    EXPECT_NEAR(law->CalculateValue(values, STRAIN_ENERGY), energy, 1e-13 * kYoung);
}

class NeoHookean : public ::testing::TestWithParam<std::string> {};

TEST_P(NeoHookean, SmallStrainLimitIsLinearElasticity) {
    auto law = MakeLaw(GetParam());
    const std::string linear = GetParam() == "HyperElastic3DLaw" ? "LinearElastic3DLaw" : "LinearElasticPlaneStrain2DLaw";
    const auto properties = ElasticProperties(kYoung, kPoisson);
    const int dim = TensorDimension(*law);
    const Matrix I = Matrix::Identity(dim, dim);
    const auto state = Evaluate(*law, KinematicState(*properties, I), Measure::PK2);
    const auto linear_state = Evaluate(*MakeLaw(linear), KinematicState(*properties, I), Measure::PK2);
    EXPECT_LT(RelativeError(state.constitutive_matrix, linear_state.constitutive_matrix), 1e-14);
    EXPECT_NEAR(state.stress_vector.norm(), 0.0, 1e-14);
    auto values = KinematicState(*properties, I);
    EXPECT_NEAR(law->CalculateValue(values, STRAIN_ENERGY), 0.0, 1e-14);
}

TEST_P(NeoHookean, ElementStrainIsIgnoredAndKept) {
    // SmallDisplacement elements pass F_eq = I + ε and their ε: the stress follows F (docs/theory/structural.md §4).
    auto law = MakeLaw(GetParam());
    const auto properties = ElasticProperties(kYoung, kPoisson);
    const int dim = TensorDimension(*law);
    Matrix F = Matrix::Identity(dim, dim);
    F(0, 0) = 1.05;
    auto values = KinematicState(*properties, F);
    values.use_element_provided_strain = true;
    values.strain_vector = Vector::Constant(law->GetStrainSize(), 0.3);
    const auto with_strain = Evaluate(*law, values, Measure::PK2);
    const auto without = Evaluate(*law, KinematicState(*properties, F), Measure::PK2);
    EXPECT_LT(RelativeError(with_strain.stress_vector, without.stress_vector), 1e-15);
    EXPECT_TRUE(with_strain.strain_vector.isApprox(Vector::Constant(law->GetStrainSize(), 0.3)));
}

TEST_P(NeoHookean, SpatialMeasuresWriteTheAlmansiStrain) {
    auto law = MakeLaw(GetParam());
    const auto properties = ElasticProperties(kYoung, kPoisson);
    const int dim = TensorDimension(*law);
    Matrix F = Matrix::Identity(dim, dim);
    F(0, 0) = 2.0;
    const auto state = Evaluate(*law, KinematicState(*properties, F), Measure::Cauchy);
    EXPECT_NEAR(state.strain_vector[0], 0.5 * (1.0 - 0.25), 1e-15);  // e = ½(1 − 1/λ²)
}

TEST_P(NeoHookean, InvertedDeformationIsAnInvertedElementError) {
    auto law = MakeLaw(GetParam());
    const auto properties = ElasticProperties(kYoung, kPoisson);
    const int dim = TensorDimension(*law);
    Matrix F = Matrix::Identity(dim, dim);
    F(0, 0) = -1.0;
    try {
        Evaluate(*law, KinematicState(*properties, F), Measure::PK2);
        FAIL() << "expected an InvertedElementError";
    } catch (const InvertedElementError& error) {
        EXPECT_NE(std::string(error.what()).find("det F = -1"), std::string::npos) << error.what();
        EXPECT_EQ(error.ElementId(), 0u);  // the law does not know its element; BaseSolidElement adds it
        EXPECT_DOUBLE_EQ(error.Value(), -1.0);
    }
}

TEST_P(NeoHookean, Pk1IsAConfigurationError) {
    auto law = MakeLaw(GetParam());
    const auto properties = ElasticProperties(kYoung, kPoisson);
    const int dim = TensorDimension(*law);
    EXPECT_THROW(Evaluate(*law, KinematicState(*properties, Matrix::Identity(dim, dim)), Measure::PK1),
                 ConfigurationError);
}

INSTANTIATE_TEST_SUITE_P(Structural, NeoHookean, ::testing::Values("HyperElastic3DLaw", "HyperElasticPlaneStrain2DLaw"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace contact_app::testing
