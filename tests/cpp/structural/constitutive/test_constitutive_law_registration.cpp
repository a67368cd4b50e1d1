// SPDX-License-Identifier: BSD-3-Clause
// Every registered constitutive law: sizes, tangent = FD of the stress, energy derivative = stress, Check messages.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "contact_app/kernel/geometries/geometry_factory.h"
#include "contact_app/kernel/process_info.h"
#include "law_test_utilities.h"

namespace contact_app::testing {
namespace {

/// What each registered law must be; a registered name without a row fails every test.
struct LawTraits {
    const char* name;
    int dimension;
    int strain_size;
    bool reads_element_strain;  // PK2 uses Parameters::strain_vector when the element provides it
    bool finite_strain;         // Kirchhoff/Cauchy are true spatial quantities (objective)
};

constexpr LawTraits kLawTable[] = {
    {"LinearElastic3DLaw", 3, 6, true, false},
    {"LinearElasticPlaneStrain2DLaw", 2, 3, true, false},
    {"LinearElasticPlaneStress2DLaw", 2, 3, true, false},
    {"LinearElasticAxisym2DLaw", 2, 4, true, false},
    {"HyperElastic3DLaw", 3, 6, false, true},
    {"HyperElasticPlaneStrain2DLaw", 2, 3, false, true},
    {"KirchhoffSaintVenant3DLaw", 3, 6, true, true},
    {"KirchhoffSaintVenantPlaneStrain2DLaw", 2, 3, true, true},
    {"KirchhoffSaintVenantPlaneStress2DLaw", 2, 3, true, true},
};

std::vector<std::string> RegisteredLawNames() {
    RegisterConstitutiveLaws();
    return Registry<ConstitutiveLaw>::Instance().Names();
}

constexpr double kStep = 1e-6;
constexpr double kTolerance = 1e-6;

class RegisteredLaw : public ::testing::TestWithParam<std::string> {
protected:
    void SetUp() override {
        for (const auto& row : kLawTable)
            if (GetParam() == row.name) traits = &row;
        ASSERT_NE(traits, nullptr) << GetParam() << " is registered but has no row in kLawTable";
        law = MakeLaw(GetParam());
        properties = ElasticProperties(210.0, 0.3);
    }
    /// The F components a perturbation may touch (axisymmetric F has no θ coupling).
    std::vector<std::pair<int, int>> Directions() const {
        std::vector<std::pair<int, int>> directions;
        const int dim = TensorDimension(*law);
        for (int i = 0; i < dim; ++i)
            for (int j = 0; j < dim; ++j)
                if (traits->strain_size != 4 || (i < 2 && j < 2) || (i == 2 && j == 2)) directions.emplace_back(i, j);
        return directions;
    }
    Vector StressAt(const Matrix& F, Measure measure) {
        return Evaluate(*law, KinematicState(*properties, F), measure).stress_vector;
    }
    const LawTraits* traits = nullptr;
    ConstitutiveLaw::Pointer law;
    std::shared_ptr<Properties> properties;
    std::mt19937 rng{20240611};
};

TEST_P(RegisteredLaw, SizesMatchTheTable) {
    EXPECT_EQ(law->WorkingSpaceDimension(), traits->dimension);
    EXPECT_EQ(law->GetStrainSize(), traits->strain_size);
    EXPECT_EQ(law->Info(), GetParam());
    const auto copy = law->Clone();
    EXPECT_NE(copy.get(), law.get());
    EXPECT_EQ(copy->Info(), GetParam());
}

TEST_P(RegisteredLaw, TangentIsFdOfStressWrtElementStrain) {
    if (!traits->reads_element_strain) GTEST_SKIP() << GetParam() << " computes its stress from F only";
    for (int sample = 0; sample < 3; ++sample) {
        const Vector strain = RandomStrain(*law, rng);
        const auto state = Evaluate(*law, ProvidedStrainState(*properties, strain), Measure::PK2);
        EXPECT_TRUE(state.strain_vector.isApprox(strain)) << "an element-provided strain must not be overwritten";
        Matrix fd(strain.size(), strain.size());
        for (Eigen::Index b = 0; b < strain.size(); ++b) {
            Vector plus = strain, minus = strain;
            plus[b] += kStep;
            minus[b] -= kStep;
            fd.col(b) = (Evaluate(*law, ProvidedStrainState(*properties, plus), Measure::PK2).stress_vector -
                         Evaluate(*law, ProvidedStrainState(*properties, minus), Measure::PK2).stress_vector) /
                        (2.0 * kStep);
        }
        EXPECT_LT(RelativeError(state.constitutive_matrix, fd), kTolerance);
    }
}

TEST_P(RegisteredLaw, TangentIsFdOfStressWrtFMappedThroughE) {
    // dS = D dE for every perturbation dF: D·(FD of E) = FD of S. Linear laws: every measure is S = D E(F).
    std::vector<Measure> measures{Measure::PK2};
    if (!traits->finite_strain) measures = {Measure::PK1, Measure::PK2, Measure::Kirchhoff, Measure::Cauchy};
    for (const Measure measure : measures) {
        for (int sample = 0; sample < 3; ++sample) {
            const Matrix F = RandomDeformationGradient(*law, rng);
            const auto state = Evaluate(*law, KinematicState(*properties, F), measure);
            Matrix dE(traits->strain_size, 0), dS(traits->strain_size, 0);
            for (const auto& [i, j] : Directions()) {
                Matrix plus = F, minus = F;
                plus(i, j) += kStep;
                minus(i, j) -= kStep;
                dE.conservativeResize(Eigen::NoChange, dE.cols() + 1);
                dS.conservativeResize(Eigen::NoChange, dS.cols() + 1);
                dE.rightCols(1) = (GreenLagrangeVoigt(plus, traits->strain_size) -
                                   GreenLagrangeVoigt(minus, traits->strain_size)) / (2.0 * kStep);
                dS.rightCols(1) = (StressAt(plus, measure) - StressAt(minus, measure)) / (2.0 * kStep);
            }
            EXPECT_LT(RelativeError(state.constitutive_matrix * dE, dS), kTolerance) << "measure " << int(measure);
        }
    }
}

TEST_P(RegisteredLaw, SpatialTangentIsTheLieDerivativeOfKirchhoffStress) {
    // Perturb F(δ) = (I + δ l) F: (dτ/dδ − l τ − τ lᵀ) = c : sym(l) (Kirchhoff) and = J c_σ : sym(l) (Cauchy).
    if (!traits->finite_strain) GTEST_SKIP() << GetParam() << " returns D ε for every measure (not objective)";
    const int dim = TensorDimension(*law);
    for (const Measure measure : {Measure::Kirchhoff, Measure::Cauchy}) {
        const Matrix F = RandomDeformationGradient(*law, rng);
        const double J = F.determinant();
        const auto state = Evaluate(*law, KinematicState(*properties, F), measure);
        const double to_kirchhoff = measure == Measure::Cauchy ? J : 1.0;
        const Matrix tau = to_kirchhoff * StressTensor(state.stress_vector);
        for (int i = 0; i < dim; ++i) {
            for (int j = 0; j < dim; ++j) {
                Matrix l = Matrix::Zero(dim, dim);
                l(i, j) = 1.0;
                auto kirchhoff_at = [&](double delta) {
                    const Matrix Fd = (Matrix::Identity(dim, dim) + delta * l) * F;
                    return Matrix((measure == Measure::Cauchy ? Fd.determinant() : 1.0) *
                                  StressTensor(StressAt(Fd, measure)));
                };
                const Matrix rate = (kirchhoff_at(kStep) - kirchhoff_at(-kStep)) / (2.0 * kStep);
                const Matrix lie = rate - l * tau - tau * l.transpose();
                const Vector d_voigt = StrainVoigt(0.5 * (l + l.transpose()), traits->strain_size);
                const Vector predicted = to_kirchhoff * state.constitutive_matrix * d_voigt;
                EXPECT_LT(RelativeError(predicted, StressVoigt(lie, traits->strain_size), 1.0), kTolerance)
                    << "measure " << int(measure) << " l(" << i << "," << j << ")";
            }
        }
    }
}

TEST_P(RegisteredLaw, StrainEnergyDerivativeIsTheStress) {
    const Matrix F = RandomDeformationGradient(*law, rng);
    const auto state = Evaluate(*law, KinematicState(*properties, F), Measure::PK2);
    for (const auto& [i, j] : Directions()) {
        Matrix plus = F, minus = F;
        plus(i, j) += kStep;
        minus(i, j) -= kStep;
        auto plus_state = KinematicState(*properties, plus), minus_state = KinematicState(*properties, minus);
        const double dW = (law->CalculateValue(plus_state, STRAIN_ENERGY) -
                           law->CalculateValue(minus_state, STRAIN_ENERGY)) / (2.0 * kStep);
        const Vector dE = (GreenLagrangeVoigt(plus, traits->strain_size) -
                           GreenLagrangeVoigt(minus, traits->strain_size)) / (2.0 * kStep);
        EXPECT_NEAR(dW, state.stress_vector.dot(dE), kTolerance * state.stress_vector.norm() * dE.norm());
    }
    if (!traits->reads_element_strain) return;
    const Vector strain = RandomStrain(*law, rng);
    const Vector stress = Evaluate(*law, ProvidedStrainState(*properties, strain), Measure::PK2).stress_vector;
    for (Eigen::Index a = 0; a < strain.size(); ++a) {
        Vector plus = strain, minus = strain;
        plus[a] += kStep;
        minus[a] -= kStep;
        auto plus_state = ProvidedStrainState(*properties, plus), minus_state = ProvidedStrainState(*properties, minus);
        const double dW = (law->CalculateValue(plus_state, STRAIN_ENERGY) -
                           law->CalculateValue(minus_state, STRAIN_ENERGY)) / (2.0 * kStep);
        EXPECT_NEAR(dW, stress[a], kTolerance * stress.norm());
    }
}

TEST_P(RegisteredLaw, ComputedStrainIsGreenLagrange) {
    const Matrix F = RandomDeformationGradient(*law, rng);
    const auto state = Evaluate(*law, KinematicState(*properties, F), Measure::PK2);
    EXPECT_LT(RelativeError(state.strain_vector, GreenLagrangeVoigt(F, traits->strain_size)), 1e-14);
}

/// The InputError message of law->Check on @p properties, or "" if it passes.
std::string CheckMessage(const ConstitutiveLaw& law, const Properties& properties) {
    const auto geometry = CreateGeometry("Point3D", {std::make_shared<Node>(1, 0.0, 0.0, 0.0)});
    try {
        law.Check(properties, *geometry, ProcessInfo());
    } catch (const InputError& error) {
        return error.what();
    }
    return "";
}

TEST_P(RegisteredLaw, CheckNamesMissingYoungModulus) {
    Properties bad(7);
    bad.SetValue(POISSON_RATIO, 0.3);
    const std::string message = CheckMessage(*law, bad);
    EXPECT_NE(message.find(GetParam()), std::string::npos) << message;
    EXPECT_NE(message.find("properties 7 have no YOUNG_MODULUS"), std::string::npos) << message;
    EXPECT_NE(message.find("fix:"), std::string::npos) << message;
}

TEST_P(RegisteredLaw, CheckRejectsPoissonRatioOneHalf) {
    const std::string message = CheckMessage(*law, *ElasticProperties(210.0, 0.5, 8));
    EXPECT_NE(message.find("properties 8 have POISSON_RATIO = 0.5"), std::string::npos) << message;
    EXPECT_NE(message.find("expected: -0.999 <= POISSON_RATIO <= 0.499"), std::string::npos) << message;
}

TEST_P(RegisteredLaw, CheckRejectsBadValuesAndAcceptsTheLimits) {
    EXPECT_NE(CheckMessage(*law, *ElasticProperties(-1.0, 0.3)).find("YOUNG_MODULUS = -1"), std::string::npos);
    EXPECT_NE(CheckMessage(*law, *ElasticProperties(210.0, -1.0)).find("POISSON_RATIO = -1"), std::string::npos);
    Properties no_poisson(3);
    no_poisson.SetValue(YOUNG_MODULUS, 1.0);
    EXPECT_NE(CheckMessage(*law, no_poisson).find("have no POISSON_RATIO"), std::string::npos);
    auto dense = ElasticProperties(210.0, 0.3);
    dense->SetValue(DENSITY, -2.0);
    EXPECT_NE(CheckMessage(*law, *dense).find("DENSITY = -2"), std::string::npos);
    EXPECT_EQ(CheckMessage(*law, *ElasticProperties(210.0, 0.499)), "");
    EXPECT_EQ(CheckMessage(*law, *ElasticProperties(210.0, -0.999)), "");
}

TEST_P(RegisteredLaw, MissingPropertyInResponseIsAnInputError) {
    Properties empty(4);
    const Matrix F = Matrix::Identity(TensorDimension(*law), TensorDimension(*law));
    EXPECT_THROW(Evaluate(*law, KinematicState(empty, F), Measure::PK2), InputError);
}

INSTANTIATE_TEST_SUITE_P(ConstitutiveLawRegistration, RegisteredLaw, ::testing::ValuesIn(RegisteredLawNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace contact_app::testing
