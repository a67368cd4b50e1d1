// SPDX-License-Identifier: BSD-3-Clause
/// The block step length of the contact line search: the minimum of the parabola through the residual norms at
/// 0, ½ and 1 when it is convex, clamped to [α_min, 1]; otherwise 1 if the full step did not increase the norm,
/// else α_min.
#include <gtest/gtest.h>

#include "custom_strategies/line_search_contact_strategy.h"

namespace contact_app::testing {
namespace {

TEST(LineSearchContactStrategy, ParabolaMinimumIsTheStepLength) {
    // r(α) = (α − 0.4)² + 1: r0 = 1.16, r½ = 1.01, r1 = 1.36 → α = 0.4.
    auto r = [](double alpha) { return (alpha - 0.4) * (alpha - 0.4) + 1.0; };
    EXPECT_NEAR(LineSearchContactStrategy::BlockAlpha(r(0.0), r(0.5), r(1.0), 1e-3), 0.4, 1e-14);
}

TEST(LineSearchContactStrategy, StepLengthIsClampedAndFallsBack) {
    auto r = [](double alpha, double center) { return (alpha - center) * (alpha - center); };
    EXPECT_DOUBLE_EQ(LineSearchContactStrategy::BlockAlpha(r(0, 3.0), r(0.5, 3.0), r(1, 3.0), 1e-3), 1.0);
    EXPECT_DOUBLE_EQ(LineSearchContactStrategy::BlockAlpha(r(0, -2.0), r(0.5, -2.0), r(1, -2.0), 1e-3), 1e-3);
    // Concave or linear: the full step if it reduces the norm, else the smallest step.
    EXPECT_DOUBLE_EQ(LineSearchContactStrategy::BlockAlpha(1.0, 0.5, 0.0, 1e-3), 1.0);
    EXPECT_DOUBLE_EQ(LineSearchContactStrategy::BlockAlpha(1.0, 1.5, 2.0, 1e-3), 1e-3);
    EXPECT_DOUBLE_EQ(LineSearchContactStrategy::BlockAlpha(0.0, 0.0, 0.0, 1e-3), 1.0);  // nothing to reduce
}

}  // namespace
}  // namespace contact_app::testing
