// SPDX-License-Identifier: BSD-3-Clause
// SmallDisplacementElement (and its axisymmetric variant): the residual of a strain-based law is linear,
// RHS = −K u with a constant symmetric K.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "contact_app/kernel/registry.h"
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

/// The wrapped law with IsLinear() false: the element then integrates the law at every evaluation.
class UndeclaredLinearLaw : public ConstitutiveLaw {
public:
    explicit UndeclaredLinearLaw(Pointer law) : mLaw(std::move(law)) {}
    Pointer Clone() const override { return std::make_shared<UndeclaredLinearLaw>(mLaw->Clone()); }
    int WorkingSpaceDimension() const override { return mLaw->WorkingSpaceDimension(); }
    int GetStrainSize() const override { return mLaw->GetStrainSize(); }
    void CalculateMaterialResponse(Parameters& rValues, StressMeasure measure) override {
        mLaw->CalculateMaterialResponse(rValues, measure);
    }
    std::string Info() const override { return "Undeclared" + mLaw->Info(); }

private:
    Pointer mLaw;
};

/// Small-displacement elements × the linear elastic laws (those that declare IsLinear).
std::vector<ElementLawCase> KeptStiffnessCases() {
    std::vector<ElementLawCase> cases;
    for (const ElementLawCase& c : LinearCases())
        if (Registry<ConstitutiveLaw>::Instance().Get(c.law).IsLinear()) cases.push_back(c);
    return cases;
}

class KeptStiffnessTest : public ::testing::TestWithParam<ElementLawCase> {};

TEST_P(KeptStiffnessTest, LocalSystemEqualsTheLawIntegralWithBodyForces) {
    const ElementLawCase& c = GetParam();
    SolidTestModel model(c.law);
    Element& element = model.AddSingleElement(c.element);
    model.GetProperties().SetValue(VOLUME_ACCELERATION, Array3(0.5, -9.81, 0.25));
    for (std::size_t i = 0; i < element.GetGeometry().PointsNumber(); ++i)
        element.GetGeometry()[i].GetSolutionStepValue(VOLUME_ACCELERATION) = Array3(0.3, -1.0, 0.7 * i);
    element.Initialize(model.GetProcessInfo());
    EXPECT_EQ(element.WhyStiffnessVaries(), "");
    ApplyDeformation(model, element, {0.2, 0.5, 0.05, 7});
    Matrix kept_lhs, lhs, lhs_only;
    Vector kept_rhs, rhs, rhs_only;
    element.CalculateLocalSystem(kept_lhs, kept_rhs, model.GetProcessInfo());
    element.CalculateLeftHandSide(lhs_only, model.GetProcessInfo());
    element.CalculateRightHandSide(rhs_only, model.GetProcessInfo());
    EXPECT_EQ((kept_lhs - kept_lhs.transpose()).norm(), 0.0);  // one triangle kept
    EXPECT_EQ(RelativeError(lhs_only, kept_lhs), 0.0);
    EXPECT_EQ((rhs_only - kept_rhs).norm(), 0.0);

    const ConstitutiveLaw::Pointer law = model.GetProperties().GetValue(CONSTITUTIVE_LAW);
    const ConstitutiveLaw::Pointer undeclared = std::make_shared<UndeclaredLinearLaw>(law);
    model.GetProperties().SetValue(CONSTITUTIVE_LAW, undeclared);
    element.Initialize(model.GetProcessInfo());
    EXPECT_NE(element.WhyStiffnessVaries().find("not a linear elastic law"), std::string::npos);
    element.CalculateLocalSystem(lhs, rhs, model.GetProcessInfo());
    EXPECT_LT(RelativeError(kept_lhs, lhs), 1e-14);
    EXPECT_LT((kept_rhs - rhs).norm(), 1e-13 * rhs.norm());
}

TEST_P(KeptStiffnessTest, APropertyChangeArrivesWithTheNextSolutionStep) {
    const ElementLawCase& c = GetParam();
    SolidTestModel model(c.law);
    Element& element = model.AddSingleElement(c.element);
    element.Initialize(model.GetProcessInfo());
    ApplyDeformation(model, element, {0.1, 0.3, 0.02, 3});
    Matrix K, K2;
    Vector rhs, rhs2;
    element.CalculateLocalSystem(K, rhs, model.GetProcessInfo());
    model.GetProperties().SetValue(YOUNG_MODULUS, 2.0 * model.GetProperties().GetValue(YOUNG_MODULUS));
    element.InitializeSolutionStep(model.GetProcessInfo());
    element.CalculateLocalSystem(K2, rhs2, model.GetProcessInfo());
    EXPECT_LT(RelativeError(K2, Matrix(2.0 * K)), 1e-14);
    EXPECT_LT((rhs2 - 2.0 * rhs).norm(), 1e-13 * rhs2.norm());
}

INSTANTIATE_TEST_SUITE_P(All, KeptStiffnessTest, ::testing::ValuesIn(KeptStiffnessCases()), CaseName);

TEST(WhyStiffnessVaries, NamesTheFiniteStrainFormulationOrTheNonlinearLaw) {
    for (const ElementLawCase& c : ElementLawCases()) {
        SolidTestModel model(c.law);
        Element& element = model.AddSingleElement(c.element);
        const std::string reason = element.WhyStiffnessVaries();
        const bool linear = Registry<ConstitutiveLaw>::Instance().Get(c.law).IsLinear();
        if (c.element.formulation != Formulation::SmallDisplacement)
            EXPECT_EQ(reason, "is a " + c.element.family + ", whose stiffness follows the displacement") << c.law;
        else if (!linear)
            EXPECT_EQ(reason, "has " + c.law + ", not a linear elastic law") << c.element.name;
        else
            EXPECT_EQ(reason, "") << c.element.name << " × " << c.law;
    }
}

}  // namespace
}  // namespace contact_app::testing
