// SPDX-License-Identifier: BSD-3-Clause
// SmallDisplacementElement (and its axisymmetric variant): the residual of a strain-based law is linear,
// RHS = −K u with a constant symmetric K.
#include <gtest/gtest.h>

#include "solid_element_test_utilities.h"

namespace contact_app::testing {
namespace {

/// Small-displacement elements × laws that use the element's strain (all but Neo-Hookean).
std::vector<ElementLawCase> LinearCases() {
    std::vector<ElementLawCase> cases;
    for (const ElementLawCase& c : ElementLawCases())
        if (c.element.formulation == Formulation::SmallDisplacement && !HasInexactTangent(c)) cases.push_back(c);
    return cases;
}

class SmallDisplacementTest : public ::testing::TestWithParam<ElementLawCase> {};

TEST_P(SmallDisplacementTest, ResidualIsMinusConstantSymmetricStiffnessTimesDisplacement) {
    const ElementLawCase& c = GetParam();
    SolidTestModel model(c.law);
    Element& element = model.AddSingleElement(c.element);
    element.Initialize(model.GetProcessInfo());
    Matrix K0, K;
    Vector rhs, u;
    element.CalculateLeftHandSide(K0, model.GetProcessInfo());
    ApplyDeformation(model, element, {0.2, 0.5, 0.05, 3});  // kinematics stay on X whatever the mesh motion
    element.CalculateLocalSystem(K, rhs, model.GetProcessInfo());
    element.GetValuesVector(u);
    EXPECT_LT(RelativeError(K, K0), 1e-14);
    EXPECT_LT((K - K.transpose()).norm(), 1e-13 * K.norm());
    EXPECT_LT(RelativeError(rhs, Vector(-K * u)), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(All, SmallDisplacementTest, ::testing::ValuesIn(LinearCases()), CaseName);

}  // namespace
}  // namespace contact_app::testing
