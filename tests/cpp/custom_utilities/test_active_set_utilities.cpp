// SPDX-License-Identifier: BSD-3-Clause
// Active-set and stick/slip rules of each contact family on hand-built nodal states: activation, deactivation,
// multiplier reset, stick/slip with hysteresis, change counters.
#include <gtest/gtest.h>

#include <cmath>

#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/model.h"
#include "custom_utilities/active_set_utilities.h"

namespace contact_app {
namespace {

constexpr double kScale = 2.0, kPenalty = 10.0;

/// Root "Structure" with a "Contact" child holding slave nodes; k = 2, ε = 10, n = +y on every node.
class ActiveSetModel {
public:
    ActiveSetModel() {
        RegisterContactApplication();
        root = &model.CreateModelPart("Structure");
        for (const VariableData* v :
             {static_cast<const VariableData*>(&WEIGHTED_GAP), static_cast<const VariableData*>(&WEIGHTED_SLIP),
              static_cast<const VariableData*>(&NORMAL), static_cast<const VariableData*>(&VECTOR_LAGRANGE_MULTIPLIER),
              static_cast<const VariableData*>(&LAGRANGE_MULTIPLIER_CONTACT_PRESSURE)})
            root->AddNodalSolutionStepVariable(*v);
        contact = &root->CreateSubModelPart("Contact");
        ProcessInfo& info = root->GetProcessInfo();
        info.SetValue(SCALE_FACTOR, kScale);
        info.SetValue(INITIAL_PENALTY, kPenalty);
        info.SetValue(NL_ITERATION_NUMBER, 1);
        info.SetValue(TANGENT_FACTOR, 1.0);
    }

    /// A slave node of Contact with gap @p gap, activity @p active and normal +y.
    Node& Add(double gap, bool active, bool slip = false) {
        const IndexType id = root->NumberOfNodes() + 1;
        auto node = root->CreateNewNode(id, static_cast<double>(id), 0.0, 0.0);
        contact->AddNodes({id});
        node->Set(SLAVE, true);
        node->Set(ACTIVE, active);
        node->Set(SLIP, slip);
        node->FastGetSolutionStepValue(WEIGHTED_GAP) = gap;
        node->FastGetSolutionStepValue(NORMAL) = Array3(0, 1, 0);
        return *node;
    }

    Model model;
    ModelPart* root = nullptr;
    ModelPart* contact = nullptr;
};

TEST(ActiveSetUtilities, test_alm_frictionless_activation_and_deactivation) {
    ActiveSetModel m;
    Node& opening = m.Add(-0.1, false);  // λ̄ = 0 + 10·(−0.1) = −1 → activated, λ := −1/2
    Node& closing = m.Add(0.5, true);    // λ̄ = 2·(−1) + 5 = 3 → deactivated
    Node& staying = m.Add(0.1, true);    // λ̄ = 2·(−3) + 1 = −5 → stays, λ kept
    Node& open = m.Add(0.2, false);      // λ̄ = 2 → stays open
    Node& own_penalty = m.Add(-0.1, false);
    own_penalty.SetValue(INITIAL_PENALTY, -1.0);  // nodal ε first: λ̄ = 0.1 → stays open
    Node& master = m.Add(-1.0, false);
    master.Set(SLAVE, false);
    closing.FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) = -1.0;
    staying.FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) = -3.0;
    EXPECT_EQ(ActiveSetUtilities::ComputeALMFrictionlessActiveSet(*m.root), 2u);
    EXPECT_TRUE(opening.Is(ACTIVE));
    EXPECT_DOUBLE_EQ(opening.FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE), -1.0 / kScale);
    EXPECT_DOUBLE_EQ(opening.GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE), -1.0);
    EXPECT_FALSE(closing.Is(ACTIVE));
    EXPECT_DOUBLE_EQ(closing.FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE), -1.0);
    EXPECT_DOUBLE_EQ(closing.GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE), 3.0);
    EXPECT_TRUE(staying.Is(ACTIVE));
    EXPECT_DOUBLE_EQ(staying.FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE), -3.0);
    EXPECT_DOUBLE_EQ(staying.GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE), -5.0);
    EXPECT_FALSE(open.Is(ACTIVE));
    EXPECT_FALSE(own_penalty.Is(ACTIVE));
    EXPECT_DOUBLE_EQ(own_penalty.GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE), 0.1);
    EXPECT_FALSE(master.Is(ACTIVE));
    EXPECT_FALSE(master.Has(AUGMENTED_NORMAL_CONTACT_PRESSURE));
    // Converged set: a second update flips nothing.
    EXPECT_EQ(ActiveSetUtilities::ComputeALMFrictionlessActiveSet(*m.root), 0u);
}

TEST(ActiveSetUtilities, test_a_node_no_pair_covers_leaves_the_active_set_with_its_multiplier) {
    ActiveSetModel m;
    Node& covered = m.Add(-0.1, true);
    Node& slid_off = m.Add(-0.1, true);  // compressed, but its last pass found it in no pair's overlap
    covered.SetValue(NODAL_AREA, 0.5);
    slid_off.SetValue(NODAL_AREA, 0.0);
    for (Node* node : {&covered, &slid_off}) node->FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) = -3.0;
    EXPECT_EQ(ActiveSetUtilities::ComputeALMFrictionlessActiveSet(*m.root), 1u);
    EXPECT_TRUE(covered.Is(ACTIVE));
    EXPECT_FALSE(slid_off.Is(ACTIVE));
    EXPECT_EQ(slid_off.FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE), 0.0);
    EXPECT_EQ(covered.FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE), -3.0);
    // The same for the components and frictional families (vector multiplier) and the penalty ones.
    slid_off.Set(ACTIVE, true);
    slid_off.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = Array3(0.5, -3.0, 0.0);
    ActiveSetUtilities::ComputeALMFrictionlessComponentsActiveSet(*m.root);
    EXPECT_FALSE(slid_off.Is(ACTIVE));
    EXPECT_EQ(slid_off.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER), Array3(0, 0, 0));
    slid_off.Set(ACTIVE, true);
    slid_off.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = Array3(0.5, -3.0, 0.0);
    ActiveSetUtilities::ComputeALMFrictionalActiveSet(*m.root, false);
    EXPECT_FALSE(slid_off.Is(ACTIVE));
    EXPECT_EQ(slid_off.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER), Array3(0, 0, 0));
    slid_off.Set(ACTIVE, true);
    ActiveSetUtilities::ComputePenaltyFrictionlessActiveSet(*m.root);
    EXPECT_FALSE(slid_off.Is(ACTIVE));
}

TEST(ActiveSetUtilities, test_set_is_frozen_after_the_first_iteration_of_the_simplified_newton) {
    ActiveSetModel m;
    Node& node = m.Add(-0.1, false);
    m.root->GetProcessInfo().SetValue(NL_ITERATION_NUMBER, 2);
    EXPECT_EQ(ActiveSetUtilities::ComputeALMFrictionlessActiveSet(*m.root), 0u);
    EXPECT_EQ(ActiveSetUtilities::ComputePenaltyFrictionlessActiveSet(*m.root), 0u);
    EXPECT_FALSE(node.Is(ACTIVE));
    m.root->Set(INTERACTION, true);  // full semi-smooth Newton: every iteration
    EXPECT_EQ(ActiveSetUtilities::ComputePenaltyFrictionlessActiveSet(*m.root), 1u);
    EXPECT_TRUE(node.Is(ACTIVE));
    m.root->GetProcessInfo().Data().Erase(SCALE_FACTOR);
    EXPECT_THROW(ActiveSetUtilities::ComputeALMFrictionlessActiveSet(*m.root), InputError);
}

TEST(ActiveSetUtilities, test_alm_components_project_the_multiplier_on_activation) {
    ActiveSetModel m;
    Node& opening = m.Add(-0.1, false);  // λ̄n = 2·(n·λ) − 1 with n·λ = 0.3 → −0.4
    Node& closing = m.Add(0.2, true);    // λ̄n = 2·(−0.5) + 2 = 1
    opening.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = Array3(0.7, 0.3, 0.0);
    closing.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = Array3(0.1, -0.5, 0.0);
    EXPECT_EQ(ActiveSetUtilities::ComputeALMFrictionlessComponentsActiveSet(*m.root), 2u);
    EXPECT_TRUE(opening.Is(ACTIVE));
    EXPECT_FALSE(closing.Is(ACTIVE));
    EXPECT_LT((opening.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) - Array3(0, -0.4 / kScale, 0)).norm(), 1e-15);
    EXPECT_DOUBLE_EQ(closing.GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE), 1.0);
    EXPECT_EQ(closing.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER), Array3(0.1, -0.5, 0.0));
}

TEST(ActiveSetUtilities, test_penalty_frictionless_uses_the_weighted_gap_only) {
    ActiveSetModel m;
    Node& touching = m.Add(0.0, true);  // λ̄n = 0: not active (strict)
    Node& penetrating = m.Add(-1e-3, false);
    EXPECT_EQ(ActiveSetUtilities::ComputePenaltyFrictionlessActiveSet(*m.root), 2u);
    EXPECT_FALSE(touching.Is(ACTIVE));
    EXPECT_TRUE(penetrating.Is(ACTIVE));
    EXPECT_DOUBLE_EQ(penetrating.GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE), kPenalty * -1e-3);
}

TEST(ActiveSetUtilities, test_penalty_frictional_stick_slip_with_consistent_orientation) {
    ActiveSetModel m;
    // λ̄n = 10·(−0.1) = −1, μ = 0.5 → Coulomb bound 0.5; λ̄τ = κ ε ũτ.
    Node& stick = m.Add(-0.1, true, true);
    stick.FastGetSolutionStepValue(WEIGHTED_SLIP) = Array3(0.01, 0, 0);  // |λ̄τ| = 0.1 ≤ 0.5 → stick
    Node& slip = m.Add(-0.1, true, false);
    slip.FastGetSolutionStepValue(WEIGHTED_SLIP) = Array3(-0.2, 0, 0);  // 2 > 0.5 → slip
    Node& leaving = m.Add(0.1, true, true);
    leaving.FastGetSolutionStepValue(WEIGHTED_SLIP) = Array3(0.3, 0, 0);
    for (Node* node : {&stick, &slip, &leaving}) node->SetValue(FRICTION_COEFFICIENT, 0.5);
    const auto flips = ActiveSetUtilities::ComputePenaltyFrictionalActiveSet(*m.root);
    EXPECT_EQ(flips[0], 1u);  // leaving
    EXPECT_EQ(flips[1], 2u);  // stick and slip swapped
    EXPECT_FALSE(stick.Is(SLIP));
    EXPECT_LT((stick.GetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE) - Array3(0.1, 0, 0)).norm(), 1e-15);
    EXPECT_TRUE(slip.Is(SLIP));
    // Slip traction μ|λ̄n| along ũτ, the orientation of the stick value κεũτ (B10 done right).
    const Array3 slip_traction = slip.GetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE);
    EXPECT_LT((slip_traction - Array3(-0.5, 0, 0)).norm(), 1e-15);
    EXPECT_GT(slip_traction.dot(slip.FastGetSolutionStepValue(WEIGHTED_SLIP)), 0.0);
    EXPECT_FALSE(leaving.Is(ACTIVE));
    EXPECT_FALSE(leaving.Is(SLIP));
    EXPECT_EQ(leaving.FastGetSolutionStepValue(WEIGHTED_SLIP), Array3(Array3::Zero()));
    // Pure slip: every active node slips and slip flips are not counted.
    stick.Set(SLIP, false);
    const auto pure = ActiveSetUtilities::ComputePenaltyFrictionalActiveSet(*m.root, true);
    EXPECT_EQ(pure[1], 0u);
    EXPECT_TRUE(stick.Is(SLIP));
    EXPECT_LT((stick.GetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE) - Array3(0.5, 0, 0)).norm(), 1e-15);
}

TEST(ActiveSetUtilities, test_penalty_slip_that_reverses_against_its_build_direction_sticks) {
    // λ̄n = 10·(−0.1) = −1, μ = 0.5: bound 0.5; trial κ ε ũτ = 10 ũτ. TANGENT_XI: the direction the build slipped along.
    ActiveSetModel m;
    Node& reversing = m.Add(-0.1, true, true);
    reversing.FastGetSolutionStepValue(WEIGHTED_SLIP) = Array3(-0.2, 0, 0);  // |trial| 2 > 0.5, but against +x
    Node& continuing = m.Add(-0.1, true, true);
    continuing.FastGetSolutionStepValue(WEIGHTED_SLIP) = Array3(0.2, 0, 0);
    for (Node* node : {&reversing, &continuing}) {
        node->SetValue(FRICTION_COEFFICIENT, 0.5);
        node->SetValue(TANGENT_XI, Array3(1, 0, 0));
    }
    auto flips = ActiveSetUtilities::ComputePenaltyFrictionalActiveSet(*m.root);
    EXPECT_EQ(flips[0], 0u);
    EXPECT_EQ(flips[1], 1u);  // the reversing node tries stick, the overshoot lies between the two directions
    EXPECT_FALSE(reversing.Is(SLIP));
    EXPECT_LT((reversing.GetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE) - Array3(-2, 0, 0)).norm(), 1e-15);
    EXPECT_TRUE(continuing.Is(SLIP));
    // From stick it slips the other way at the next update (the build's direction is now −x).
    reversing.SetValue(TANGENT_XI, Array3(-1, 0, 0));
    flips = ActiveSetUtilities::ComputePenaltyFrictionalActiveSet(*m.root);
    EXPECT_EQ(flips[1], 1u);
    EXPECT_TRUE(reversing.Is(SLIP));
    EXPECT_LT((reversing.GetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE) - Array3(-0.5, 0, 0)).norm(), 1e-15);
    EXPECT_EQ(ActiveSetUtilities::ComputePenaltyFrictionalActiveSet(*m.root)[1], 0u);
}

TEST(ActiveSetUtilities, test_penalty_node_opening_within_the_iterate_motion_is_held_and_counted) {
    // release_gap = 1e-3 (the largest correction of the iterate); mean gaps G/A with A = 0.5, λ̄ = ε G (η = 1).
    ActiveSetModel m;
    Node& held = m.Add(2e-4, true);        // opened by 4e-4 < 1e-3: stays ACTIVE, counted
    Node& released = m.Add(1e-3, true);    // opened by 2e-3 > 1e-3: leaves
    Node& closed = m.Add(2e-4, false);     // open and inactive: stays out (the hold only keeps)
    Node& entering = m.Add(-1e-4, false);  // penetrating: enters
    Node& pressed = m.Add(-1e-4, true);    // penetrating and active: no change
    for (Node* node : {&held, &released, &closed, &entering, &pressed}) {
        node->SetValue(NODAL_AREA, 0.5);
        node->SetValue(SQUARED_PAIR_AREA, 0.25);  // one pair: η = 1
    }
    EXPECT_EQ(ActiveSetUtilities::ComputePenaltyFrictionlessActiveSet(*m.root, 1e-3), 3u);
    EXPECT_TRUE(held.Is(ACTIVE));
    EXPECT_FALSE(released.Is(ACTIVE));
    EXPECT_FALSE(closed.Is(ACTIVE));
    EXPECT_TRUE(entering.Is(ACTIVE) && pressed.Is(ACTIVE));
    EXPECT_DOUBLE_EQ(held.GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE), kPenalty * 2e-4);  // the tension it pulls with
    // The held node keeps counting while it is open: the set cannot converge with an active node open. Once the
    // corrections fall below its opening it leaves; a converged set has G < 0 on every ACTIVE node, G >= 0 elsewhere.
    EXPECT_EQ(ActiveSetUtilities::ComputePenaltyFrictionlessActiveSet(*m.root, 1e-3), 1u);
    EXPECT_TRUE(held.Is(ACTIVE));
    EXPECT_EQ(ActiveSetUtilities::ComputePenaltyFrictionlessActiveSet(*m.root, 1e-5), 1u);
    EXPECT_FALSE(held.Is(ACTIVE));
    EXPECT_EQ(ActiveSetUtilities::ComputePenaltyFrictionlessActiveSet(*m.root, 1e-5), 0u);
    for (Node* node : {&held, &released, &closed, &entering, &pressed})
        EXPECT_EQ(node->Is(ACTIVE), node->FastGetSolutionStepValue(WEIGHTED_GAP) < 0.0);
    // Without a release gap (the default) an open node leaves at once, as before.
    held.Set(ACTIVE, true);
    EXPECT_EQ(ActiveSetUtilities::ComputePenaltyFrictionlessActiveSet(*m.root), 1u);
    EXPECT_FALSE(held.Is(ACTIVE));
    // Frictional: the same normal rule; a held node has no compression, so it slips with its (small) bound.
    held.Set(ACTIVE, true);
    held.SetValue(FRICTION_COEFFICIENT, 0.5);
    held.FastGetSolutionStepValue(WEIGHTED_SLIP) = Array3(0.01, 0, 0);
    const auto flips = ActiveSetUtilities::ComputePenaltyFrictionalActiveSet(*m.root, false, 1e-3);
    EXPECT_EQ(flips[0], 1u);
    EXPECT_TRUE(held.Is(ACTIVE) && held.Is(SLIP));
    EXPECT_EQ(ActiveSetUtilities::ComputePenaltyFrictionalActiveSet(*m.root, false, 1e-5)[0], 1u);
    EXPECT_FALSE(held.Is(ACTIVE) || held.Is(SLIP));
}

TEST(ActiveSetUtilities, test_alm_frictional_hysteresis_augmentation_and_activation) {
    ActiveSetModel m;
    ProcessInfo& info = m.root->GetProcessInfo();
    info.SetValue(SLIP_THRESHOLD, 0.1);
    info.SetValue(SLIP_AUGMENTATION_COEFFICIENT, 0.5);
    // Active nodes with λ = (0.3, −1, 0): λn = −1, λτ = (0.3, 0, 0), g̃ = 0 → λ̄n = −2, k λτ = (0.6, 0, 0).
    auto active = [&](bool slip, double mu, const Array3& weighted_slip) -> Node& {
        Node& node = m.Add(0.0, true, slip);
        node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = Array3(0.3, -1.0, 0.0);
        node.FastGetSolutionStepValue(WEIGHTED_SLIP) = weighted_slip;
        node.SetValue(FRICTION_COEFFICIENT, mu);
        return node;
    };
    const Array3 no_slip = Array3::Zero(), small_slip(0.01, 0, 0);
    Node& stick_stays = active(false, 0.32, no_slip);   // 0.6/0.64 = 0.94 ≤ 1 → stick
    Node& slip_stays = active(true, 0.32, no_slip);     // 0.94 > 1 − 0.1 → still slip (hysteresis)
    Node& slip_to_stick = active(true, 0.4, no_slip);   // 0.75 → stick
    Node& stick_to_slip = active(false, 0.25, no_slip); // 1.2 → slip
    Node& stick_full = active(false, 0.4, small_slip);  // λ̄τ = 0.6 + κεũτ = 0.7; 0.7/0.8 → stick
    Node& slip_augmented = active(true, 0.375, small_slip);  // λ̄τ = 0.6 + κεũτ = 0.7: 0.933 > 0.9 → slip
    Node& entering = m.Add(-0.1, false);                // λ̄n = −1, λ̄τ = κ ε ũτ = (0.2, 0, 0)
    entering.FastGetSolutionStepValue(WEIGHTED_SLIP) = Array3(0.02, 0, 0);
    entering.SetValue(FRICTION_COEFFICIENT, 0.5);
    Node& leaving = m.Add(0.5, true, true);  // λ̄n = 2·(−0.1) + 5 > 0
    leaving.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = Array3(0, -0.1, 0);
    leaving.FastGetSolutionStepValue(WEIGHTED_SLIP) = small_slip;

    const auto flips = ActiveSetUtilities::ComputeALMFrictionalActiveSet(*m.root);
    EXPECT_EQ(flips[0], 2u);  // entering, leaving
    EXPECT_EQ(flips[1], 2u);  // slip_to_stick, stick_to_slip
    EXPECT_FALSE(stick_stays.Is(SLIP));
    EXPECT_TRUE(slip_stays.Is(SLIP));
    EXPECT_FALSE(slip_to_stick.Is(SLIP));
    EXPECT_TRUE(stick_to_slip.Is(SLIP));
    EXPECT_FALSE(stick_full.Is(SLIP));
    EXPECT_TRUE(slip_augmented.Is(SLIP));  // the trial counts κεũτ on slipping nodes too (no 0.5 factor)
    auto tangent = [](const Node& node) { return node.GetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE); };
    EXPECT_LT((tangent(stick_stays) - Array3(0.6, 0, 0)).norm(), 1e-14);
    EXPECT_LT((tangent(stick_full) - Array3(0.7, 0, 0)).norm(), 1e-14);
    EXPECT_LT((tangent(slip_augmented) - Array3(0.375 * 2.0, 0, 0)).norm(), 1e-14);  // −μ λ̄n along λ̄τ
    EXPECT_LT((tangent(stick_to_slip) - Array3(0.25 * 2.0, 0, 0)).norm(), 1e-14);  // −μ λ̄n along λ̄τ
    // Leaving stick: back onto the cone, kPλ = (0.5, 0, 0); a node that was slipping keeps its λ.
    EXPECT_LT((stick_to_slip.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) - Array3(0.25, -1, 0)).norm(), 1e-15);
    EXPECT_EQ(slip_stays.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER), Array3(0.3, -1, 0));
    EXPECT_LT((tangent(slip_stays) - Array3(0.32 * 2.0, 0, 0)).norm(), 1e-14);
    // Activation: λ := n λ̄n/k + λ̄τ/k.
    EXPECT_TRUE(entering.Is(ACTIVE));
    EXPECT_LT((entering.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) - Array3(0.1, -0.5, 0)).norm(), 1e-15);
    EXPECT_FALSE(entering.Is(SLIP));  // 0.2/0.5 → stick
    EXPECT_FALSE(leaving.Is(ACTIVE));
    EXPECT_FALSE(leaving.Is(SLIP));
    EXPECT_EQ(leaving.FastGetSolutionStepValue(WEIGHTED_SLIP), Array3(Array3::Zero()));
    // Pure slip: all active nodes slip, slip flips are not counted.
    const auto pure = ActiveSetUtilities::ComputeALMFrictionalActiveSet(*m.root, true);
    EXPECT_EQ(pure[1], 0u);
    for (Node* node : {&stick_stays, &slip_to_stick, &stick_full, &entering}) EXPECT_TRUE(node->Is(SLIP));
}

TEST(ActiveSetUtilities, test_alm_frictional_node_leaving_stick_returns_to_the_cone) {
    // λ = (0.9, −1, 0.3), g̃ = 0, k = 2: λ̄n = −2, kPλ = (1.8, 0, 0.6), S = 0 → trial = kPλ, |trial| = 1.90 > μ|λ̄n| = 0.5.
    ActiveSetModel m;
    auto node_with = [&](bool slip) -> Node& {
        Node& node = m.Add(0.0, true, slip);
        node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = Array3(0.9, -1.0, 0.3);
        node.SetValue(FRICTION_COEFFICIENT, 0.25);
        return node;
    };
    Node& leaving_stick = node_with(false);
    Node& slipping = node_with(true);
    ActiveSetUtilities::ComputeALMFrictionalActiveSet(*m.root);
    EXPECT_TRUE(leaving_stick.Is(SLIP) && slipping.Is(SLIP));
    // Pλ := (μ|λ̄n|/k) τ̂ with τ̂ the trial direction; the normal part is kept.
    const Array3 direction = Array3(1.8, 0.0, 0.6).normalized();
    const Array3 mapped = Array3(0.0, -1.0, 0.0) + (0.25 * 2.0 / kScale) * direction;
    EXPECT_LT((leaving_stick.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) - mapped).norm(), 1e-15);
    EXPECT_LT((leaving_stick.GetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE) - 0.5 * direction).norm(), 1e-15);
    // A node that was slipping keeps its Newton iterate.
    EXPECT_EQ(slipping.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER), Array3(0.9, -1.0, 0.3));
}

TEST(ActiveSetUtilities, test_alm_frictional_slip_node_whose_friction_feeds_its_slip_sticks) {
    // λ = (0.9, −1, 0.3), k = 2: kPλ = (1.8, 0, 0.6), λ̄n = −2, μ = 0.25: every trial (|kPλ + εŜ| ≈ 1.9) exceeds the bound
    // 0.5. A slipping node whose direction turned beyond its linear range in the step (SLIP_TRIAL_FACTOR raised to 50)
    // with Ŝ = (−1e-3, 0, 0) had its friction along its own motion (kPλ·Ŝ < 0): it overshot the cone and sticks; with
    // Ŝ = (+1e-3, 0, 0) it dissipates and keeps slipping; so do a sticking node (it leaves for slip), a node at the base
    // factor (a passing state of a converging Newton path) and a node whose slip is round-off for the direction.
    ActiveSetModel m;
    auto node_with = [&](bool slip, double weighted_slip, double factor) -> Node& {
        Node& node = m.Add(0.0, true, slip);
        node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = Array3(0.9, -1.0, 0.3);
        node.FastGetSolutionStepValue(WEIGHTED_SLIP) = Array3(weighted_slip, 0.0, 0.0);
        node.SetValue(FRICTION_COEFFICIENT, 0.25);
        node.SetValue(TANGENT_XI, Array3(1.8, 0.0, 0.6).normalized());
        node.SetValue(SLIP_TRIAL_FACTOR, factor);
        return node;
    };
    Node& feeding = node_with(true, -1e-3, 50.0);
    Node& dissipating = node_with(true, 1e-3, 50.0);
    Node& sticking = node_with(false, -1e-3, 50.0);
    Node& at_base = node_with(true, -1e-3, 1.0);
    Node& round_off = node_with(true, -1e-9, 50.0);  // f ε|Ŝ| = 5e-7 < 1e-4 of the bound 0.5
    const auto flips = ActiveSetUtilities::ComputeALMFrictionalActiveSet(*m.root);
    EXPECT_FALSE(feeding.Is(SLIP));
    for (Node* node : {&dissipating, &sticking, &at_base, &round_off}) EXPECT_TRUE(node->Is(SLIP)) << node->Id();
    EXPECT_GE(flips[1], 2u);
}

TEST(ActiveSetUtilities, test_alm_frictional_frictionless_node_activation_drops_the_tangent) {
    ActiveSetModel m;
    Node& entering = m.Add(-0.1, false);
    entering.FastGetSolutionStepValue(WEIGHTED_SLIP) = Array3(0.02, 0, 0);  // μ = 0: tangent not carried over
    ActiveSetUtilities::ComputeALMFrictionalActiveSet(*m.root);
    EXPECT_LT((entering.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) - Array3(0, -0.5, 0)).norm(), 1e-15);
    EXPECT_TRUE(entering.Is(SLIP));  // μ = 0: any tangential traction exceeds the bound
}

TEST(ActiveSetUtilities, test_alm_frictional_turn_beyond_the_linearisation_raises_the_slip_trial_factor) {
    // λ = (0.3, −1, 0): kPλ = (0.6, 0, 0), λ̄n = −2, μ = 0.25 → bound 0.5 < 0.6, slip; ε = 10, κ = 1 → f = 1.
    ActiveSetModel m;
    auto slipping = [&](const Array3& weighted_slip, const Array3& built_direction) -> Node& {
        Node& node = m.Add(0.0, true, true);
        node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = Array3(0.3, -1.0, 0.0);
        node.FastGetSolutionStepValue(WEIGHTED_SLIP) = weighted_slip;
        node.SetValue(FRICTION_COEFFICIENT, 0.25);
        node.SetValue(TANGENT_XI, built_direction);
        return node;
    };
    // Trial (0.6, 0, 0.01) with f = 1: both turned by θ = atan(0.01/0.6) from x, and by π/2 − θ from z.
    Node& small_turn = slipping(Array3(0, 0, 1e-3), Array3(1, 0, 0));
    Node& large_turn = slipping(Array3(0, 0, 1e-3), Array3(0, 0, 1));
    ActiveSetUtilities::ResetSlipTrialFactors(*m.contact);
    EXPECT_EQ(small_turn.GetValue(SLIP_TRIAL_FACTOR), 1.0);
    ActiveSetUtilities::ComputeALMFrictionalActiveSet(*m.root);
    EXPECT_TRUE(small_turn.Is(SLIP) && large_turn.Is(SLIP));
    // θ_f = √(2 f ε|ũτ| / bound) = √0.04 = 0.2 covers θ = 0.0167, not 1.554.
    const double theta = std::atan2(0.6, 0.01);
    EXPECT_EQ(small_turn.GetValue(SLIP_TRIAL_FACTOR), 1.0);
    const double raised = 4.0 * theta * theta * 0.5 / (2.0 * kPenalty * 1e-3);  // θ_f = 2θ
    EXPECT_NEAR(large_turn.GetValue(SLIP_TRIAL_FACTOR), raised, 1e-12 * raised);
    // The slip direction weighs the slip by the node's own factor; the stick/slip test keeps max(κ, 1).
    const ProcessInfo& info = m.root->GetProcessInfo();
    EXPECT_LT((ActiveSetUtilities::SlipDirectionTrial(large_turn, info) - Array3(0.6, 0, raised * kPenalty * 1e-3)).norm(),
              1e-12);
    EXPECT_LT((ActiveSetUtilities::TrialTangentialTraction(large_turn, info, true) - Array3(0.6, 0, 0.01)).norm(), 1e-15);
    // Slipping, the node's traction follows the raised direction.
    const Array3 expected = 0.5 * Array3(0.6, 0, raised * kPenalty * 1e-3).normalized();
    ActiveSetUtilities::ComputeALMFrictionalActiveSet(*m.root);
    EXPECT_LT((large_turn.GetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE) - expected).norm(), 1e-12);
    // A new step starts from max(κ, 1); a 2D model (DOMAIN_SIZE 2) never raises: its directions only flip.
    ActiveSetUtilities::ResetSlipTrialFactors(*m.contact);
    EXPECT_EQ(large_turn.GetValue(SLIP_TRIAL_FACTOR), 1.0);
    m.root->GetProcessInfo().SetValue(DOMAIN_SIZE, 2);
    large_turn.SetValue(TANGENT_XI, Array3(0, 0, 1));
    ActiveSetUtilities::ComputeALMFrictionalActiveSet(*m.root);
    EXPECT_EQ(large_turn.GetValue(SLIP_TRIAL_FACTOR), 1.0);
}

}  // namespace
}  // namespace contact_app
