// SPDX-License-Identifier: BSD-3-Clause
// Finite-strain elements (TotalLagrangian, UpdatedLagrangian, AxisymTotalLagrangian): at rest their tangent is
// the small-displacement stiffness of the same geometry, so they linearise to the small-displacement element.
#include <gtest/gtest.h>

#include "contact_app/kernel/inverted_element_error.h"
#include "contact_app/kernel/variables.h"
#include "solid_element_test_utilities.h"

namespace contact_app::testing {
namespace {

std::vector<ElementLawCase> FiniteStrainCases() {
    std::vector<ElementLawCase> cases;
    for (const ElementLawCase& c : ElementLawCases())
        if (c.element.formulation != Formulation::SmallDisplacement) cases.push_back(c);
    return cases;
}

/// The small-displacement element of the same family and size, e.g. AxisymTotalLagrangianElement2D4N →
/// AxisymSmallDisplacementElement2D4N.
ElementInfo SmallDisplacementCounterpart(const ElementInfo& element) {
    for (const ElementInfo& candidate : SolidElements())
        if (candidate.formulation == Formulation::SmallDisplacement && candidate.geometry == element.geometry &&
            candidate.axisymmetric == element.axisymmetric)
            return candidate;
    ADD_FAILURE() << "no small-displacement counterpart of " << element.name;
    return element;
}

class FiniteStrainTest : public ::testing::TestWithParam<ElementLawCase> {};

TEST_P(FiniteStrainTest, TangentAtRestEqualsSmallDisplacementStiffness) {
    const ElementLawCase& c = GetParam();
    SolidTestModel finite_model(c.law), small_model(c.law);
    Element& finite = finite_model.AddSingleElement(c.element);
    Element& small = small_model.AddSingleElement(SmallDisplacementCounterpart(c.element));
    finite.Initialize(finite_model.GetProcessInfo());
    small.Initialize(small_model.GetProcessInfo());
    Matrix K_finite, K_small;
    finite.CalculateLeftHandSide(K_finite, finite_model.GetProcessInfo());
    small.CalculateLeftHandSide(K_small, small_model.GetProcessInfo());
    EXPECT_LT(RelativeError(K_finite, K_small), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(All, FiniteStrainTest, ::testing::ValuesIn(FiniteStrainCases()), CaseName);

/// Total-Lagrangian elements with a Neo-Hookean law, whose ln J needs det F > 0.
std::vector<ElementLawCase> TotalLagrangianHyperElasticCases() {
    std::vector<ElementLawCase> cases;
    for (const ElementLawCase& c : ElementLawCases())
        if (c.element.formulation == Formulation::TotalLagrangian && !c.element.axisymmetric &&
            c.law.rfind("HyperElastic", 0) == 0)
            cases.push_back(c);
    return cases;
}

class InvertedLawTest : public ::testing::TestWithParam<ElementLawCase> {};

// The law meets det F = -1; the element that evaluated it adds its id and TIME to the InvertedElementError.
TEST_P(InvertedLawTest, LawErrorIsLocatedByTheElement) {
    const ElementLawCase& c = GetParam();
    SolidTestModel model(c.law);
    Element& element = model.AddSingleElement(c.element, 7);
    element.Initialize(model.GetProcessInfo());
    Geometry& geometry = element.GetGeometry();
    for (std::size_t i = 0; i < geometry.PointsNumber(); ++i)  // x = -X: det F = -1
        model.SetDisplacement(geometry[i], Array3(-2.0 * geometry[i].InitialCoordinates()[0], 0.0, 0.0));
    model.Part().GetProcessInfo().SetValue(TIME, 1.5);
    Vector rhs;
    try {
        element.CalculateRightHandSide(rhs, model.GetProcessInfo());
        FAIL() << "expected an InvertedElementError";
    } catch (const InvertedElementError& error) {
        EXPECT_EQ(error.ElementId(), 7u);
        EXPECT_EQ(error.Quantity(), "det F");
        EXPECT_NEAR(error.Value(), -1.0, 1e-12);
        EXPECT_DOUBLE_EQ(error.Time(), 1.5);
        const std::string message = error.what();
        for (const char* part : {"#7", "det F = -1", "(TIME = 1.5)", "step cutting"})
            EXPECT_NE(message.find(part), std::string::npos) << message;
    }
}

INSTANTIATE_TEST_SUITE_P(All, InvertedLawTest, ::testing::ValuesIn(TotalLagrangianHyperElasticCases()), CaseName);

}  // namespace
}  // namespace contact_app::testing
