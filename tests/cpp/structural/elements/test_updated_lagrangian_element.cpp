// SPDX-License-Identifier: BSD-3-Clause
// UpdatedLagrangianElement: equals the total-Lagrangian element for hyperelastic laws, keeps the total F
// across steps (stored F0), needs a 2-step buffer and reports an inverted current configuration.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "contact_app/kernel/inverted_element_error.h"
#include "contact_app/kernel/variables.h"
#include "solid_element_test_utilities.h"

namespace contact_app::testing {
namespace {

/// UL elements × hyperelastic laws (Neo-Hookean, Kirchhoff–Saint-Venant), where UL and TL are the same model.
std::vector<ElementLawCase> UpdatedLagrangianHyperelasticCases() {
    std::vector<ElementLawCase> cases;
    for (const ElementLawCase& c : ElementLawCases())
        if (c.element.formulation == Formulation::UpdatedLagrangian && c.law.rfind("LinearElastic", 0) != 0)
            cases.push_back(c);
    return cases;
}

std::string TotalLagrangianName(const std::string& updated) {
    return "TotalLagrangian" + updated.substr(std::string("UpdatedLagrangian").size());
}

/// x = M X on every node of @p element (M 3×3, identity out of plane in 2D).
void SetHomogeneous(SolidTestModel& model, Element& element, const Eigen::Matrix3d& M, std::size_t step = 0) {
    Geometry& geometry = element.GetGeometry();
    for (std::size_t i = 0; i < geometry.PointsNumber(); ++i)
        model.SetDisplacement(geometry[i], Array3((M - Eigen::Matrix3d::Identity()) * geometry[i].InitialCoordinates()),
                              step);
}

Eigen::Matrix3d Stretch(int dimension, double scale, unsigned seed) {
    Eigen::Matrix3d M = Eigen::Matrix3d::Identity();
    for (int a = 0; a < dimension; ++a)
        for (int b = 0; b < dimension; ++b) M(a, b) += scale * std::sin(1.0 + seed + 3 * a + 7 * b);
    return RotationMatrix(dimension, 0.2 * seed) * M;
}

class UpdatedLagrangianTest : public ::testing::TestWithParam<ElementLawCase> {};

TEST_P(UpdatedLagrangianTest, MatchesTotalLagrangianAtTheSameConfiguration) {
    const ElementLawCase& c = GetParam();
    SolidTestModel ul_model(c.law), tl_model(c.law);
    Element& ul = ul_model.AddSingleElement(c.element);
    ElementInfo tl_info = c.element;
    tl_info.name = TotalLagrangianName(c.element.name);
    Element& tl = tl_model.AddSingleElement(tl_info);
    ul.Initialize(ul_model.GetProcessInfo());
    tl.Initialize(tl_model.GetProcessInfo());
    ApplyDeformation(ul_model, ul, {0.1, 0.4, 0.02, 9});
    ApplyDeformation(tl_model, tl, {0.1, 0.4, 0.02, 9});
    Matrix K_ul, K_tl;
    Vector r_ul, r_tl;
    ul.CalculateLocalSystem(K_ul, r_ul, ul_model.GetProcessInfo());
    tl.CalculateLocalSystem(K_tl, r_tl, tl_model.GetProcessInfo());
    EXPECT_LT(RelativeError(r_ul, r_tl), 1e-10);
    EXPECT_LT(RelativeError(K_ul, K_tl), 1e-10);
}

TEST_P(UpdatedLagrangianTest, StoredF0KeepsTheTotalDeformationGradientAcrossSteps) {
    const ElementLawCase& c = GetParam();
    const int d = c.element.dimension;
    SolidTestModel model(c.law);
    Element& element = model.AddSingleElement(c.element);
    ModelPart& part = model.Part();
    element.Initialize(part.GetProcessInfo());
    const auto expect_total_f = [&](const Eigen::Matrix3d& M, const char* when) {
        std::vector<Matrix> F;
        element.CalculateOnIntegrationPoints(DEFORMATION_GRADIENT, F, part.GetProcessInfo());
        for (const Matrix& f : F) EXPECT_LT((f - M.topLeftCorner(d, d)).norm(), 1e-12) << when;
    };
    const Eigen::Matrix3d A = Stretch(d, 0.05, 1), B = Stretch(d, 0.08, 2);
    for (const Eigen::Matrix3d& M : {A, B}) {
        part.CloneTimeStep(part.GetProcessInfo().GetValue(TIME) + 1.0);
        element.InitializeSolutionStep(part.GetProcessInfo());
        SetHomogeneous(model, element, M);
        expect_total_f(M, "during the step");
        element.FinalizeSolutionStep(part.GetProcessInfo());
        expect_total_f(M, "after FinalizeSolutionStep");
    }
    // The residual at the end of step 2 equals the total-Lagrangian one for the same configuration.
    SolidTestModel tl_model(c.law);
    ElementInfo tl_info = c.element;
    tl_info.name = TotalLagrangianName(c.element.name);
    Element& tl = tl_model.AddSingleElement(tl_info);
    tl.Initialize(tl_model.GetProcessInfo());
    SetHomogeneous(tl_model, tl, B);
    Vector r_ul, r_tl;
    element.CalculateRightHandSide(r_ul, part.GetProcessInfo());
    tl.CalculateRightHandSide(r_tl, tl_model.GetProcessInfo());
    EXPECT_LT(RelativeError(r_ul, r_tl), 1e-10);
}

TEST_P(UpdatedLagrangianTest, InvertedCurrentConfigurationIsAnInvertedElementError) {
    const ElementLawCase& c = GetParam();
    SolidTestModel model(c.law);
    Element& element = model.AddSingleElement(c.element);
    element.Initialize(model.GetProcessInfo());
    Eigen::Matrix3d mirror = Eigen::Matrix3d::Identity();
    mirror(0, 0) = -1.0;
    SetHomogeneous(model, element, mirror);
    model.Part().GetProcessInfo().SetValue(TIME, 0.25);
    Vector rhs;
    // A ConvergenceError (the iteration fails, not the run) that carries the element, det J and TIME.
    ExpectError<ConvergenceError>(
        [&] { element.CalculateRightHandSide(rhs, model.GetProcessInfo()); },
        {"inverted in the current configuration", "#1", "(TIME = 0.25)", "smaller increments"});
    try {
        element.CalculateRightHandSide(rhs, model.GetProcessInfo());
        FAIL() << "expected an InvertedElementError";
    } catch (const InvertedElementError& error) {
        EXPECT_EQ(error.ElementId(), 1u);
        EXPECT_EQ(error.Quantity(), "det J");
        EXPECT_LT(error.Value(), 0.0);
        EXPECT_DOUBLE_EQ(error.Time(), 0.25);
    }
}

TEST_P(UpdatedLagrangianTest, SingleStepBufferIsReported) {
    const ElementLawCase& c = GetParam();
    SolidTestModel model(c.law, /*buffer_size=*/1);
    Element& element = model.AddSingleElement(c.element);
    ExpectError<InputError>([&] { element.Check(model.GetProcessInfo()); }, {"buffer", "#1"});
    ExpectError<InputError>([&] { element.Initialize(model.GetProcessInfo()); }, {"buffer size >= 2"});
}

INSTANTIATE_TEST_SUITE_P(All, UpdatedLagrangianTest, ::testing::ValuesIn(UpdatedLagrangianHyperelasticCases()),
                         CaseName);

}  // namespace
}  // namespace contact_app::testing
