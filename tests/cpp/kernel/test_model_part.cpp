// SPDX-License-Identifier: BSD-3-Clause
// ModelPart and Model: hierarchy, membership, dotted paths, ids and entity creation.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/model.h"
#include "contact_app/kernel/registry.h"
#include "contact_app/kernel/variables.h"

namespace contact_app {
namespace {

class ModelPartTest : public ::testing::Test {
protected:
    void SetUp() override {
        RegisterContactApplication();
        ModelPart& main = model.CreateModelPart("Main", 2);
        main.AddNodalSolutionStepVariable(DISPLACEMENT);
        for (IndexType id = 1; id <= 4; ++id) main.CreateNewNode(id, double(id % 2), double(id / 3), 0.0);
    }
    Model model;
};

TEST_F(ModelPartTest, SubModelPartEntitiesBelongToAllAncestors) {
    ModelPart& main = model.GetModelPart("Main");
    ModelPart& a = main.CreateSubModelPart("A");
    ModelPart& b = a.CreateSubModelPart("B");
    b.AddNodes({1, 2});
    auto node = b.CreateNewNode(10, 5.0, 5.0, 0.0);
    EXPECT_EQ(b.NumberOfNodes(), 3u);
    EXPECT_EQ(a.NumberOfNodes(), 3u);
    EXPECT_EQ(main.NumberOfNodes(), 5u);
    EXPECT_EQ(main.pGetNode(10), node);
    EXPECT_TRUE(node->SolutionStepsDataHas(DISPLACEMENT));  // layout shared with the root
    EXPECT_EQ(node->GetBufferSize(), 2u);

    auto properties = main.CreateNewProperties(1);
    auto element = b.CreateNewElement("Element2D3N", 5, {1, 2, 10}, properties);
    EXPECT_TRUE(main.HasElement(5));
    EXPECT_TRUE(a.HasElement(5));
    EXPECT_EQ(&element->GetProperties(), properties.get());
    EXPECT_EQ(&b.GetProcessInfo(), &main.GetProcessInfo());

    main.RemoveNode(2);
    EXPECT_FALSE(b.HasNode(2));
    EXPECT_EQ(b.FullName(), "Main.A.B");
    EXPECT_EQ(&b.GetRootModelPart(), &main);
}

TEST_F(ModelPartTest, DottedPathsReachNestedParts) {
    model.CreateModelPart("Main.Contact.Slave");
    EXPECT_TRUE(model.HasModelPart("Main.Contact.Slave"));
    EXPECT_FALSE(model.HasModelPart("Main.Contact.Master"));
    EXPECT_EQ(model.GetModelPart("Main.Contact.Slave").Name(), "Slave");
    EXPECT_EQ(&model.GetModelPart("Main").GetSubModelPart("Contact.Slave"), &model.GetModelPart("Main.Contact.Slave"));
    try {
        model.GetModelPart("Main.Contcat");
        FAIL();
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("did you mean \"Contact\""), std::string::npos);
    }
    EXPECT_THROW(model.GetModelPart("Structure"), InputError);
    EXPECT_THROW(model.CreateModelPart("Main"), InputError);
}

TEST_F(ModelPartTest, IdsAreUniquePerRootAndContainersStaySorted) {
    ModelPart& main = model.GetModelPart("Main");
    EXPECT_THROW(main.CreateNewNode(3, 0.0, 0.0, 0.0), InputError);
    EXPECT_THROW(main.GetSubModelPart("Missing"), InputError);
    main.CreateNewNode(0 + 7, 0.0, 0.0, 0.0);
    main.CreateNewNode(6, 0.0, 0.0, 0.0);
    std::vector<IndexType> ids;
    for (const auto& node : main.Nodes()) ids.push_back(node->Id());
    EXPECT_EQ(ids, (std::vector<IndexType>{1, 2, 3, 4, 6, 7}));
    EXPECT_THROW(main.CreateNewNode(0, 0.0, 0.0, 0.0), InputError);
}

TEST_F(ModelPartTest, CreatingAnEntityChecksNameNodesAndCount) {
    ModelPart& main = model.GetModelPart("Main");
    auto properties = main.CreateNewProperties(0);
    try {
        main.CreateNewElement("Element2D4M", 1, {1, 2, 3, 4}, properties);
        FAIL();
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("did you mean \"Element2D4N\""), std::string::npos);
    }
    EXPECT_THROW(main.CreateNewElement("Element2D4N", 1, {1, 2, 3}, properties), InputError);
    EXPECT_THROW(main.CreateNewCondition("LineCondition2D2N", 1, {1, 99}, properties), InputError);
    auto condition = main.CreateNewCondition("LineCondition2D2N", 1, {1, 2}, properties);
    EXPECT_THROW(main.CreateNewCondition("LineCondition2D2N", 1, {2, 3}, properties), InputError);
    condition->Set(TO_ERASE);
    main.CreateSubModelPart("Skin").AddConditions({1});
    EXPECT_EQ(main.RemoveConditionsFlagged(TO_ERASE), 1u);
    EXPECT_FALSE(main.GetSubModelPart("Skin").HasCondition(1));
}

TEST_F(ModelPartTest, CloneTimeStepAdvancesTimeStepAndBuffer) {
    ModelPart& main = model.GetModelPart("Main");
    main.GetNode(1).FastGetSolutionStepValue(DISPLACEMENT_X) = 1.5;
    main.CloneTimeStep(0.1);
    main.CloneTimeStep(0.3);
    EXPECT_DOUBLE_EQ(main.GetProcessInfo().GetValue(TIME), 0.3);
    EXPECT_NEAR(main.GetProcessInfo().GetValue(DELTA_TIME), 0.2, 1e-15);
    EXPECT_EQ(main.GetProcessInfo().GetValue(STEP), 2);
    EXPECT_DOUBLE_EQ(main.GetNode(1).GetSolutionStepValue(DISPLACEMENT_X, 1), 1.5);
}

TEST_F(ModelPartTest, NonFiniteTimeIsRefusedBeforeTheBuffersMove) {
    ModelPart& main = model.GetModelPart("Main");
    main.GetNode(1).FastGetSolutionStepValue(DISPLACEMENT_X) = 1.5;
    const auto message = [&](double time) -> std::string {
        try {
            main.CloneTimeStep(time);
        } catch (const InputError& error) {
            return error.what();
        }
        return "";
    };
    EXPECT_NE(message(std::nan("")).find("CloneTimeStep(nan) on model part Main: the new time is not finite"),
              std::string::npos);
    EXPECT_NE(message(-INFINITY).find("the new time is not finite"), std::string::npos);
    EXPECT_EQ(main.GetProcessInfo().GetValue(STEP), 0);
    EXPECT_DOUBLE_EQ(main.GetNode(1).FastGetSolutionStepValue(DISPLACEMENT_X), 1.5);  // buffers not shifted
    main.CloneTimeStep(1.7e308);
    EXPECT_NE(message(-1.7e308).find("the step from the current TIME 1.7e+308 is not finite"), std::string::npos);
    EXPECT_EQ(main.GetProcessInfo().GetValue(STEP), 1);
}

TEST_F(ModelPartTest, NonFiniteCoordinatesWeightsAndIdsBeyondTheRangeAreRefused) {
    ModelPart& sub = model.GetModelPart("Main").CreateSubModelPart("Sub");
    try {
        sub.CreateNewNode(5, 0.0, std::nan(""), 0.0);
        FAIL();
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("node 5 of model part Main.Sub has a non-finite coordinate (0, nan, 0)"),
                  std::string::npos)
            << error.what();
    }
    EXPECT_THROW(sub.CreateNewNode(6, INFINITY, 0.0, 0.0), InputError);
    EXPECT_FALSE(sub.HasNode(5) || sub.HasNode(6));
    try {
        sub.CreateNewNode(9223372036854775808ULL, 0.0, 0.0, 0.0);
        FAIL();
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("is beyond the largest id 9223372036854775807"), std::string::npos);
    }
    ModelPart& main = model.GetModelPart("Main");
    for (const auto& node : main.Nodes()) node->AddDof(DISPLACEMENT_X);
    EXPECT_THROW(main.CreateNewMasterSlaveConstraint("LinearMasterSlaveConstraint", 1, main.GetNode(1), DISPLACEMENT_X,
                                                     main.GetNode(2), DISPLACEMENT_X, std::nan(""), 0.0),
                 InputError);
    EXPECT_THROW(main.CreateNewMasterSlaveConstraint("LinearMasterSlaveConstraint", 1, main.GetNode(1), DISPLACEMENT_X,
                                                     main.GetNode(2), DISPLACEMENT_X, 1.0, INFINITY),
                 InputError);
    EXPECT_EQ(main.NumberOfMasterSlaveConstraints(), 0u);
}

TEST_F(ModelPartTest, MasterSlaveConstraintAppliesItsRelation) {
    ModelPart& main = model.GetModelPart("Main");
    for (const auto& node : main.Nodes()) node->AddDof(DISPLACEMENT_X);
    main.GetNode(1).FastGetSolutionStepValue(DISPLACEMENT_X) = 2.0;
    auto constraint = main.CreateNewMasterSlaveConstraint("LinearMasterSlaveConstraint", 1, main.GetNode(1),
                                                          DISPLACEMENT_X, main.GetNode(2), DISPLACEMENT_X, 0.5, 0.1);
    constraint->Apply(main.GetProcessInfo());
    EXPECT_DOUBLE_EQ(main.GetNode(2).FastGetSolutionStepValue(DISPLACEMENT_X), 1.1);
    EXPECT_THROW(main.CreateNewMasterSlaveConstraint("LinearMasterSlaveConstraint", 2, {}, {}, Matrix::Ones(1, 1),
                                                     Vector::Zero(1)),
                 InputError);
}

TEST(Registry, HoldsTheKernelMeshEntities) {
    RegisterContactApplication();
    const auto elements = Registry<Element>::Instance().Names();
    EXPECT_NE(std::find(elements.begin(), elements.end(), "Element3D8N"), elements.end());
    EXPECT_TRUE(Registry<Condition>::Instance().Has("SurfaceCondition3D4N"));
    EXPECT_EQ(Registry<Condition>::Instance().Get("Condition3D").GetGeometry().Name(), "Triangle3D3");
    EXPECT_TRUE(Registry<MasterSlaveConstraint>::Instance().Has("LinearMasterSlaveConstraint"));
}

}  // namespace
}  // namespace contact_app
