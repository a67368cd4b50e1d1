// SPDX-License-Identifier: BSD-3-Clause
/// ContactMasterSlaveConstraint: registration, Create, the SetDofList / SetLocalSystem refresh used by the MPC
/// condition (with its size checks), the test relation, Apply, and the base class refusing SetLocalSystem.
#include <gtest/gtest.h>

#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/model.h"
#include "contact_app/kernel/registry.h"
#include "custom_strategies/contact_master_slave_constraint.h"

namespace contact_app::testing {
namespace {

class ContactMasterSlaveConstraintTest : public ::testing::Test {
protected:
    void SetUp() override {
        RegisterContactApplication();
        RegisterContactMasterSlaveConstraints();
        RegisterContactMasterSlaveConstraints();  // idempotent
        part = &model.CreateModelPart("Constraint");
        part->AddNodalSolutionStepVariable(DISPLACEMENT);
        for (IndexType id = 1; id <= 3; ++id) {
            auto node = part->CreateNewNode(id, 0.0, 0.0, 0.0);
            node->AddDof(DISPLACEMENT_X);
            node->AddDof(DISPLACEMENT_Y);
        }
    }
    Dof* DofOf(IndexType id, const Variable<double>& v) { return &part->GetNode(id).GetDof(v); }

    Model model;
    ModelPart* part = nullptr;
};

TEST_F(ContactMasterSlaveConstraintTest, IsRegisteredAndCreatesItsOwnClass) {
    ASSERT_TRUE(Registry<MasterSlaveConstraint>::Instance().Has("ContactMasterSlaveConstraint"));
    const auto& prototype = Registry<MasterSlaveConstraint>::Instance().Get("ContactMasterSlaveConstraint");
    EXPECT_NE(dynamic_cast<const ContactMasterSlaveConstraint*>(&prototype), nullptr);
    Matrix T(1, 2);
    T << 0.25, 0.75;
    Vector c(1);
    c << 0.1;
    const auto created = prototype.Create(4, {DofOf(2, DISPLACEMENT_X), DofOf(3, DISPLACEMENT_X)},
                                          {DofOf(1, DISPLACEMENT_X)}, T, c);
    ASSERT_NE(std::dynamic_pointer_cast<ContactMasterSlaveConstraint>(created), nullptr);
    EXPECT_EQ(created->Id(), 4u);
    EXPECT_EQ(created->Info(), "ContactMasterSlaveConstraint #4");
    EXPECT_THROW(prototype.Create(5, {DofOf(2, DISPLACEMENT_X)}, {DofOf(1, DISPLACEMENT_X)}, T, c), InputError);
}

TEST_F(ContactMasterSlaveConstraintTest, ConditionRefreshReplacesDofsRelationAndConstant) {
    ContactMasterSlaveConstraint constraint(1);
    ProcessInfo info;
    Matrix T;
    Vector c;
    constraint.CalculateLocalSystem(T, c, info);
    EXPECT_EQ(T.size(), 0);
    EXPECT_EQ(c.size(), 0);

    const DofsVectorType slaves = {DofOf(1, DISPLACEMENT_X), DofOf(1, DISPLACEMENT_Y)};
    const DofsVectorType masters = {DofOf(2, DISPLACEMENT_Y), DofOf(3, DISPLACEMENT_Y)};
    Matrix relation(2, 2);
    relation << 0.0, 0.0, 0.4, 0.6;
    Vector constant(2);
    constant << 0.0, -0.01;
    // Sizes are checked against the DoF lists: set them first.
    EXPECT_THROW(constraint.SetLocalSystem(relation, constant, info), InputError);
    constraint.SetDofList(slaves, masters, info);
    EXPECT_THROW(constraint.SetLocalSystem(relation, Vector::Zero(3), info), InputError);
    EXPECT_THROW(constraint.SetLocalSystem(Matrix::Zero(2, 3), constant, info), InputError);
    constraint.SetLocalSystem(relation, constant, info);
    constraint.CalculateLocalSystem(T, c, info);
    EXPECT_EQ(T, relation);
    EXPECT_EQ(c, constant);
    DofsVectorType got_slaves, got_masters;
    constraint.GetDofList(got_slaves, got_masters, info);
    EXPECT_EQ(got_slaves, slaves);
    EXPECT_EQ(got_masters, masters);

    part->GetNode(2).FastGetSolutionStepValue(DISPLACEMENT_Y) = 1.0;
    part->GetNode(3).FastGetSolutionStepValue(DISPLACEMENT_Y) = 2.0;
    constraint.Apply(info);
    EXPECT_DOUBLE_EQ(part->GetNode(1).FastGetSolutionStepValue(DISPLACEMENT_Y), 0.4 + 1.2 - 0.01);
    EXPECT_DOUBLE_EQ(part->GetNode(1).FastGetSolutionStepValue(DISPLACEMENT_X), 0.0);
    EXPECT_NO_THROW(constraint.FinalizeNonLinearIteration(info));
    constraint.CalculateLocalSystem(T, c, info);
    EXPECT_EQ(T, relation);  // FinalizeNonLinearIteration leaves the relation alone
}

TEST_F(ContactMasterSlaveConstraintTest, TestRelationHasTheShapeOfTAndANewTDropsIt) {
    ContactMasterSlaveConstraint constraint(1);
    const ProcessInfo info;
    constraint.SetDofList({DofOf(1, DISPLACEMENT_Y)}, {DofOf(2, DISPLACEMENT_Y), DofOf(3, DISPLACEMENT_X)}, info);
    Matrix relation(1, 2), test(1, 2), got;
    relation << 0.5, 0.5;
    test << 0.5, 0.2;
    constraint.SetLocalSystem(relation, Vector::Zero(1), info);
    EXPECT_FALSE(constraint.CalculateTestRelation(got, info));  // W = T
    EXPECT_THROW(constraint.SetTestRelation(Matrix::Zero(2, 2), info), InputError);
    constraint.SetTestRelation(test, info);
    ASSERT_TRUE(constraint.CalculateTestRelation(got, info));
    EXPECT_EQ(got, test);
    constraint.SetLocalSystem(relation, Vector::Zero(1), info);  // a new T makes the old W stale
    EXPECT_FALSE(constraint.CalculateTestRelation(got, info));
    MasterSlaveConstraint base(2);
    EXPECT_FALSE(base.CalculateTestRelation(got, info));
    EXPECT_THROW(base.SetTestRelation(test, info), InputError);
}

TEST_F(ContactMasterSlaveConstraintTest, BaseConstraintRefusesSetLocalSystem) {
    MasterSlaveConstraint base(2);
    try {
        base.SetLocalSystem(Matrix::Zero(0, 0), Vector::Zero(0), ProcessInfo());
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("fix:"), std::string::npos);
    }
}

}  // namespace
}  // namespace contact_app::testing
