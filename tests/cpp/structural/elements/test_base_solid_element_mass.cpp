// SPDX-License-Identifier: BSD-3-Clause
// Mass (consistent, lumped, MASS_FACTOR), Rayleigh damping and body force of every registered solid element.
#include <cmath>

#include <gtest/gtest.h>

#include "contact_app/kernel/geometries/quadrature.h"
#include "contact_app/kernel/properties.h"
#include "solid_element_test_utilities.h"

namespace contact_app::testing {
namespace {

class SolidElementMassTest : public ::testing::TestWithParam<ElementInfo> {
protected:
    SolidElementMassTest() : model(CompatibleLaws(GetParam()).front()), element(model.AddSingleElement(GetParam())) {
        element.Initialize(model.GetProcessInfo());
    }

    /// ∫ dV of the initial configuration: × THICKNESS in 2D, × 2πR in axisymmetry, with Gauss @p order.
    double ReferenceVolume(int order = 5) const {
        const Geometry& geometry = element.GetGeometry();
        Vector N;
        double volume = 0.0;
        for (const IntegrationPoint& point : GaussRule(geometry.Family(), order)) {
            geometry.ShapeFunctionsValues(N, point.local);
            double factor = GetParam().dimension == 2 ? 0.5 : 1.0;  // THICKNESS of SolidTestModel
            if (GetParam().axisymmetric) {
                factor = 0.0;
                for (std::size_t i = 0; i < geometry.PointsNumber(); ++i)
                    factor += 2.0 * M_PI * N[static_cast<Eigen::Index>(i)] * geometry[i].X0();
            }
            volume +=
                point.weight * geometry.DeterminantOfJacobian(point.local, Geometry::Configuration::Initial) * factor;
        }
        return volume;
    }

    /// Σ_ij M[(i,a),(j,b)] for every pair of directions (a, b).
    Matrix DirectionSums(const Matrix& M) const {
        const int d = GetParam().dimension;
        Matrix sums = Matrix::Zero(d, d);
        for (Eigen::Index r = 0; r < M.rows(); ++r)
            for (Eigen::Index c = 0; c < M.cols(); ++c) sums(r % d, c % d) += M(r, c);
        return sums;
    }

    SolidTestModel model;
    Element& element;
};

TEST_P(SolidElementMassTest, ConsistentMassSumsToDensityTimesVolume) {
    ApplyDeformation(model, element, {0.1, 0.3, 0.02, 4});  // the mass lives on the initial configuration
    Matrix M;
    element.CalculateMassMatrix(M, model.GetProcessInfo());
    const double mass = 2.0 * ReferenceVolume();
    EXPECT_LT((DirectionSums(M) - mass * Matrix::Identity(GetParam().dimension, GetParam().dimension)).norm(),
              1e-12 * mass);
    EXPECT_LT((M - M.transpose()).norm(), 1e-14 * M.norm());
}

TEST_P(SolidElementMassTest, LumpedMassIsDiagonalAndSumsToDensityTimesVolume) {
    model.GetProperties().SetValue(COMPUTE_LUMPED_MASS_MATRIX, true);
    Matrix M;
    element.CalculateMassMatrix(M, model.GetProcessInfo());
    const double mass = 2.0 * ReferenceVolume();
    EXPECT_EQ((M - Matrix(M.diagonal().asDiagonal())).norm(), 0.0);
    EXPECT_LT((DirectionSums(M) - mass * Matrix::Identity(GetParam().dimension, GetParam().dimension)).norm(),
              1e-12 * mass);
}

TEST_P(SolidElementMassTest, MassFactorOfElementThenPropertiesScalesMass) {
    Matrix M, scaled;
    element.CalculateMassMatrix(M, model.GetProcessInfo());
    model.GetProperties().SetValue(MASS_FACTOR, 2.0);
    element.CalculateMassMatrix(scaled, model.GetProcessInfo());
    EXPECT_LT((scaled - 2.0 * M).norm(), 1e-14 * M.norm());
    element.SetValue(MASS_FACTOR, 3.0);  // the element's value comes first
    element.CalculateMassMatrix(scaled, model.GetProcessInfo());
    EXPECT_LT((scaled - 3.0 * M).norm(), 1e-14 * M.norm());
}

TEST_P(SolidElementMassTest, MissingDensityIsReported) {
    model.GetProperties().Data().Erase(DENSITY);
    Matrix M;
    ExpectError<InputError>([&] { element.CalculateMassMatrix(M, model.GetProcessInfo()); }, {"DENSITY", "#1"});
}

TEST_P(SolidElementMassTest, RayleighDampingIsAlphaMassPlusBetaStiffness) {
    ApplyDeformation(model, element, {0.05, 0.2, 0.01, 2});
    ProcessInfo& info = model.Part().GetProcessInfo();
    Matrix M, K, C;
    element.CalculateMassMatrix(M, info);
    element.CalculateLeftHandSide(K, info);
    element.CalculateDampingMatrix(C, info);
    EXPECT_EQ(C.norm(), 0.0);  // no coefficients anywhere
    info.SetValue(RAYLEIGH_ALPHA, 0.5);
    element.CalculateDampingMatrix(C, info);
    EXPECT_LT((C - 0.5 * M).norm(), 1e-14 * M.norm());
    model.GetProperties().SetValue(RAYLEIGH_ALPHA, 0.1);  // Properties override the ProcessInfo
    model.GetProperties().SetValue(RAYLEIGH_BETA, 0.02);
    element.CalculateDampingMatrix(C, info);
    const Matrix expected = 0.1 * M + 0.02 * K;
    EXPECT_LT((C - expected).norm(), 1e-14 * expected.norm());
}

TEST_P(SolidElementMassTest, BodyForceResultantIsDensityTimesAccelerationTimesVolume) {
    const Array3 g_properties(0.5, -2.0, 0.25), g_nodal(-0.1, -9.0, 1.0);
    model.GetProperties().SetValue(VOLUME_ACCELERATION, g_properties);
    Geometry& geometry = element.GetGeometry();
    for (std::size_t i = 0; i < geometry.PointsNumber(); ++i)
        geometry[i].GetSolutionStepValue(VOLUME_ACCELERATION) = g_nodal;
    Vector rhs;
    element.CalculateRightHandSide(rhs, model.GetProcessInfo());
    const int d = GetParam().dimension;
    Vector resultant = Vector::Zero(d);
    for (Eigen::Index k = 0; k < rhs.size(); ++k) resultant[k % d] += rhs[k];
    // Integrated with the stiffness rule, not exact for curved Tetrahedra3D10 (det J of degree 3).
    const int order = element.GetGeometry().DefaultIntegrationOrder();
    const Vector expected = 2.0 * ReferenceVolume(order) * (g_properties + g_nodal).head(d);
    EXPECT_LT((resultant - expected).norm(), 1e-12 * expected.norm());
}

INSTANTIATE_TEST_SUITE_P(All, SolidElementMassTest, ::testing::ValuesIn(SolidElements()), ElementName);

}  // namespace
}  // namespace contact_app::testing
