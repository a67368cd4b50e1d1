// SPDX-License-Identifier: BSD-3-Clause
// Dual<N>: chain rule of every operation, comparisons on the value, Eigen interplay, seeding helpers.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <functional>

#include "automatic_differentiation/ad_helpers.h"

namespace contact_app {
namespace {

using D2 = Dual<2>;

/// Central finite difference of f at (x, y) against the Dual gradient.
void ExpectGradient(const std::function<D2(D2, D2)>& f, double x, double y) {
    const D2 r = f(D2::Variable(x, 0), D2::Variable(y, 1));
    const double h = 1e-6;
    const double dx = (f(D2(x + h), D2(y)).Value() - f(D2(x - h), D2(y)).Value()) / (2 * h);
    const double dy = (f(D2(x), D2(y + h)).Value() - f(D2(x), D2(y - h)).Value()) / (2 * h);
    EXPECT_NEAR(r.Derivatives()[0], dx, 1e-7 * (1 + std::abs(dx)));
    EXPECT_NEAR(r.Derivatives()[1], dy, 1e-7 * (1 + std::abs(dy)));
}

TEST(Dual, test_dual_arithmetic_and_functions_follow_the_chain_rule) {
    ExpectGradient([](D2 a, D2 b) { return a + b * a - 3.0 * b + 2.0; }, 0.7, -1.3);
    ExpectGradient([](D2 a, D2 b) { return a / b - 1.0 / a + b / 4.0 - (2.0 - a); }, 0.7, -1.3);
    ExpectGradient([](D2 a, D2 b) { return sqrt(a * a + b * b) * abs(b); }, 0.7, -1.3);
    ExpectGradient([](D2 a, D2 b) { return pow(a, 2.5) + sin(b) * cos(a) + exp(b) * log(a); }, 0.7, -1.3);
    ExpectGradient([](D2 a, D2 b) { return atan2(b, a) + atan2(a, b); }, 0.7, -1.3);
    ExpectGradient([](D2 a, D2 b) { D2 c = a; c *= b; c /= a + 3.0; c -= b; c += 1.0; return -c; }, 0.7, -1.3);
}

TEST(Dual, test_dual_comparisons_use_the_value_and_sqrt_of_zero_is_finite) {
    const D2 a = D2::Variable(1.0, 0), b = D2::Variable(2.0, 1);
    EXPECT_TRUE(a < b);
    EXPECT_TRUE(b > 1.5);
    EXPECT_TRUE(0.5 <= a);
    EXPECT_FALSE(a == b);
    EXPECT_TRUE(a != 3.0);
    EXPECT_TRUE(isfinite(sqrt(D2::Variable(0.0, 0))));
    EXPECT_EQ(Value(2.5), 2.5);
    // Value-initialisation gives zero like double (default-initialisation leaves it unset, also like double).
    const Dual<21> zero{};
    EXPECT_EQ(zero.Value(), 0.0);
    EXPECT_EQ(zero.Derivatives().cwiseAbs().sum(), 0.0);
}

TEST(Dual, test_dual_works_inside_eigen_fixed_size_algebra) {
    // d(A⁻¹)/dA_00 = −A⁻¹ e0 e0ᵀ A⁻¹, and det, cross, dot, mixed products with double matrices.
    Eigen::Matrix3d a;
    a << 4, 1, 0.5, 1, 3, 0.2, 0.5, 0.2, 2;
    Eigen::Matrix<Dual<9>, 3, 3> ad = Seed<9>(a);
    const Eigen::Matrix<Dual<9>, 3, 3> inv = ad.inverse();
    const Eigen::Matrix3d ai = a.inverse();
    const Eigen::Matrix3d expected = -ai.col(0) * ai.row(0);
    EXPECT_LT((Derivative(inv, 0) - expected).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_NEAR(ad.determinant().Derivatives()[0], a.determinant() * ai(0, 0), 1e-12);
    const Eigen::Matrix<Dual<9>, 3, 1> c = ad.col(0).cross(ad.col(1));
    EXPECT_NEAR(c[2].Value(), 4 * 3 - 1 * 1, 1e-14);
    const Eigen::Matrix<Dual<9>, 3, 1> mixed = a * ad.col(2) + 2.0 * ad.col(0);
    EXPECT_NEAR(mixed[0].Derivatives()[0], 2.0, 1e-14);
    EXPECT_NEAR(mixed[0].Derivatives()[2], 4.0, 1e-14);
    EXPECT_EQ(Jacobian(Eigen::Matrix<Dual<9>, 3, 1>(ad.row(1).transpose())).row(0)[3], 1.0);
    EXPECT_TRUE(Values(ad).isApprox(a));
}

TEST(Dual, test_seed_numbers_variables_row_major_and_embed_shifts_them) {
    Eigen::Matrix<double, 2, 3> x;
    x << 1, 2, 3, 4, 5, 6;
    const auto s = Seed<10>(x, 4);
    EXPECT_EQ(s(1, 2).Value(), 6.0);
    EXPECT_EQ(s(1, 2).Derivatives()[4 + 5], 1.0);
    EXPECT_EQ(s(1, 2).Derivatives().sum(), 1.0);
    const Dual<12> e = Embed<12>(s(0, 1), 2);
    EXPECT_EQ(e.Derivatives()[2 + 5], 1.0);
    EXPECT_EQ(e.Derivatives().sum(), 1.0);
}

}  // namespace
}  // namespace contact_app
