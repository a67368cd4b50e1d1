// SPDX-License-Identifier: BSD-3-Clause
// Every registered load condition: DoFs, equation ids, values, LHS = −FD(RHS) with follower loads, Check messages.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "contact_app/kernel/registry.h"
#include "load_condition_test_utilities.h"
#include "tests/cpp/error_test_utilities.h"

namespace contact_app::testing {
namespace {

/// What each registered load condition must be; a registered load-condition name without a row fails.
struct LoadConditionTraits {
    const char* name;
    int dofs_per_node;
    std::vector<Array3> nodes;  // reference coordinates, node ids 1..n
};

const std::vector<LoadConditionTraits>& LoadConditionTable() {
    static const std::vector<LoadConditionTraits> table{
        {"PointLoadCondition2D1N", 2, {Array3(0.3, 0.2, 0.0)}},
        {"PointLoadCondition3D1N", 3, {Array3(0.3, 0.2, 0.1)}},
        {"LineLoadCondition2D2N", 2, {Array3(0.0, 0.0, 0.0), Array3(1.0, 0.2, 0.0)}},
        {"AxisymLineLoadCondition2D2N", 2, {Array3(1.0, 0.0, 0.0), Array3(1.5, 0.8, 0.0)}},
        {"SurfaceLoadCondition3D3N", 3, {Array3(0.0, 0.0, 0.0), Array3(1.0, 0.1, 0.2), Array3(0.2, 1.0, 0.1)}},
        {"SurfaceLoadCondition3D4N", 3,
         {Array3(0.0, 0.0, 0.0), Array3(1.0, 0.0, 0.1), Array3(1.1, 1.0, 0.3), Array3(0.0, 0.9, 0.0)}},
    };
    return table;
}

std::vector<std::string> RegisteredLoadConditionNames() {
    RegisterLoadConditions();
    std::vector<std::string> names;
    for (const std::string& name : Registry<Condition>::Instance().Names())
        if (name.find("LoadCondition") != std::string::npos) names.push_back(name);
    return names;
}

class RegisteredLoadCondition : public ::testing::TestWithParam<std::string> {
protected:
    void SetUp() override {
        for (const auto& row : LoadConditionTable())
            if (GetParam() == row.name) traits = &row;
        ASSERT_NE(traits, nullptr) << GetParam() << " is registered but has no row in LoadConditionTable()";
    }
    /// The condition (id 1) on nodes 1..n of @p model, with every load source set.
    Condition& Build(LoadConditionModel& model, bool with_dofs = true) {
        model.AddNodes(traits->nodes, with_dofs);
        std::vector<IndexType> ids;
        for (std::size_t i = 0; i < traits->nodes.size(); ++i) ids.push_back(i + 1);
        Condition& condition = model.AddCondition(GetParam(), 1, ids);
        condition.SetValue(POINT_LOAD, Array3(1.0, -2.0, 0.5));
        condition.SetValue(LINE_LOAD, Array3(0.3, -0.7, 0.0));
        condition.SetValue(SURFACE_LOAD, Array3(0.2, 0.4, -0.9));
        condition.SetValue(PRESSURE, 0.7);
        condition.SetValue(NEGATIVE_FACE_PRESSURE, 0.4);
        condition.SetValue(POSITIVE_FACE_PRESSURE, 0.1);
        for (const auto& node : model.part->Nodes()) {
            const double s = static_cast<double>(node->Id());
            node->FastGetSolutionStepValue(POINT_LOAD) = Array3(0.1 * s, 0.2, -0.3);
            node->FastGetSolutionStepValue(LINE_LOAD) = Array3(-0.2 * s, 0.5, 0.0);
            node->FastGetSolutionStepValue(SURFACE_LOAD) = Array3(0.3, -0.1 * s, 0.6);
            node->FastGetSolutionStepValue(NEGATIVE_FACE_PRESSURE) = 0.25 * s;
            node->FastGetSolutionStepValue(POSITIVE_FACE_PRESSURE) = 0.1;
        }
        return condition;
    }
    const LoadConditionTraits* traits = nullptr;
};

TEST_P(RegisteredLoadCondition, DofsAreDisplacementsNodeByNode) {
    LoadConditionModel model;
    Condition& condition = Build(model);
    const int d = traits->dofs_per_node;
    const std::size_t n = traits->nodes.size();
    DofsVectorType dofs;
    condition.GetDofList(dofs, ProcessInfo());
    ASSERT_EQ(dofs.size(), n * d);
    const char* const names[] = {"DISPLACEMENT_X", "DISPLACEMENT_Y", "DISPLACEMENT_Z"};
    for (std::size_t a = 0; a < dofs.size(); ++a) {
        EXPECT_EQ(dofs[a]->Id(), a / d + 1);
        EXPECT_EQ(dofs[a]->GetVariable().Name(), names[a % d]);
        EXPECT_EQ(dofs[a]->GetReaction().Name(), "REACTION_" + std::string(1, "XYZ"[a % d]));
        dofs[a]->SetEquationId(100 + a);
        Displace(dofs[a]->GetNode(), Array3(0.01 * dofs[a]->Id(), -0.02, 0.03));
    }
    EquationIdVectorType ids;
    condition.EquationIdVector(ids, ProcessInfo());
    ASSERT_EQ(ids.size(), n * d);
    for (std::size_t a = 0; a < ids.size(); ++a) EXPECT_EQ(ids[a], 100 + a);
    Vector values;
    condition.GetValuesVector(values);
    ASSERT_EQ(values.size(), static_cast<Eigen::Index>(n * d));
    EXPECT_DOUBLE_EQ(values[(n - 1) * d], 0.01 * n);
    EXPECT_DOUBLE_EQ(values[1], -0.02);
    Matrix mass;
    condition.CalculateMassMatrix(mass, ProcessInfo());
    EXPECT_EQ(mass.size(), 0);
    EXPECT_EQ(CheckMessage(condition), "");
}

TEST_P(RegisteredLoadCondition, LhsIsMinusFdOfRhsAtDisplacedStates) {
    LoadConditionModel model;
    Condition& condition = Build(model);
    std::mt19937 rng(11);
    for (int sample = 0; sample < 3; ++sample) {
        DisplaceRandomly(*model.part, rng, 0.15, traits->dofs_per_node);
        Matrix lhs;
        Vector rhs;
        condition.CalculateLocalSystem(lhs, rhs, ProcessInfo());
        const Matrix fd = FiniteDifferenceLhs(condition, traits->dofs_per_node);
        ASSERT_EQ(lhs.rows(), fd.rows());
        const double scale = lhs.cwiseAbs().maxCoeff();
        if (traits->nodes.size() == 1) {  // point loads do not depend on u
            EXPECT_EQ(scale, 0.0);
            EXPECT_LT(fd.cwiseAbs().maxCoeff(), 1e-9);
            continue;
        }
        EXPECT_GT(scale, 0.1);
        EXPECT_LT((lhs - fd).cwiseAbs().maxCoeff() / scale, 1e-6) << "sample " << sample;
        Matrix lhs_only;
        condition.CalculateLeftHandSide(lhs_only, ProcessInfo());
        EXPECT_EQ(lhs_only, lhs);
        EXPECT_EQ(Rhs(condition), rhs);
    }
}

TEST_P(RegisteredLoadCondition, CheckNamesMissingHistoricalDisplacement) {
    LoadConditionModel model(false);
    Condition& condition = Build(model, false);
    const std::string message = CheckMessage(condition);
    EXPECT_NE(message.find("node 1 has no historical DISPLACEMENT"), std::string::npos) << message;
    EXPECT_NE(message.find("fix:"), std::string::npos) << message;
}

TEST_P(RegisteredLoadCondition, CheckNamesMissingDof) {
    LoadConditionModel model;
    Condition& condition = Build(model, false);
    const std::string message = CheckMessage(condition);
    EXPECT_NE(message.find("node 1 has no DISPLACEMENT_X DoF"), std::string::npos) << message;
    EXPECT_NE(message.find("AddDof(DISPLACEMENT_X, REACTION_X)"), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(LoadConditionRegistration, RegisteredLoadCondition,
                         ::testing::ValuesIn(RegisteredLoadConditionNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace contact_app::testing
