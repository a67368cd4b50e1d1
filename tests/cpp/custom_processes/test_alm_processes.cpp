// SPDX-License-Identifier: BSD-3-Clause
// ALM helper processes on hand-built interfaces: automatic penalty and scale factor, fast initialisation,
// adaptive penalty branches, dynamic factor.
#include <cmath>

#include <gtest/gtest.h>

#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/model.h"
#include "custom_processes/aalm_adapt_penalty_value_process.h"
#include "custom_processes/alm_fast_init_process.h"
#include "custom_processes/alm_variables_calculation_process.h"
#include "custom_processes/compute_dynamic_factor_process.h"
#include "tests/cpp/error_test_utilities.h"

namespace contact_app {
namespace {

using testing::ExpectError;

/// 2D interface: slave line 1-2 (length 2, E = 100, h = 0.5) and master line 3-4 (length 1, E = 300, h = 0.25).
ModelPart& TwoSidedInterface(Model& model) {
    RegisterContactApplication();
    ModelPart& part = model.CreateModelPart("Contact", 2);
    part.AddNodalSolutionStepVariable(NODAL_H);
    part.AddNodalSolutionStepVariable(WEIGHTED_GAP);
    part.AddNodalSolutionStepVariable(WEIGHTED_SLIP);
    part.CreateNewNode(1, 0.0, 0.0, 0.0);
    part.CreateNewNode(2, 2.0, 0.0, 0.0);
    part.CreateNewNode(3, 1.0, 0.1, 0.0);
    part.CreateNewNode(4, 0.0, 0.1, 0.0);
    auto slave_properties = part.CreateNewProperties(1);
    auto master_properties = part.CreateNewProperties(2);
    slave_properties->SetValue(YOUNG_MODULUS, 100.0);
    master_properties->SetValue(YOUNG_MODULUS, 300.0);
    part.CreateNewCondition("LineCondition2D2N", 7, {1, 2}, slave_properties)->Set(SLAVE, true);
    part.CreateNewCondition("LineCondition2D2N", 9, {3, 4}, master_properties)->Set(MASTER, true);
    for (IndexType id : {1, 2}) part.GetNode(id).FastGetSolutionStepValue(NODAL_H) = 0.5;
    for (IndexType id : {3, 4}) part.GetNode(id).FastGetSolutionStepValue(NODAL_H) = 0.25;
    for (IndexType id : {1, 2}) part.GetNode(id).Set(SLAVE, true);
    for (IndexType id : {3, 4}) part.GetNode(id).Set(SLAVE, false);
    return part;
}

TEST(ALMProcesses, test_alm_variables_follow_the_stiffness_formula) {
    Model model;
    ModelPart& part = TwoSidedInterface(model);
    const double f = 2.0, p = 3.0;
    ALMVariablesCalculationProcess(part, f, p).Execute();
    // Slave: Ē = 100·2/2, h̄ = (0.5 + 0.5)·2/2 / 2 → ε_s = 200 f; master: Ē = 300, h̄ = 0.25 → ε_m = 1200 f
    // (the 1e−12 regularisations of the reference included).
    const double tiny = 1e-12;
    auto stiffness = [&](double modulus_area, double length_area, double area) {
        return (modulus_area / (area + tiny)) / (length_area / (area + tiny) + tiny);
    };
    const double penalty = f * stiffness(100.0 * 2.0, 1.0 * 2.0 / 2.0, 2.0);
    ASSERT_LT(penalty, f * stiffness(300.0, 0.5 / 2.0, 1.0));
    EXPECT_NEAR(part.GetProcessInfo().GetValue(INITIAL_PENALTY), penalty, 1e-14 * penalty);
    EXPECT_NEAR(part.GetProcessInfo().GetValue(SCALE_FACTOR), p * penalty, 1e-14 * p * penalty);
    // Without a slave modulus the master values are used for the slave side too.
    part.GetProperties(1).SetValue(YOUNG_MODULUS, 0.0);
    ALMVariablesCalculationProcess(part).Execute();
    const double master = stiffness(300.0, 0.5 / 2.0, 1.0);
    EXPECT_NEAR(part.GetProcessInfo().GetValue(INITIAL_PENALTY), master, 1e-14 * master);
    // Unflagged conditions count for both sides: both sides see the area-weighted mix.
    part.GetProperties(1).SetValue(YOUNG_MODULUS, 100.0);
    for (const auto& condition : part.Conditions()) condition->Reset(SLAVE | MASTER);
    ALMVariablesCalculationProcess(part).Execute();
    const double mixed = stiffness(100.0 * 2.0 + 300.0 * 1.0, 1.0 * 2.0 / 2.0 + 0.5 * 1.0 / 2.0, 3.0);
    EXPECT_NEAR(part.GetProcessInfo().GetValue(INITIAL_PENALTY), mixed, 1e-14 * mixed);
    EXPECT_THROW(ALMVariablesCalculationProcess(part, 0.0), InputError);
}

TEST(ALMProcesses, test_a_face_without_modulus_takes_the_one_of_the_element_it_bounds) {
    Model model;
    ModelPart& part = TwoSidedInterface(model);
    const double reference_penalty = [&] {
        ALMVariablesCalculationProcess(part).Execute();
        return part.GetProcessInfo().GetValue(INITIAL_PENALTY);
    }();
    // The slave face gets a properties id without a modulus (as real models leave the interface's properties to
    // the bodies); the quadrilateral 1-2-6-5 below it carries E = 100.
    auto bare = part.CreateNewProperties(5);
    part.CreateNewNode(5, 0.0, -1.0, 0.0);
    part.CreateNewNode(6, 2.0, -1.0, 0.0);
    auto body = part.CreateNewProperties(6);
    body->SetValue(YOUNG_MODULUS, 100.0);
    part.CreateNewElement("Element2D4N", 1, {5, 6, 2, 1}, body);
    part.GetCondition(7).SetProperties(bare);
    ALMVariablesCalculationProcess(part).Execute();
    EXPECT_NEAR(part.GetProcessInfo().GetValue(INITIAL_PENALTY), reference_penalty, 1e-14 * reference_penalty);
    // Neither the face nor an element it bounds has one: an error naming the condition, not a silent 0.
    body->Data().Erase(YOUNG_MODULUS);
    ExpectError<InputError>([&] { ALMVariablesCalculationProcess(part).Execute(); },
                            {"condition 7", "YOUNG_MODULUS", "fix:"});
}

TEST(ALMProcesses, test_fast_init_resets_slave_nodes_and_averages_friction) {
    Model model;
    ModelPart& part = TwoSidedInterface(model);
    part.CreateNewNode(5, 4.0, 0.0, 0.0)->Set(SLAVE, true);
    auto third = part.CreateNewProperties(3);
    third->SetValue(FRICTION_COEFFICIENT, 0.4);
    part.GetProperties(1).SetValue(FRICTION_COEFFICIENT, 0.2);
    part.GetProperties(2).SetValue(FRICTION_COEFFICIENT, 0.1);
    part.CreateNewCondition("LineCondition2D2N", 12, {2, 5}, third)->Set(SLAVE, true);
    part.Set(SLIP, true);
    part.GetProcessInfo().SetValue(INITIAL_PENALTY, 42.0);
    for (const auto& node : part.Nodes()) {
        node->FastGetSolutionStepValue(WEIGHTED_GAP) = 1.0;
        node->FastGetSolutionStepValue(WEIGHTED_SLIP) = Array3(1, 1, 0);
    }
    part.GetCondition(7).SetValue(NORMAL, Array3(0, 1, 0));
    ALMFastInit(part).Execute();
    // Ids renumbered in order: 7, 9, 12 → 1, 2, 3.
    EXPECT_EQ(part.Conditions()[0].GetGeometry().NodeIdsString(), "[1, 2]");
    EXPECT_TRUE(part.HasCondition(1) && part.HasCondition(2) && part.HasCondition(3) && !part.HasCondition(7));
    EXPECT_EQ(part.GetCondition(3).GetGeometry().NodeIdsString(), "[2, 5]");
    EXPECT_EQ(part.GetCondition(1).GetValue(NORMAL), Array3(Array3::Zero()));
    for (IndexType id : {1, 2, 5}) {
        const Node& node = part.GetNode(id);
        EXPECT_EQ(node.FastGetSolutionStepValue(WEIGHTED_GAP), 0.0);
        EXPECT_EQ(node.FastGetSolutionStepValue(WEIGHTED_SLIP), Array3(Array3::Zero()));
        EXPECT_EQ(node.GetValue(INITIAL_PENALTY), 42.0);
        EXPECT_EQ(node.GetValue(DYNAMIC_FACTOR), 1.0);
        EXPECT_TRUE(node.Has(AUGMENTED_NORMAL_CONTACT_PRESSURE) && node.Has(AUGMENTED_TANGENT_CONTACT_PRESSURE));
    }
    EXPECT_EQ(part.GetNode(3).FastGetSolutionStepValue(WEIGHTED_GAP), 1.0);  // master: untouched
    EXPECT_FALSE(part.GetNode(3).Has(INITIAL_PENALTY));
    // Node 2 is shared by μ = 0.2 and μ = 0.4 conditions.
    EXPECT_DOUBLE_EQ(part.GetNode(1).GetValue(FRICTION_COEFFICIENT), 0.2);
    EXPECT_DOUBLE_EQ(part.GetNode(2).GetValue(FRICTION_COEFFICIENT), (0.2 + 0.4) / 2.0);
    EXPECT_DOUBLE_EQ(part.GetNode(5).GetValue(FRICTION_COEFFICIENT), 0.4);
    EXPECT_DOUBLE_EQ(part.GetNode(3).GetValue(FRICTION_COEFFICIENT), 0.1);
}

/// One node with NODAL_AREA 2, NODAL_H 1, MAX_GAP_FACTOR 0.1 (g_max = 0.1) and normalised gaps g, g_old.
struct AdaptCase {
    double gap, gap_old, expected_factor;  // expected ε / ε_prev
};

TEST(ALMProcesses, test_aalm_adapt_penalty_branches) {
    RegisterContactApplication();
    const double sqrt2 = std::sqrt(2.0);
    const AdaptCase cases[] = {
        {-0.05, 0.2, std::abs(0.2 / -0.05 * (0.05 + 0.1) / (-0.05 - 0.2))},  // sign change, |g_old| > g_max: 2.4
        {-0.05, 0.08, std::abs(0.08 / (10.0 * -0.05))},                      // sign change, small g_old: 0.16
        {-0.8, -0.01, 2.0},                                                  // jump 0.79 > 5 g_max: doubled
        {-0.3, -0.25, (sqrt2 + 1.0) * (sqrt2 + 1.0)},                        // |g| < 10 g_max: (√(3−1)+1)²
        {-1.2, -1.0, 2.0 * -1.0 / -1.2},                                     // |g| ≥ 10 g_max, growing: 2 g_old/g
        {-1.0, -1.0, std::sqrt(10.0 - 1.0) + 1.0},                           // |g| ≥ 10 g_max, steady: 4
        {-0.05, -0.02, 1.0},                                                 // |g| ≤ g_max: ε_prev kept
    };
    for (const bool first_iteration : {false, true}) {
        for (const AdaptCase& c : cases) {
            Model model;
            ModelPart& part = model.CreateModelPart("Contact", 2);
            part.AddNodalSolutionStepVariable(WEIGHTED_GAP);
            part.AddNodalSolutionStepVariable(NODAL_H);
            auto node = part.CreateNewNode(1, 0, 0, 0);
            ProcessInfo& info = part.GetProcessInfo();
            info.SetValue(MAX_GAP_FACTOR, 0.1);
            info.SetValue(INITIAL_PENALTY, 5.0);
            info.SetValue(STEP, first_iteration ? 1 : 3);
            info.SetValue(NL_ITERATION_NUMBER, 1);
            node->SetValue(NODAL_AREA, 2.0);
            node->SetValue(INITIAL_PENALTY, 7.0);
            node->FastGetSolutionStepValue(NODAL_H) = 1.0;
            node->FastGetSolutionStepValue(WEIGHTED_GAP, 0) = 2.0 * c.gap;
            node->FastGetSolutionStepValue(WEIGHTED_GAP, 1) = 2.0 * c.gap_old;
            AALMAdaptPenaltyValueProcess(part).Execute();
            const double previous = first_iteration ? 5.0 : 7.0;
            const double expected = previous * c.expected_factor;
            EXPECT_NEAR(node->GetValue(INITIAL_PENALTY), expected, 1e-12 * expected)
                << "g = " << c.gap << ", g_old = " << c.gap_old << ", first iteration " << first_iteration;
        }
    }
    Model model;
    ModelPart& single_buffer = model.CreateModelPart("Contact", 1);
    single_buffer.AddNodalSolutionStepVariable(WEIGHTED_GAP);
    EXPECT_THROW(AALMAdaptPenaltyValueProcess(single_buffer).Execute(), InputError);
}

TEST(ALMProcesses, test_dynamic_factor_is_the_share_of_the_step_after_impact) {
    RegisterContactApplication();
    Model model;
    ModelPart& part = model.CreateModelPart("Contact", 2);
    part.AddNodalSolutionStepVariable(WEIGHTED_GAP);
    const double gaps[][2] = {{-0.3, 0.1}, {-0.05, 0.1}, {-0.1, 0.0}, {-0.2, -0.1}, {0.1, 0.2}, {-0.3, 0.1}};
    for (int i = 0; i < 6; ++i) {
        auto node = part.CreateNewNode(i + 1, i, 0, 0);
        node->FastGetSolutionStepValue(WEIGHTED_GAP, 0) = gaps[i][0];
        node->FastGetSolutionStepValue(WEIGHTED_GAP, 1) = gaps[i][1];
        node->SetValue(DYNAMIC_FACTOR, 0.5);
    }
    part.GetNode(6).Set(SLAVE, false);  // master: not evaluated
    ComputeDynamicFactorProcess(part).Execute();
    // Open → penetrated: |g| / (g_old − g) of the step lies after the impact.
    EXPECT_DOUBLE_EQ(part.GetNode(1).GetValue(DYNAMIC_FACTOR), 0.3 / 0.4);
    EXPECT_DOUBLE_EQ(part.GetNode(2).GetValue(DYNAMIC_FACTOR), 0.05 / 0.15);
    EXPECT_DOUBLE_EQ(part.GetNode(3).GetValue(DYNAMIC_FACTOR), 1.0);  // touching at the start: the whole step
    EXPECT_DOUBLE_EQ(part.GetNode(4).GetValue(DYNAMIC_FACTOR), 1.0);  // already in contact
    EXPECT_DOUBLE_EQ(part.GetNode(5).GetValue(DYNAMIC_FACTOR), 1.0);  // open
    EXPECT_DOUBLE_EQ(part.GetNode(6).GetValue(DYNAMIC_FACTOR), 0.5);
}

}  // namespace
}  // namespace contact_app
