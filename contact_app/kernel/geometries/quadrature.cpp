// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/geometries/quadrature.h"

#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "contact_app/kernel/exceptions.h"

namespace contact_app {
namespace {

constexpr int kMaxOrder = 5;
constexpr int kNumFamilies = 7;
using Rule = std::vector<IntegrationPoint>;

IntegrationPoint Make(double x, double y, double z, double weight) { return {Array3(x, y, z), weight}; }

void CheckOrder(GeometryFamily family, int order) {
    CONTACT_CHECK(order >= 1 && order <= kMaxOrder, InputError, "no Gauss rule of order ", order, " for the ",
                  FamilyName(family), " family\n  expected: an integration order in 1..", kMaxOrder,
                  " (Kratos GAUSS_1..GAUSS_5)\n  fix: choose an order between 1 and ", kMaxOrder,
                  " (the geometry's DefaultIntegrationOrder() is always valid)");
}

// n-point Gauss–Legendre on [-1,1] in ascending order, from the closed-form roots of P_n (n ≤ 5).
Rule GaussLegendre(int n) {
    std::vector<std::pair<double, double>> half;  // (x ≥ 0, weight); x > 0 are mirrored
    switch (n) {
        case 1: half = {{0.0, 2.0}}; break;
        case 2: half = {{1.0 / std::sqrt(3.0), 1.0}}; break;
        case 3: half = {{0.0, 8.0 / 9.0}, {std::sqrt(0.6), 5.0 / 9.0}}; break;
        case 4: {
            const double r = 2.0 / 7.0 * std::sqrt(1.2), s = std::sqrt(30.0);
            half = {{std::sqrt(3.0 / 7.0 - r), (18.0 + s) / 36.0},
                    {std::sqrt(3.0 / 7.0 + r), (18.0 - s) / 36.0}};
            break;
        }
        default: {
            const double r = 2.0 * std::sqrt(10.0 / 7.0), s = 13.0 * std::sqrt(70.0);
            half = {{0.0, 128.0 / 225.0},
                    {std::sqrt(5.0 - r) / 3.0, (322.0 + s) / 900.0},
                    {std::sqrt(5.0 + r) / 3.0, (322.0 - s) / 900.0}};
        }
    }
    Rule rule;
    for (auto it = half.rbegin(); it != half.rend(); ++it)
        if (it->first > 0.0) rule.push_back(Make(-it->first, 0.0, 0.0, it->second));
    for (const auto& [x, w] : half) rule.push_back(Make(x, 0.0, 0.0, w));
    return rule;
}

Rule TensorProduct(int n, int dimension) {
    const Rule line = GaussLegendre(n);
    const Rule unit{Make(0, 0, 0, 1)};
    const Rule& second = dimension > 1 ? line : unit;
    const Rule& third = dimension > 2 ? line : unit;
    Rule rule;
    for (const auto& a : line)
        for (const auto& b : second)
            for (const auto& c : third)
                rule.push_back(Make(a.local[0], b.local[0], c.local[0], a.weight * b.weight * c.weight));
    return rule;
}

// Fully symmetric orbits in barycentric coordinates (appended with weight w each).
void TriangleOrbit3(Rule& rule, double a, double w) {  // (a, a, 1−2a) and permutations
    const double b = 1.0 - 2.0 * a;
    for (const auto& p : {Make(a, a, 0, w), Make(b, a, 0, w), Make(a, b, 0, w)}) rule.push_back(p);
}
void TetOrbit4(Rule& rule, double a, double w) {  // (a, a, a, 1−3a)
    const double b = 1.0 - 3.0 * a;
    for (const auto& p : {Make(a, a, a, w), Make(b, a, a, w), Make(a, b, a, w), Make(a, a, b, w)})
        rule.push_back(p);
}
void TetOrbit6(Rule& rule, double a, double w) {  // (a, a, b, b) with b = 1/2 − a
    const double b = 0.5 - a;
    for (const auto& p : {Make(a, a, b, w), Make(a, b, a, w), Make(b, a, a, w), Make(b, b, a, w),
                          Make(b, a, b, w), Make(a, b, b, w)})
        rule.push_back(p);
}

Rule TriangleRule(int order) {
    const double third = 1.0 / 3.0;
    Rule rule;
    switch (order) {
        case 1: rule.push_back(Make(third, third, 0, 0.5)); break;
        case 2: TriangleOrbit3(rule, 1.0 / 6.0, 1.0 / 6.0); break;
        case 3:  // Strang–Fix: negative centroid weight
            rule.push_back(Make(third, third, 0, -27.0 / 96.0));
            TriangleOrbit3(rule, 0.2, 25.0 / 96.0);
            break;
        case 4: {  // 6-point degree-4 rule, closed form (Strang & Fix / Cowper)
            const double s = std::sqrt(38.0 - 44.0 * std::sqrt(0.4));
            const double r = std::sqrt(213125.0 - 53320.0 * std::sqrt(10.0));
            TriangleOrbit3(rule, (8.0 - std::sqrt(10.0) + s) / 18.0, (620.0 + r) / 7440.0);
            TriangleOrbit3(rule, (8.0 - std::sqrt(10.0) - s) / 18.0, (620.0 - r) / 7440.0);
            break;
        }
        default: {  // Radon 7-point degree-5 rule
            const double q = std::sqrt(15.0);
            rule.push_back(Make(third, third, 0, 9.0 / 80.0));
            TriangleOrbit3(rule, (6.0 - q) / 21.0, (155.0 - q) / 2400.0);
            TriangleOrbit3(rule, (6.0 + q) / 21.0, (155.0 + q) / 2400.0);
        }
    }
    return rule;
}

Rule TetrahedronRule(int order) {
    Rule rule;
    switch (order) {
        case 1: rule.push_back(Make(0.25, 0.25, 0.25, 1.0 / 6.0)); break;
        case 2: TetOrbit4(rule, (5.0 - std::sqrt(5.0)) / 20.0, 1.0 / 24.0); break;
        case 3:  // Keast 5-point, negative centroid weight
            rule.push_back(Make(0.25, 0.25, 0.25, -2.0 / 15.0));
            TetOrbit4(rule, 1.0 / 6.0, 3.0 / 40.0);
            break;
        case 4:  // Keast 11-point, exact rational/radical data
            rule.push_back(Make(0.25, 0.25, 0.25, -74.0 / 5625.0));
            TetOrbit4(rule, 1.0 / 14.0, 343.0 / 45000.0);
            TetOrbit6(rule, (1.0 - std::sqrt(5.0 / 14.0)) / 4.0, 28.0 / 1125.0);
            break;
        default:  // positive 14-point degree-5 rule (Walkington). The orbit data solve a polynomial moment
                  // system with no closed form; solved to 40 digits (mpmath), printed to 22 here.
            TetOrbit4(rule, 0.09273525031089122640232, 0.01224884051939365825729);
            TetOrbit4(rule, 0.3108859192633006097973, 0.01878132095300264179986);
            TetOrbit6(rule, 0.04550370412564964949188, 0.007091003462846911073012);
    }
    return rule;
}

Rule PrismRule(int order) {  // triangle GAUSS_n × n-point Gauss–Legendre mapped to ζ ∈ [0,1]
    Rule rule;
    for (const auto& t : TriangleRule(order))
        for (const auto& l : GaussLegendre(order))
            rule.push_back(Make(t.local[0], t.local[1], 0.5 * (l.local[0] + 1.0), 0.5 * t.weight * l.weight));
    return rule;
}

Rule BuildRule(GeometryFamily family, int order) {
    switch (family) {
        case GeometryFamily::Point: return {Make(0, 0, 0, 1.0)};
        case GeometryFamily::Linear: return GaussLegendre(order);
        case GeometryFamily::Triangle: return TriangleRule(order);
        case GeometryFamily::Quadrilateral: return TensorProduct(order, 2);
        case GeometryFamily::Tetrahedra: return TetrahedronRule(order);
        case GeometryFamily::Hexahedra: return TensorProduct(order, 3);
        case GeometryFamily::Prism: return PrismRule(order);
    }
    CONTACT_THROW(InternalError, "unknown GeometryFamily value ", static_cast<int>(family));
}

}  // namespace

std::string FamilyName(GeometryFamily family) {
    switch (family) {
        case GeometryFamily::Point: return "Point";
        case GeometryFamily::Linear: return "Linear";
        case GeometryFamily::Triangle: return "Triangle";
        case GeometryFamily::Quadrilateral: return "Quadrilateral";
        case GeometryFamily::Tetrahedra: return "Tetrahedra";
        case GeometryFamily::Hexahedra: return "Hexahedra";
        case GeometryFamily::Prism: return "Prism";
    }
    return "unknown family " + std::to_string(static_cast<int>(family));
}

double ReferenceMeasure(GeometryFamily family) {
    switch (family) {
        case GeometryFamily::Point: return 1.0;
        case GeometryFamily::Linear: return 2.0;
        case GeometryFamily::Quadrilateral: return 4.0;
        case GeometryFamily::Hexahedra: return 8.0;
        case GeometryFamily::Tetrahedra: return 1.0 / 6.0;
        case GeometryFamily::Triangle:
        case GeometryFamily::Prism: return 0.5;
    }
    CONTACT_THROW(InternalError, "unknown GeometryFamily value ", static_cast<int>(family));
}

const std::vector<IntegrationPoint>& GaussRule(GeometryFamily family, int order) {
    CheckOrder(family, order);
    // Built once (thread-safe static initialisation); rules are immutable afterwards.
    static const auto tables = [] {
        std::array<std::array<Rule, kMaxOrder>, kNumFamilies> all;
        for (int f = 0; f < kNumFamilies; ++f)
            for (int n = 1; n <= kMaxOrder; ++n) all[f][n - 1] = BuildRule(static_cast<GeometryFamily>(f), n);
        return all;
    }();
    return tables[static_cast<int>(family)][order - 1];
}

int GaussRuleDegree(GeometryFamily family, int order) {
    CheckOrder(family, order);
    switch (family) {
        case GeometryFamily::Point: return std::numeric_limits<int>::max();
        case GeometryFamily::Linear:
        case GeometryFamily::Quadrilateral:
        case GeometryFamily::Hexahedra: return 2 * order - 1;
        default: return order;
    }
}

}  // namespace contact_app
