// SPDX-License-Identifier: BSD-3-Clause
// Node: historical buffer, non-historical values, DoFs and their error messages.
#include <gtest/gtest.h>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/model.h"
#include "contact_app/kernel/variables.h"

namespace contact_app {
namespace {

TEST(Node, BufferShiftKeepsThePreviousStepAndCopiesForward) {
    Model model;
    ModelPart& part = model.CreateModelPart("Main", 3);
    part.AddNodalSolutionStepVariable(DISPLACEMENT);
    part.AddNodalSolutionStepVariable(PRESSURE);
    Node& node = *part.CreateNewNode(1, 0.0, 0.0, 0.0);
    node.FastGetSolutionStepValue(DISPLACEMENT) = Array3(1.0, 2.0, 3.0);
    node.FastGetSolutionStepValue(PRESSURE) = 5.0;

    node.CloneSolutionStep();
    EXPECT_DOUBLE_EQ(node.GetSolutionStepValue(DISPLACEMENT_Y, 1), 2.0);
    EXPECT_DOUBLE_EQ(node.GetSolutionStepValue(DISPLACEMENT_Y, 0), 2.0);  // copied forward
    node.FastGetSolutionStepValue(DISPLACEMENT_Y) = 7.0;
    node.FastGetSolutionStepValue(PRESSURE) = 6.0;
    node.CloneSolutionStep();
    EXPECT_DOUBLE_EQ(node.GetSolutionStepValue(DISPLACEMENT_Y, 0), 7.0);
    EXPECT_DOUBLE_EQ(node.GetSolutionStepValue(DISPLACEMENT_Y, 1), 7.0);
    EXPECT_DOUBLE_EQ(node.GetSolutionStepValue(DISPLACEMENT_Y, 2), 2.0);
    EXPECT_DOUBLE_EQ(node.GetSolutionStepValue(PRESSURE, 2), 5.0);
    // Ring buffer of size 3: the oldest step is overwritten.
    node.FastGetSolutionStepValue(PRESSURE) = 9.0;
    node.CloneSolutionStep();
    EXPECT_DOUBLE_EQ(node.GetSolutionStepValue(PRESSURE, 0), 9.0);
    EXPECT_DOUBLE_EQ(node.GetSolutionStepValue(PRESSURE, 1), 9.0);
    EXPECT_DOUBLE_EQ(node.GetSolutionStepValue(PRESSURE, 2), 6.0);
    EXPECT_THROW(node.GetSolutionStepValue(PRESSURE, 3), InputError);
}

TEST(Node, AddingAVariableLaterKeepsExistingValues) {
    Model model;
    ModelPart& part = model.CreateModelPart("Main", 2);
    part.AddNodalSolutionStepVariable(PRESSURE);
    Node& node = *part.CreateNewNode(1, 0.0, 0.0, 0.0);
    node.FastGetSolutionStepValue(PRESSURE) = 4.0;
    node.CloneSolutionStep();
    node.FastGetSolutionStepValue(PRESSURE) = 8.0;
    part.AddNodalSolutionStepVariable(DISPLACEMENT);
    EXPECT_DOUBLE_EQ(node.GetSolutionStepValue(PRESSURE, 0), 8.0);
    EXPECT_DOUBLE_EQ(node.GetSolutionStepValue(PRESSURE, 1), 4.0);
    EXPECT_DOUBLE_EQ(node.GetSolutionStepValue(DISPLACEMENT_Z, 1), 0.0);
    part.SetBufferSize(3);
    EXPECT_DOUBLE_EQ(node.GetSolutionStepValue(PRESSURE, 1), 4.0);
    EXPECT_DOUBLE_EQ(node.GetSolutionStepValue(PRESSURE, 2), 0.0);
}

TEST(Node, MissingHistoricalVariableSaysHowToFixIt) {
    Model model;
    ModelPart& part = model.CreateModelPart("Main");
    Node& node = *part.CreateNewNode(3, 0.0, 0.0, 0.0);
    try {
        node.GetSolutionStepValue(WEIGHTED_GAP);
        FAIL();
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("AddNodalSolutionStepVariable(WEIGHTED_GAP)"), std::string::npos);
        EXPECT_NE(std::string(error.what()).find("node 3"), std::string::npos);
    }
}

TEST(Node, NonHistoricalValuesDefaultToZeroAndComponentsViewTheVector) {
    Node node(1, 0.0, 0.0, 0.0);
    EXPECT_FALSE(node.Has(NORMAL));
    EXPECT_DOUBLE_EQ(node.GetValue(NODAL_AREA), 0.0);
    EXPECT_TRUE(node.GetValue(NORMAL).isZero());
    node.SetValue(NORMAL_Y, 1.0);
    EXPECT_TRUE(node.Has(NORMAL));
    EXPECT_DOUBLE_EQ(node.GetValue(NORMAL)[1], 1.0);
    node.SetValue(TYING_VARIABLE, std::string("DISPLACEMENT"));
    EXPECT_EQ(node.GetValue(TYING_VARIABLE), "DISPLACEMENT");
}

TEST(Node, DofsAreFixedFreedAndKeepTheirReaction) {
    Model model;
    ModelPart& part = model.CreateModelPart("Main");
    part.AddNodalSolutionStepVariable(DISPLACEMENT);
    part.AddNodalSolutionStepVariable(REACTION);
    Node& node = *part.CreateNewNode(1, 0.0, 0.0, 0.0);
    Dof& dof = node.AddDof(DISPLACEMENT_X, REACTION_X);
    EXPECT_EQ(&node.AddDof(DISPLACEMENT_X), &dof);  // no duplicate
    EXPECT_FALSE(node.IsFixed(DISPLACEMENT_X));
    node.Fix(DISPLACEMENT_X);
    EXPECT_TRUE(dof.IsFixed());
    node.Free(DISPLACEMENT_X);
    EXPECT_FALSE(dof.IsFixed());
    dof.GetSolutionStepValue() = 0.25;
    EXPECT_DOUBLE_EQ(node.FastGetSolutionStepValue(DISPLACEMENT_X), 0.25);
    dof.GetSolutionStepReactionValue() = -3.0;
    EXPECT_DOUBLE_EQ(node.FastGetSolutionStepValue(REACTION_X), -3.0);
    EXPECT_EQ(dof.GetReaction().Name(), "REACTION_X");
    EXPECT_EQ(dof.Id(), 1u);
    // Fix adds a missing DoF (mdpa fixity), Free of a missing one is an error.
    node.Fix(DISPLACEMENT_Y);
    EXPECT_TRUE(node.HasDofFor(DISPLACEMENT_Y));
    EXPECT_THROW(node.Free(DISPLACEMENT_Z), InputError);
    EXPECT_THROW(node.AddDof(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE, WEIGHTED_SCALAR_RESIDUAL), InputError);
}

}  // namespace
}  // namespace contact_app
