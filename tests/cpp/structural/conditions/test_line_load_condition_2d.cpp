// SPDX-License-Identifier: BSD-3-Clause
// 2D line loads: closed-polygon pressure balance, face-pressure signs, total force L·q, load sources.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "load_condition_test_utilities.h"

namespace contact_app::testing {
namespace {

TEST(LineLoadCondition2D, UniformPressureOnClosedPolygonHasZeroNetForce) {
    LoadConditionModel model;
    // An irregular counter-clockwise pentagon, displaced: the follower pressure still balances.
    model.AddNodes({Array3(0, 0, 0), Array3(2, -0.3, 0), Array3(2.5, 1.2, 0), Array3(1.1, 2.0, 0), Array3(-0.4, 1.1, 0)});
    for (IndexType i = 1; i <= 5; ++i) model.AddCondition("LineLoadCondition2D2N", i, {i, i % 5 + 1}).SetValue(PRESSURE, 3.0);
    std::mt19937 rng(2);
    DisplaceRandomly(*model.part, rng, 0.2, 2);
    EXPECT_LT(NetForce(*model.part, 2).norm(), 1e-13);
    // ... while a single edge carries p·L.
    const Condition& edge = model.part->GetCondition(1);
    const double length = edge.GetGeometry().Length();
    const Vector rhs = Rhs(model.part->GetCondition(1));
    EXPECT_NEAR((rhs.head<2>() + rhs.tail<2>()).norm(), 3.0 * length, 1e-13);
}

TEST(LineLoadCondition2D, FacePressureSignsFollowTheSpec) {
    // Edge (0,0) → (1,0) of a counter-clockwise square: n = (t_y, −t_x) = (0, −1) points out.
    LoadConditionModel model;
    model.AddNodes({Array3(0, 0, 0), Array3(1, 0, 0)});
    Condition& edge = model.AddCondition("LineLoadCondition2D2N", 1, {1, 2});
    edge.SetValue(NEGATIVE_FACE_PRESSURE, 2.0);  // pushes along −n: into the body (+y)
    Vector rhs = Rhs(edge);
    EXPECT_NEAR(rhs[1] + rhs[3], 2.0, 1e-14);
    EXPECT_NEAR(rhs[0] + rhs[2], 0.0, 1e-14);
    edge.SetValue(NEGATIVE_FACE_PRESSURE, 0.0);
    edge.SetValue(POSITIVE_FACE_PRESSURE, 2.0);  // pushes along +n (−y)
    rhs = Rhs(edge);
    EXPECT_NEAR(rhs[1] + rhs[3], -2.0, 1e-14);
    edge.SetValue(POSITIVE_FACE_PRESSURE, 0.0);
    model.part->GetNode(1).FastGetSolutionStepValue(NEGATIVE_FACE_PRESSURE) = 3.0;  // nodal, linear along the edge
    rhs = Rhs(edge);
    EXPECT_NEAR(rhs[1], 1.0, 1e-14);  // ∫ N1 (3 N1) = 1
    EXPECT_NEAR(rhs[3], 0.5, 1e-14);  // ∫ N2 (3 N1) = 1/2
}

TEST(LineLoadCondition2D, LineLoadTotalIsCurrentLengthTimesLoad) {
    LoadConditionModel model;
    model.AddNodes({Array3(0, 0, 0), Array3(1, 0, 0)});
    Condition& edge = model.AddCondition("LineLoadCondition2D2N", 1, {1, 2});
    Displace(model.part->GetNode(2), Array3(0.2, 0.9, 0.0));  // current length √(1.44 + 0.81) = 1.5
    edge.SetValue(LINE_LOAD, Array3(2.0, -1.0, 7.0));
    model.properties->SetValue(THICKNESS, 0.1);  // no thickness on loads (docs/theory/structural.md §3)
    Vector rhs = Rhs(edge);
    EXPECT_NEAR(rhs[0] + rhs[2], 1.5 * 2.0, 1e-14);
    EXPECT_NEAR(rhs[1] + rhs[3], -1.5, 1e-14);
    EXPECT_NEAR(rhs[0], rhs[2], 1e-14);
    // Nodal historical loads are interpolated and added: q = (2, −1) + N1 (1, 0) + N2 (3, 0).
    model.part->GetNode(1).FastGetSolutionStepValue(LINE_LOAD) = Array3(1.0, 0.0, 0.0);
    model.part->GetNode(2).FastGetSolutionStepValue(LINE_LOAD) = Array3(3.0, 0.0, 0.0);
    rhs = Rhs(edge);
    EXPECT_NEAR(rhs[0] + rhs[2], 1.5 * (2.0 + 2.0), 1e-13);
    EXPECT_NEAR(rhs[2] - rhs[0], 1.5 * (3.0 - 1.0) / 6.0, 1e-13);  // ∫(N2 − N1)(N1 + 3N2) ds = L/3
}

TEST(LineLoadCondition2D, NonHistoricalNodalLineLoadIsTheFallback) {
    LoadConditionModel model(true, false);
    model.AddNodes({Array3(0, 0, 0), Array3(2, 0, 0)});
    model.part->GetNode(1).SetValue(LINE_LOAD, Array3(0.0, 4.0, 0.0));
    model.part->GetNode(2).SetValue(LINE_LOAD, Array3(0.0, 4.0, 0.0));
    const Vector rhs = Rhs(model.AddCondition("LineLoadCondition2D2N", 1, {1, 2}));
    EXPECT_NEAR(rhs[1] + rhs[3], 8.0, 1e-14);
}

}  // namespace
}  // namespace contact_app::testing
