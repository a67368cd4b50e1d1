// SPDX-License-Identifier: BSD-3-Clause
/// ModelPartCheckpoint: nodes (history by variable name, DoFs), entities (name, state, shared geometries, values),
/// properties (values, law, tables), constraints and the ProcessInfo round-trip; damaged or mismatched bytes are
/// refused before the target is touched.
#include <string>

#include <gtest/gtest.h>

#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/io/model_part_checkpoint.h"
#include "contact_app/kernel/constitutive_law.h"
#include "contact_app/kernel/model.h"
#include "contact_app/kernel/registry.h"
#include "contact_app/kernel/variables.h"

namespace contact_app::testing {
namespace {

ModelPart& BuildModel(Model& model, bool reversed_variables) {
    RegisterContactApplication();
    ModelPart& part = model.CreateModelPart("Structure", 2);
    if (reversed_variables) {
        part.AddNodalSolutionStepVariable(REACTION);
        part.AddNodalSolutionStepVariable(DISPLACEMENT);
    } else {
        part.AddNodalSolutionStepVariable(DISPLACEMENT);
        part.AddNodalSolutionStepVariable(REACTION);
    }
    return part;
}

void FillModel(ModelPart& part) {
    auto properties = part.CreateNewProperties(1);
    properties->SetValue(YOUNG_MODULUS, 2.1e11);
    properties->SetValue(CONSTITUTIVE_LAW, Registry<ConstitutiveLaw>::Instance().Get("LinearElasticPlaneStrain2DLaw").Clone());
    Table table("TEMPERATURE", "YOUNG_MODULUS");
    table.PushBack(0.0, 1.0);
    table.PushBack(1.0, 3.0);
    properties->SetTable(TEMPERATURE, YOUNG_MODULUS, table);
    for (IndexType id = 1; id <= 4; ++id) {
        auto node = part.CreateNewNode(id, double(id % 2), double(id / 3), 0.0);
        node->AddDof(DISPLACEMENT_X, REACTION_X).SetEquationId(2 * id);
        node->AddDof(DISPLACEMENT_Y, REACTION_Y).SetEquationId(2 * id + 1);
        node->Coordinates()[0] += 0.25;
        node->Set(ACTIVE, id % 2 == 0);
        node->SetValue(NORMAL, Array3(0.0, 1.0 / id, 0.0));
    }
    part.GetNode(1).Fix(DISPLACEMENT_Y);
    part.CloneTimeStep(0.5);
    for (const auto& node : part.Nodes()) {
        node->FastGetSolutionStepValue(DISPLACEMENT) = Array3(0.1 * node->Id(), -0.2, 0.0);
        node->FastGetSolutionStepValue(REACTION_X, 1) = 3.0 * node->Id();
    }
    auto element = part.CreateNewElement("SmallDisplacementElement2D4N", 7, {1, 2, 4, 3}, properties);
    element->Set(ACTIVE, true);
    element->SetValue(INTEGRATION_ORDER, 3);
    part.CreateNewCondition("LineCondition2D2N", 3, {1, 2}, properties)->SetValue(NORMAL, Array3(0.0, -1.0, 0.0));
    Node& slave = part.GetNode(3);
    Node& master = part.GetNode(4);
    part.CreateNewMasterSlaveConstraint("LinearMasterSlaveConstraint", 5, master, DISPLACEMENT_X, slave, DISPLACEMENT_X,
                                        0.5, 0.125);
    Matrix test(1, 1);
    test(0, 0) = 0.75;  // the test relation W of a slipping MPC node
    part.GetMasterSlaveConstraint(5).SetTestRelation(test, part.GetProcessInfo());
    ModelPart& sub = part.CreateSubModelPart("Contact");
    sub.AddNodes({1, 2});
    sub.AddConditions({3});
    sub.CreateSubModelPart("Slave").AddNodes({2});
    sub.Set(INTERACTION, true);
    part.GetProcessInfo().SetValue(DELTA_TIME, 0.5);
    part.GetProcessInfo().SetValue(STEP, 1);
}

TEST(ModelPartCheckpoint, RoundTripIsExactAndIndependentOfTheVariableOrder) {
    Model model;
    ModelPart& part = BuildModel(model, false);
    FillModel(part);
    const std::string bytes = ModelPartCheckpoint::Save(part);

    Model fresh;
    ModelPart& loaded = BuildModel(fresh, true);  // another historical layout: values travel by name
    ModelPartCheckpoint::Load(loaded, bytes, "case_0.5.rest");
    EXPECT_EQ(ModelPartCheckpoint::Save(loaded).size(), bytes.size());
    ASSERT_EQ(loaded.NumberOfNodes(), 4u);
    for (const auto& node : part.Nodes()) {
        const Node& copy = loaded.GetNode(node->Id());
        EXPECT_EQ(copy.Coordinates(), node->Coordinates());
        EXPECT_EQ(copy.InitialCoordinates(), node->InitialCoordinates());
        EXPECT_EQ(copy.FastGetSolutionStepValue(DISPLACEMENT), node->FastGetSolutionStepValue(DISPLACEMENT));
        EXPECT_EQ(copy.FastGetSolutionStepValue(REACTION_X, 1), node->FastGetSolutionStepValue(REACTION_X, 1));
        EXPECT_EQ(copy.Is(ACTIVE), node->Is(ACTIVE));
        EXPECT_EQ(copy.GetValue(NORMAL), node->GetValue(NORMAL));
        EXPECT_EQ(copy.GetDof(DISPLACEMENT_Y).EquationId(), node->GetDof(DISPLACEMENT_Y).EquationId());
        EXPECT_EQ(copy.IsFixed(DISPLACEMENT_Y), node->IsFixed(DISPLACEMENT_Y));
        EXPECT_EQ(&copy.GetDof(DISPLACEMENT_X).GetReaction(), &REACTION_X);
    }
    const Element& element = loaded.GetElement(7);
    EXPECT_TRUE(element.Is(ACTIVE));
    EXPECT_EQ(element.GetValue(INTEGRATION_ORDER), 3);
    EXPECT_EQ(element.GetGeometry()[2].Id(), 4u);
    EXPECT_EQ(&element.GetGeometry()[0], &loaded.GetNode(1));
    const Properties& properties = element.GetProperties();
    EXPECT_EQ(properties.GetValue(YOUNG_MODULUS), 2.1e11);
    ASSERT_NE(properties.GetValue(CONSTITUTIVE_LAW), nullptr);
    EXPECT_EQ(properties.GetTable(TEMPERATURE, YOUNG_MODULUS).GetValue(0.5), 2.0);
    EXPECT_EQ(loaded.GetCondition(3).GetValue(NORMAL), Array3(0.0, -1.0, 0.0));
    Matrix relation;
    Vector constant;
    loaded.GetMasterSlaveConstraint(5).CalculateLocalSystem(relation, constant, loaded.GetProcessInfo());
    EXPECT_EQ(relation(0, 0), 0.5);
    EXPECT_EQ(constant[0], 0.125);
    Matrix test;
    ASSERT_TRUE(loaded.GetMasterSlaveConstraint(5).CalculateTestRelation(test, loaded.GetProcessInfo()));
    EXPECT_EQ(test(0, 0), 0.75);
    EXPECT_TRUE(loaded.GetSubModelPart("Contact").Is(INTERACTION));
    EXPECT_TRUE(loaded.GetSubModelPart("Contact.Slave").HasNode(2));
    EXPECT_TRUE(loaded.GetSubModelPart("Contact").HasCondition(3));
    EXPECT_EQ(loaded.GetProcessInfo().GetValue(TIME), 0.5);
    EXPECT_EQ(loaded.GetProcessInfo().GetValue(STEP), 1);
    EXPECT_EQ(loaded.GetBufferSize(), 2u);
}

void ExpectRefused(const std::string& bytes, const std::string& expected) {
    Model fresh;
    ModelPart& target = BuildModel(fresh, false);
    try {
        ModelPartCheckpoint::Load(target, bytes, "case_1.rest");
        FAIL() << "accepted damaged bytes";
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("case_1.rest"), std::string::npos) << message;
        EXPECT_NE(message.find(expected), std::string::npos) << message;
    }
    EXPECT_EQ(target.NumberOfNodes(), 0u);
    EXPECT_EQ(target.NumberOfSubModelParts(), 0u);
}

TEST(ModelPartCheckpoint, DamagedForeignOrMismatchedBytesAreRefusedUntouched) {
    Model model;
    ModelPart& part = BuildModel(model, false);
    FillModel(part);
    const std::string bytes = ModelPartCheckpoint::Save(part);
    ExpectRefused(bytes.substr(0, bytes.size() - 9), "truncated");
    ExpectRefused(bytes.substr(0, 20), "truncated");
    std::string flipped = bytes;
    flipped[bytes.size() / 2] ^= 0x10;
    ExpectRefused(flipped, "corrupt");
    std::string version = bytes;
    version[8] = 7;
    ExpectRefused(version, "format version 7");
    ExpectRefused("Begin ModelPartData\nEnd ModelPartData\n" + std::string(40, ' '), "not a contact_app checkpoint");

    Model other;
    ModelPart& wrong_name = other.CreateModelPart("Body");
    EXPECT_THROW(ModelPartCheckpoint::Load(wrong_name, bytes, "case_1.rest"), InputError);
    EXPECT_EQ(wrong_name.NumberOfNodes(), 0u);
    EXPECT_THROW(ModelPartCheckpoint::Load(part, bytes, "case_1.rest"), InputError);  // not empty
}

TEST(ModelPartCheckpoint, HashSeesEveryBitOfThePayload) {
    std::string data(37, 'a');
    const auto reference = ModelPartCheckpoint::Hash(data.data(), data.size());
    for (std::size_t byte = 0; byte < data.size(); ++byte) {
        for (int bit = 0; bit < 8; ++bit) {
            std::string flipped = data;
            flipped[byte] = static_cast<char>(flipped[byte] ^ (1 << bit));
            EXPECT_NE(ModelPartCheckpoint::Hash(flipped.data(), flipped.size()), reference);
        }
    }
    EXPECT_NE(ModelPartCheckpoint::Hash(data.data(), data.size() - 1), reference);
}

}  // namespace
}  // namespace contact_app::testing
