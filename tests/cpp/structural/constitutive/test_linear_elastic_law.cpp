// SPDX-License-Identifier: BSD-3-Clause
// Linear elastic laws: hand D matrices, one σ = D ε for every measure, strain from F, energy, size errors.
#include <gtest/gtest.h>

#include <string>

#include "law_test_utilities.h"

namespace contact_app::testing {
namespace {

// E = 200, ν = 0.25: c = E/((1+ν)(1−2ν)) = 320, c(1−ν) = 240, cν = 80, μ = c(1−2ν)/2 = 80;
// plane stress E/(1−ν²) = 640/3, times ν = 160/3, shear E/(2(1+ν)) = 80.
Matrix HandMatrix(const std::string& name) {
    if (name == "LinearElastic3DLaw")
        return (Matrix(6, 6) << 240, 80, 80, 0, 0, 0, 80, 240, 80, 0, 0, 0, 80, 80, 240, 0, 0, 0, 0, 0, 0, 80, 0, 0,
                0, 0, 0, 0, 80, 0, 0, 0, 0, 0, 0, 80).finished();
    if (name == "LinearElasticPlaneStrain2DLaw") return (Matrix(3, 3) << 240, 80, 0, 80, 240, 0, 0, 0, 80).finished();
    if (name == "LinearElasticPlaneStress2DLaw")
        return (Matrix(3, 3) << 640.0 / 3, 160.0 / 3, 0, 160.0 / 3, 640.0 / 3, 0, 0, 0, 80).finished();
    return (Matrix(4, 4) << 240, 80, 80, 0, 80, 240, 80, 0, 80, 80, 240, 0, 0, 0, 0, 80).finished();  // axisym
}

class LinearElasticLaw : public ::testing::TestWithParam<std::string> {};

TEST_P(LinearElasticLaw, TangentIsTheHandMatrixAndEveryMeasureGivesDEpsilon) {
    auto law = MakeLaw(GetParam());
    const auto properties = ElasticProperties(200.0, 0.25);
    const Matrix D = HandMatrix(GetParam());
    const Vector strain = Vector::LinSpaced(law->GetStrainSize(), 0.01, -0.02);
    for (const Measure measure : {Measure::PK1, Measure::PK2, Measure::Kirchhoff, Measure::Cauchy}) {
        const auto state = Evaluate(*law, ProvidedStrainState(*properties, strain), measure);
        EXPECT_LT(RelativeError(state.constitutive_matrix, D), 1e-14) << int(measure);
        EXPECT_LT(RelativeError(state.stress_vector, D * strain), 1e-14) << int(measure);
    }
}

TEST_P(LinearElasticLaw, StrainFromFIsGreenLagrangeForEveryMeasure) {
    auto law = MakeLaw(GetParam());
    const auto properties = ElasticProperties(200.0, 0.25);
    const int dim = TensorDimension(*law);
    Matrix F = Matrix::Identity(dim, dim);
    F(0, 1) = 0.1;
    if (dim == 3) F(2, 2) = 1.2;  // axisymmetric hoop stretch: E_θθ = ½(1.44 − 1) = 0.22
    const Vector expected = GreenLagrangeVoigt(F, law->GetStrainSize());
    EXPECT_NEAR(expected[1], 0.005, 1e-15);  // E_yy = ½ F01²
    for (const Measure measure : {Measure::PK2, Measure::Cauchy}) {
        const auto state = Evaluate(*law, KinematicState(*properties, F), measure);
        EXPECT_LT(RelativeError(state.strain_vector, expected), 1e-14);
        EXPECT_LT(RelativeError(state.stress_vector, HandMatrix(GetParam()) * expected), 1e-14);
    }
}

TEST_P(LinearElasticLaw, FlagsSelectTheOutputs) {
    auto law = MakeLaw(GetParam());
    const auto properties = ElasticProperties(200.0, 0.25);
    auto values = ProvidedStrainState(*properties, Vector::Ones(law->GetStrainSize()));
    values.compute_constitutive_tensor = false;
    law->CalculateMaterialResponse(values, Measure::PK2);
    EXPECT_EQ(values.constitutive_matrix.size(), 0);
    EXPECT_EQ(values.stress_vector.size(), law->GetStrainSize());
}

TEST_P(LinearElasticLaw, StrainEnergyIsHalfEpsilonDEpsilon) {
    auto law = MakeLaw(GetParam());
    const auto properties = ElasticProperties(200.0, 0.25);
    Vector strain = Vector::Zero(law->GetStrainSize());
    strain[0] = 0.01;
    strain[strain.size() - 1] = 0.02;  // a shear strain γ
    auto values = ProvidedStrainState(*properties, strain);
    // ½(240·0.01² + 80·0.02²) for the solid D's and 80 shear; plane stress has D₀₀ = 640/3.
    const double d00 = GetParam() == "LinearElasticPlaneStress2DLaw" ? 640.0 / 3 : 240.0;
    EXPECT_NEAR(law->CalculateValue(values, STRAIN_ENERGY), 0.5 * (d00 * 1e-4 + 80.0 * 4e-4), 1e-15);
    EXPECT_EQ(law->CalculateValue(values, VON_MISES_STRESS), 0.0);
}

TEST_P(LinearElasticLaw, WrongStrainSizeIsAnInputError) {
    auto law = MakeLaw(GetParam());
    const auto properties = ElasticProperties();
    try {
        Evaluate(*law, ProvidedStrainState(*properties, Vector::Zero(5)), Measure::PK2);
        FAIL() << "expected an InputError";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("strain vector of size 5"), std::string::npos) << error.what();
    }
}

INSTANTIATE_TEST_SUITE_P(Structural, LinearElasticLaw,
                         ::testing::Values("LinearElastic3DLaw", "LinearElasticPlaneStrain2DLaw",
                                           "LinearElasticPlaneStress2DLaw", "LinearElasticAxisym2DLaw"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(LinearElasticAxisym2DLaw, TwoByTwoFHasUnitHoopStretch) {
    auto law = MakeLaw("LinearElasticAxisym2DLaw");
    const auto properties = ElasticProperties(200.0, 0.25);
    Matrix F = Matrix::Identity(2, 2);
    F(0, 0) = 1.1;
    const auto state = Evaluate(*law, KinematicState(*properties, F), Measure::PK2);
    EXPECT_NEAR(state.strain_vector[0], 0.105, 1e-15);
    EXPECT_EQ(state.strain_vector[2], 0.0);
}

TEST(LinearElastic3DLaw, TwoByTwoFIsAnInputError) {
    auto law = MakeLaw("LinearElastic3DLaw");
    const auto properties = ElasticProperties();
    EXPECT_THROW(Evaluate(*law, KinematicState(*properties, Matrix::Identity(2, 2)), Measure::PK2), InputError);
}

}  // namespace
}  // namespace contact_app::testing
