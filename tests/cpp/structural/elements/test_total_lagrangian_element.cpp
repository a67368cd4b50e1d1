// SPDX-License-Identifier: BSD-3-Clause
// Finite-strain elements (TotalLagrangian, UpdatedLagrangian, AxisymTotalLagrangian): at rest their tangent is
// the small-displacement stiffness of the same geometry, so they linearise to the small-displacement element.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace contact_app::testing
