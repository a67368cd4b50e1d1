// SPDX-License-Identifier: BSD-3-Clause
// Integration-point results of every registered solid element × compatible law under a homogeneous
// deformation: F, strain, PK2/Cauchy stress (vectors and tensors), von Mises stress and strain energy.
#include <cmath>

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "contact_app/kernel/registry.h"
#include "solid_element_test_utilities.h"

namespace contact_app::testing {
namespace {

using StressMeasure = ConstitutiveLaw::StressMeasure;

class SolidElementResultsTest : public ::testing::TestWithParam<ElementLawCase> {
protected:
    SolidElementResultsTest() : model(GetParam().law), element(model.AddSingleElement(GetParam().element)) {
        element.Initialize(model.GetProcessInfo());
        const int d = GetParam().element.dimension;
        // Homogeneous map x = F3 X (axisymmetric: a diagonal stretch, so that F_θθ = r/R = F3(0,0)).
        Eigen::Matrix3d H;
        H << 0.08, 0.03, -0.02, -0.05, -0.06, 0.04, 0.02, 0.01, 0.05;
        if (GetParam().element.axisymmetric) {
            F3 = Eigen::Matrix3d::Identity() + Eigen::Matrix3d(H.diagonal().asDiagonal());
            F3(2, 2) = F3(0, 0);
        } else {
            F3 = RotationMatrix(d, 0.4) * (Eigen::Matrix3d::Identity() + H);
            if (d == 2) F3.row(2) = F3.col(2) = Eigen::Vector3d::UnitZ();
        }
        Geometry& geometry = element.GetGeometry();
        for (std::size_t i = 0; i < geometry.PointsNumber(); ++i) {
            const Array3& X = geometry[i].InitialCoordinates();
            model.SetDisplacement(geometry[i], Array3((F3 - Eigen::Matrix3d::Identity()) * X));
        }
    }

    bool Small() const { return GetParam().element.formulation == Formulation::SmallDisplacement; }
    int FSize() const { return GetParam().element.axisymmetric ? 3 : GetParam().element.dimension; }
    /// The strain the element reports and the F it hands to the law.
    Vector ExpectedStrain() const {
        const Eigen::Matrix3d E = Small() ? Eigen::Matrix3d(0.5 * (F3 + F3.transpose()) - Eigen::Matrix3d::Identity())
                                          : Eigen::Matrix3d(0.5 * (F3.transpose() * F3 - Eigen::Matrix3d::Identity()));
        return ToVoigt(E, true);
    }
    Matrix ExpectedF() const {
        const Eigen::Matrix3d E = Small() ? Eigen::Matrix3d(0.5 * (F3 + F3.transpose())) : F3;
        return E.topLeftCorner(FSize(), FSize());
    }
    Vector Expected(StressMeasure measure) const {
        return LawStress(GetParam().law, *model.pGetProperties(), ExpectedF(), ExpectedStrain(),
                         Small() || GetParam().element.axisymmetric, measure);
    }
    Vector ToVoigt(const Eigen::Matrix3d& t, bool engineering) const {
        const double s = engineering ? 2.0 : 1.0;
        switch (GetParam().element.strain_size) {
            case 3:
                return Eigen::Vector3d(t(0, 0), t(1, 1), s * t(0, 1));
            case 4:
                return Eigen::Vector4d(t(0, 0), t(1, 1), t(2, 2), s * t(0, 1));
            default: {
                Vector v(6);
                v << t(0, 0), t(1, 1), t(2, 2), s * t(0, 1), s * t(1, 2), s * t(0, 2);
                return v;
            }
        }
    }
    template <class T>
    std::vector<T> Results(const Variable<T>& variable) {
        std::vector<T> values;
        element.CalculateOnIntegrationPoints(variable, values, model.GetProcessInfo());
        EXPECT_EQ(values.size(),
                  element.GetGeometry().IntegrationPoints(element.GetGeometry().DefaultIntegrationOrder()).size());
        return values;
    }

    SolidTestModel model;
    Element& element;
    Eigen::Matrix3d F3;
};

TEST_P(SolidElementResultsTest, DeformationGradientAndStrainAreTheHomogeneousOnes) {
    for (const Matrix& F : Results(DEFORMATION_GRADIENT)) EXPECT_LT((F - ExpectedF()).norm(), 1e-12);
    for (const Vector& strain : Results(GREEN_LAGRANGE_STRAIN_VECTOR))
        EXPECT_LT((strain - ExpectedStrain()).norm(), 1e-12);
}

TEST_P(SolidElementResultsTest, StressVectorsAndTensorsMatchTheLaw) {
    const Vector pk2 = Expected(StressMeasure::PK2), cauchy = Expected(StressMeasure::Cauchy);
    for (const Vector& s : Results(PK2_STRESS_VECTOR)) EXPECT_LT((s - pk2).norm(), 1e-10 * pk2.norm());
    for (const Vector& s : Results(CAUCHY_STRESS_VECTOR)) EXPECT_LT((s - cauchy).norm(), 1e-10 * cauchy.norm());
    const auto to_voigt = [&](const Matrix& t) {
        Eigen::Matrix3d full = Eigen::Matrix3d::Zero();
        full.topLeftCorner(t.rows(), t.cols()) = t;
        return ToVoigt(full, false);
    };
    for (const Matrix& t : Results(PK2_STRESS_TENSOR)) {
        EXPECT_EQ(t.rows(), FSize());
        EXPECT_LT((to_voigt(t) - pk2).norm(), 1e-10 * pk2.norm());
    }
    for (const Matrix& t : Results(CAUCHY_STRESS_TENSOR))
        EXPECT_LT((to_voigt(t) - cauchy).norm(), 1e-10 * cauchy.norm());
}

/// Finite-strain elements × hyperelastic laws, for which σ = F S Fᵀ / J.
class PushForwardTest : public SolidElementResultsTest {};

std::vector<ElementLawCase> FiniteStrainHyperelasticCases() {
    std::vector<ElementLawCase> cases;
    for (const ElementLawCase& c : ElementLawCases())
        if (c.element.formulation != Formulation::SmallDisplacement && c.law.rfind("LinearElastic", 0) != 0)
            cases.push_back(c);
    return cases;
}

TEST_P(PushForwardTest, CauchyIsPushForwardOfPK2) {
    const std::vector<Matrix> F = Results(DEFORMATION_GRADIENT), S = Results(PK2_STRESS_TENSOR),
                              sigma = Results(CAUCHY_STRESS_TENSOR);
    for (std::size_t g = 0; g < F.size(); ++g) {
        const Matrix push = F[g] * S[g] * F[g].transpose() / F[g].determinant();
        EXPECT_LT((push - sigma[g]).norm(), 1e-10 * sigma[g].norm());
    }
}

TEST_P(SolidElementResultsTest, VonMisesAndStrainEnergyAreConsistent) {
    const std::vector<Matrix> sigma = Results(CAUCHY_STRESS_TENSOR);
    const std::vector<double> von_mises = Results(VON_MISES_STRESS), energy = Results(STRAIN_ENERGY);
    for (std::size_t g = 0; g < sigma.size(); ++g) {
        Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
        s.topLeftCorner(sigma[g].rows(), sigma[g].cols()) = sigma[g];
        const double expected = std::sqrt(
            0.5 * (std::pow(s(0, 0) - s(1, 1), 2) + std::pow(s(1, 1) - s(2, 2), 2) + std::pow(s(2, 2) - s(0, 0), 2)) +
            3.0 * (s(0, 1) * s(0, 1) + s(1, 2) * s(1, 2) + s(0, 2) * s(0, 2)));
        EXPECT_NEAR(von_mises[g], expected, 1e-10 * expected);
        EXPECT_GT(energy[g], 0.0);
    }
    for (std::size_t i = 0; i < element.GetGeometry().PointsNumber(); ++i)
        model.SetDisplacement(element.GetGeometry()[i], Array3::Zero());
    for (const double w : Results(STRAIN_ENERGY)) EXPECT_NEAR(w, 0.0, 1e-12);  // E = 200: round-off of tr C − 3
}

INSTANTIATE_TEST_SUITE_P(All, SolidElementResultsTest, ::testing::ValuesIn(ElementLawCases()), CaseName);
INSTANTIATE_TEST_SUITE_P(All, PushForwardTest, ::testing::ValuesIn(FiniteStrainHyperelasticCases()), CaseName);

}  // namespace
}  // namespace contact_app::testing
