// SPDX-License-Identifier: BSD-3-Clause
/// Gauss rules: exact up to the claimed degree, not beyond, weights, point counts, caching, order errors.
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/geometries/quadrature.h"

namespace contact_app {
namespace {

using Exponents = std::array<int, 3>;

double Factorial(int n) { return n <= 1 ? 1.0 : n * Factorial(n - 1); }
double LineMonomial(int a) { return a % 2 ? 0.0 : 2.0 / (a + 1); }

int Dimension(GeometryFamily family) {
    switch (family) {
        case GeometryFamily::Point: return 0;
        case GeometryFamily::Linear: return 1;
        case GeometryFamily::Triangle:
        case GeometryFamily::Quadrilateral: return 2;
        default: return 3;
    }
}

// Exact ∫ ξ^a η^b ζ^c over the reference element, and a scale for the relative error (∫ |monomial|).
double ExactIntegral(GeometryFamily family, const Exponents& e) {
    const auto [a, b, c] = e;
    switch (family) {
        case GeometryFamily::Linear: return LineMonomial(a);
        case GeometryFamily::Quadrilateral: return LineMonomial(a) * LineMonomial(b);
        case GeometryFamily::Hexahedra: return LineMonomial(a) * LineMonomial(b) * LineMonomial(c);
        case GeometryFamily::Triangle: return Factorial(a) * Factorial(b) / Factorial(a + b + 2);
        case GeometryFamily::Tetrahedra:
            return Factorial(a) * Factorial(b) * Factorial(c) / Factorial(a + b + c + 3);
        case GeometryFamily::Prism: return Factorial(a) * Factorial(b) / Factorial(a + b + 2) / (c + 1);
        default: return 1.0;
    }
}
double AbsoluteIntegral(GeometryFamily family, const Exponents& e) {
    const auto line = [](int a) { return 2.0 / (a + 1); };
    switch (family) {
        case GeometryFamily::Linear: return line(e[0]);
        case GeometryFamily::Quadrilateral: return line(e[0]) * line(e[1]);
        case GeometryFamily::Hexahedra: return line(e[0]) * line(e[1]) * line(e[2]);
        default: return ExactIntegral(family, e);  // monomials are non-negative on simplices/prisms
    }
}

std::vector<Exponents> MonomialsOfDegree(int dimension, int degree) {
    std::vector<Exponents> result;
    for (int a = 0; a <= degree; ++a)
        for (int b = 0; b <= degree - a; ++b) {
            const int c = degree - a - b;
            if ((dimension < 2 && b > 0) || (dimension < 3 && c > 0)) continue;
            result.push_back({a, b, c});
        }
    return result;
}

double Quadrature(const std::vector<IntegrationPoint>& rule, const Exponents& e) {
    double sum = 0.0;
    for (const auto& p : rule)
        sum += p.weight * std::pow(p.local[0], e[0]) * std::pow(p.local[1], e[1]) * std::pow(p.local[2], e[2]);
    return sum;
}

double RelativeError(GeometryFamily family, const std::vector<IntegrationPoint>& rule, const Exponents& e) {
    return std::abs(Quadrature(rule, e) - ExactIntegral(family, e)) / AbsoluteIntegral(family, e);
}

struct RuleCase {
    GeometryFamily family;
    int order;
};

class GaussRuleTest : public ::testing::TestWithParam<RuleCase> {};

TEST_P(GaussRuleTest, WeightsSumToReferenceMeasure) {
    double sum = 0.0;
    for (const auto& p : GaussRule(GetParam().family, GetParam().order)) sum += p.weight;
    EXPECT_NEAR(sum, ReferenceMeasure(GetParam().family), 1e-15 * ReferenceMeasure(GetParam().family));
}

TEST_P(GaussRuleTest, IntegratesEveryMonomialUpToClaimedDegreeExactly) {
    const auto [family, order] = GetParam();
    const auto& rule = GaussRule(family, order);
    for (int degree = 0; degree <= GaussRuleDegree(family, order); ++degree)
        for (const Exponents& e : MonomialsOfDegree(Dimension(family), degree))
            EXPECT_LT(RelativeError(family, rule, e), 1e-13)
                << "monomial ξ^" << e[0] << " η^" << e[1] << " ζ^" << e[2];
}

TEST_P(GaussRuleTest, FailsOnSomeMonomialOfClaimedDegreePlusOne) {
    const auto [family, order] = GetParam();
    const auto& rule = GaussRule(family, order);
    double worst = 0.0;
    for (const Exponents& e : MonomialsOfDegree(Dimension(family), GaussRuleDegree(family, order) + 1))
        worst = std::max(worst, RelativeError(family, rule, e));
    EXPECT_GT(worst, 1e-6) << "the rule is exact one degree beyond its claim: the claimed degree is not tight";
}

TEST_P(GaussRuleTest, PointsLieStrictlyInsideReferenceElement) {
    const auto [family, order] = GetParam();
    for (const auto& p : GaussRule(family, order)) {
        const Array3& x = p.local;
        switch (family) {
            case GeometryFamily::Triangle:
                EXPECT_TRUE(x.head<2>().minCoeff() > 0 && x.head<2>().sum() < 1);
                break;
            case GeometryFamily::Tetrahedra: EXPECT_TRUE(x.minCoeff() > 0 && x.sum() < 1); break;
            case GeometryFamily::Prism:
                EXPECT_TRUE(x.head<2>().minCoeff() > 0 && x.head<2>().sum() < 1 && x[2] > 0 && x[2] < 1);
                break;
            default: EXPECT_LT(x.cwiseAbs().maxCoeff(), 1.0);
        }
        for (int d = Dimension(family); d < 3; ++d) EXPECT_EQ(x[d], 0.0) << "unused local components must be 0";
    }
}

TEST_P(GaussRuleTest, HasDocumentedPointCount) {
    const auto [family, order] = GetParam();
    const int n = order;
    const std::array<int, 5> triangle{1, 3, 4, 6, 7}, tetrahedra{1, 4, 5, 11, 14};
    std::size_t expected = 0;
    switch (family) {
        case GeometryFamily::Linear: expected = n; break;
        case GeometryFamily::Quadrilateral: expected = n * n; break;
        case GeometryFamily::Hexahedra: expected = n * n * n; break;
        case GeometryFamily::Triangle: expected = triangle[n - 1]; break;
        case GeometryFamily::Tetrahedra: expected = tetrahedra[n - 1]; break;
        case GeometryFamily::Prism: expected = triangle[n - 1] * n; break;
        default: expected = 1;
    }
    EXPECT_EQ(GaussRule(family, order).size(), expected);
}

std::vector<RuleCase> AllRules() {
    std::vector<RuleCase> cases;
    for (GeometryFamily family :
         {GeometryFamily::Linear, GeometryFamily::Triangle, GeometryFamily::Quadrilateral,
          GeometryFamily::Tetrahedra, GeometryFamily::Hexahedra, GeometryFamily::Prism})
        for (int order = 1; order <= 5; ++order) cases.push_back({family, order});
    return cases;
}

INSTANTIATE_TEST_SUITE_P(AllFamiliesAndOrders, GaussRuleTest, ::testing::ValuesIn(AllRules()),
                         [](const ::testing::TestParamInfo<RuleCase>& info) {
                             return FamilyName(info.param.family) + "_GAUSS_" +
                                    std::to_string(info.param.order);
                         });

TEST(GaussRule, PointFamilyIsOneUnitWeightAtTheOrigin) {
    for (int order = 1; order <= 5; ++order) {
        const auto& rule = GaussRule(GeometryFamily::Point, order);
        ASSERT_EQ(rule.size(), 1u);
        EXPECT_EQ(rule[0].weight, 1.0);
        EXPECT_EQ(rule[0].local, Array3::Zero());
    }
}

TEST(GaussRule, OrderOutsideOneToFiveThrowsInputErrorNamingFamilyOrderAndRange) {
    for (int order : {0, 6, -1}) {
        try {
            GaussRule(GeometryFamily::Tetrahedra, order);
            FAIL() << "order " << order << " accepted";
        } catch (const InputError& error) {
            const std::string message = error.what();
            EXPECT_NE(message.find("Tetrahedra"), std::string::npos) << message;
            EXPECT_NE(message.find("order " + std::to_string(order)), std::string::npos) << message;
            EXPECT_NE(message.find("1..5"), std::string::npos) << message;
        }
    }
    EXPECT_THROW(GaussRuleDegree(GeometryFamily::Linear, 6), InputError);
}

TEST(GaussRule, RepeatedCallsReturnTheSameCachedTable) {
    EXPECT_EQ(&GaussRule(GeometryFamily::Hexahedra, 3), &GaussRule(GeometryFamily::Hexahedra, 3));
}

TEST(GaussRule, TriangleOrder2IsTheThreeInteriorPointRule) {
    const auto& rule = GaussRule(GeometryFamily::Triangle, 2);
    const std::vector<Array3> expected{Array3(1.0 / 6, 1.0 / 6, 0), Array3(2.0 / 3, 1.0 / 6, 0),
                                       Array3(1.0 / 6, 2.0 / 3, 0)};
    ASSERT_EQ(rule.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_LT((rule[i].local - expected[i]).norm(), 3e-16);
        EXPECT_DOUBLE_EQ(rule[i].weight, 1.0 / 6.0);
    }
}

TEST(GaussRule, TriangleOrder3IsStrangFixWithNegativeCentroidWeight) {
    const auto& rule = GaussRule(GeometryFamily::Triangle, 3);
    EXPECT_LT((rule[0].local - Array3(1.0 / 3, 1.0 / 3, 0)).norm(), 1e-16);
    EXPECT_DOUBLE_EQ(rule[0].weight, -27.0 / 96.0);
}

TEST(GaussRule, TetrahedronOrder2UsesTheClosedFormAbscissa) {
    const double a = (5.0 - std::sqrt(5.0)) / 20.0, b = (5.0 + 3.0 * std::sqrt(5.0)) / 20.0;
    const auto& rule = GaussRule(GeometryFamily::Tetrahedra, 2);
    ASSERT_EQ(rule.size(), 4u);
    EXPECT_NEAR(rule[0].local[0], a, 1e-17);
    EXPECT_NEAR(rule[1].local[0], b, 1e-16);
    for (const auto& p : rule) EXPECT_DOUBLE_EQ(p.weight, 1.0 / 24.0);
}

TEST(GaussRule, LineRulesAreGaussLegendreToFullPrecision) {
    const auto& rule = GaussRule(GeometryFamily::Linear, 2);
    EXPECT_DOUBLE_EQ(rule[0].local[0], -1.0 / std::sqrt(3.0));
    EXPECT_DOUBLE_EQ(rule[1].local[0], 1.0 / std::sqrt(3.0));
    EXPECT_DOUBLE_EQ(rule[0].weight, 1.0);
    const auto& five = GaussRule(GeometryFamily::Linear, 5);
    for (std::size_t i = 0; i + 1 < five.size(); ++i)
        EXPECT_LT(five[i].local[0], five[i + 1].local[0]) << "ascending";
    EXPECT_DOUBLE_EQ(five[2].weight, 128.0 / 225.0);
}

TEST(GaussRule, PrismRuleIsTriangleRuleTimesLineRuleOnZeroOne) {
    const auto& prism = GaussRule(GeometryFamily::Prism, 2);
    ASSERT_EQ(prism.size(), 6u);
    EXPECT_NEAR(prism[0].local[2], 0.5 - 0.5 / std::sqrt(3.0), 1e-16);
    EXPECT_NEAR(prism[0].weight, 1.0 / 12.0, 1e-16);
}

}  // namespace
}  // namespace contact_app
