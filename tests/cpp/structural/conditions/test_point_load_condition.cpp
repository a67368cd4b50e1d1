// SPDX-License-Identifier: BSD-3-Clause
// Point loads: condition and historical nodal POINT_LOAD add; 2D keeps x, y; no stiffness.
#include <gtest/gtest.h>

#include "load_condition_test_utilities.h"

namespace contact_app::testing {
namespace {

TEST(PointLoadCondition, ConditionAndNodalLoadsAdd) {
    LoadConditionModel model;
    Node& node = model.AddNode(1, Array3(1.0, 2.0, 3.0));
    Condition& condition = model.AddCondition("PointLoadCondition3D1N", 1, {1});
    condition.SetValue(POINT_LOAD, Array3(1.0, 2.0, 3.0));
    node.FastGetSolutionStepValue(POINT_LOAD) = Array3(0.5, -1.0, 4.0);
    EXPECT_TRUE(Rhs(condition).isApprox(Vector(Eigen::Vector3d(1.5, 1.0, 7.0))));
    Matrix lhs;
    condition.CalculateLeftHandSide(lhs, ProcessInfo());
    EXPECT_EQ(lhs, Matrix::Zero(3, 3));
}

TEST(PointLoadCondition, TwoDimensionalKeepsInPlaneComponents) {
    LoadConditionModel model(true, false);  // POINT_LOAD not historical: only the condition value counts
    Node& node = model.AddNode(1, Array3(1.0, 2.0, 0.0));
    node.SetValue(POINT_LOAD, Array3(9.0, 9.0, 9.0));  // not read: non-historical (docs/theory/structural.md §3)
    Condition& condition = model.AddCondition("PointLoadCondition2D1N", 1, {1});
    condition.SetValue(POINT_LOAD, Array3(1.0, -2.0, 5.0));
    EXPECT_TRUE(Rhs(condition).isApprox(Vector(Eigen::Vector2d(1.0, -2.0))));
}

}  // namespace
}  // namespace contact_app::testing
