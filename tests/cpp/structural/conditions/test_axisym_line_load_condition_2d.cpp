// SPDX-License-Identifier: BSD-3-Clause
// Axisymmetric line loads integrate 2π r over the meridian, without a THICKNESS divisor.
#include <gtest/gtest.h>

#include <cmath>

#include "load_condition_test_utilities.h"

namespace contact_app::testing {
namespace {

TEST(AxisymLineLoadCondition2D, VerticalEdgeCarriesTwoPiRLq) {
    LoadConditionModel model;
    model.AddNodes({Array3(2.0, 0.0, 0.0), Array3(2.0, 3.0, 0.0)});
    Condition& edge = model.AddCondition("AxisymLineLoadCondition2D2N", 1, {1, 2});
    edge.SetValue(LINE_LOAD, Array3(0.5, 0.0, 0.0));
    model.properties->SetValue(THICKNESS, 4.0);  // docs/theory/structural.md §8 D2: not divided by THICKNESS
    const Vector rhs = Rhs(edge);
    EXPECT_NEAR(rhs[0] + rhs[2], 2.0 * M_PI * 2.0 * 3.0 * 0.5, 1e-12);
    EXPECT_NEAR(rhs[1] + rhs[3], 0.0, 1e-14);
}

TEST(AxisymLineLoadCondition2D, SlopedEdgeIntegratesTheRadius) {
    // ∫ 2π r q ds = 2π q L (r1 + r2)/2 for a straight edge; r taken on the current (displaced) nodes.
    LoadConditionModel model;
    model.AddNodes({Array3(1.0, 0.0, 0.0), Array3(3.0, 0.0, 0.0)});
    Condition& edge = model.AddCondition("AxisymLineLoadCondition2D2N", 1, {1, 2});
    Displace(model.part->GetNode(2), Array3(1.0, 4.0, 0.0));  // current (4, 4): L = 5
    edge.SetValue(LINE_LOAD, Array3(0.0, -2.0, 0.0));
    const Vector rhs = Rhs(edge);
    EXPECT_NEAR(rhs[1] + rhs[3], 2.0 * M_PI * (-2.0) * 5.0 * 2.5, 1e-11);
    // The outer node takes more: ∫ N2 r ds / ∫ N1 r ds = (r1 + 2 r2)/(2 r1 + r2) = 9/6.
    EXPECT_NEAR(rhs[3] / rhs[1], 1.5, 1e-13);
}

TEST(AxisymLineLoadCondition2D, PressureOnClosedMeridianHasZeroAxialForce) {
    // A counter-clockwise rectangle in the (r, z) half-plane: the axial components cancel, the radial
    // ones do not (the hoop direction carries them).
    LoadConditionModel model;
    model.AddNodes({Array3(1, 0, 0), Array3(2, 0, 0), Array3(2, 1, 0), Array3(1, 1, 0)});
    for (IndexType i = 1; i <= 4; ++i)
        model.AddCondition("AxisymLineLoadCondition2D2N", i, {i, i % 4 + 1}).SetValue(PRESSURE, 1.0);
    const Array3 net = NetForce(*model.part, 2);
    EXPECT_NEAR(net[1], 0.0, 1e-13);
    EXPECT_NEAR(net[0], 2.0 * M_PI * (1.0 * 1.0 - 2.0 * 1.0), 1e-12);  // inner face pushed out, outer in
}

}  // namespace
}  // namespace contact_app::testing
