// SPDX-License-Identifier: BSD-3-Clause
// Flags (tri-state semantics), the variable registry, tables and the entity container.
#include <gtest/gtest.h>

#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/entity_container.h"
#include "contact_app/kernel/flags.h"
#include "contact_app/kernel/node.h"
#include "contact_app/kernel/table.h"
#include "contact_app/kernel/variable_registry.h"
#include "contact_app/kernel/variables.h"

namespace contact_app {
namespace {

TEST(Flags, SetResetAndDefinedFollowKratos) {
    Flags flags;
    EXPECT_FALSE(flags.Is(ACTIVE));
    EXPECT_TRUE(flags.IsNot(ACTIVE));
    EXPECT_FALSE(flags.IsDefined(ACTIVE));
    EXPECT_TRUE(flags.Is(ACTIVE.AsFalse()));  // undefined reads as false
    flags.Set(ACTIVE);
    flags.Set(SLIP, false);
    EXPECT_TRUE(flags.Is(ACTIVE));
    EXPECT_TRUE(flags.IsDefined(SLIP));
    EXPECT_FALSE(flags.Is(SLIP));
    EXPECT_TRUE(flags.Is(ACTIVE | SLAVE) == false);
    flags.Set(SLAVE);
    EXPECT_TRUE(flags.Is(ACTIVE | SLAVE));
    flags.Reset(ACTIVE);
    EXPECT_FALSE(flags.IsDefined(ACTIVE));
    EXPECT_FALSE(flags.Is(ACTIVE));
    flags.Flip(SLIP);
    EXPECT_TRUE(flags.Is(SLIP));
    EXPECT_EQ(GetFlag("MODIFIED"), MODIFIED);
    EXPECT_THROW(GetFlag("ACTIV"), InputError);
    EXPECT_EQ(ACTIVE.DefinedBits(), std::uint64_t(1) << 47);
}

TEST(VariableRegistry, KnowsKernelStructuralAndContactVariablesWithTypes) {
    RegisterContactApplication();
    const auto& registry = VariableRegistry::Instance();
    EXPECT_EQ(registry.Get("DISPLACEMENT").Type(), VariableType::Array);
    EXPECT_EQ(registry.Get("DISPLACEMENT_X").Type(), VariableType::Component);
    EXPECT_EQ(registry.Get("DISPLACEMENT_X").SourceVariable(), &DISPLACEMENT);
    EXPECT_EQ(registry.Get("WEIGHTED_GAP").Type(), VariableType::Double);
    EXPECT_EQ(registry.Get("INTEGRATION_ORDER_CONTACT").Type(), VariableType::Integer);
    EXPECT_EQ(registry.Get("TYING_VARIABLE").Type(), VariableType::String);
    EXPECT_EQ(registry.Get("WEIGHTED_SLIP_Z").ComponentIndex(), 2);
    EXPECT_EQ(registry.Get("CAUCHY_STRESS_VECTOR").Type(), VariableType::Vector);
    EXPECT_EQ(&registry.GetTyped<double>("YOUNG_MODULUS"), &YOUNG_MODULUS);
    EXPECT_THROW(registry.GetTyped<int>("YOUNG_MODULUS"), InputError);
    for (std::size_t key = 0; key < registry.Size(); ++key) EXPECT_EQ(registry.ByKey(key).Key(), key);
    try {
        registry.Get("WEIGHTED_GAPP");
        FAIL();
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("did you mean \"WEIGHTED_GAP\""), std::string::npos);
    }
}

TEST(Table, InterpolatesAndExtrapolatesLinearly) {
    Table table("TIME", "PRESSURE");
    table.PushBack(1.0, 10.0);
    table.PushBack(0.0, 0.0);
    table.PushBack(2.0, 30.0);
    EXPECT_DOUBLE_EQ(table.GetValue(0.5), 5.0);
    EXPECT_DOUBLE_EQ(table.GetValue(1.5), 20.0);
    EXPECT_DOUBLE_EQ(table.GetValue(3.0), 50.0);
    EXPECT_DOUBLE_EQ(table.GetValue(-1.0), -10.0);
    EXPECT_DOUBLE_EQ(table.GetDerivative(1.5), 20.0);
    EXPECT_THROW(table.PushBack(1.0, 3.0), InputError);
    EXPECT_THROW(Table().GetValue(0.0), InputError);
}

TEST(EntityContainer, BulkInsertionSortsAndDetectsClashes) {
    EntityContainer<Node> nodes;
    std::vector<Node::Pointer> batch;
    for (IndexType id : {5, 2, 9, 1}) batch.push_back(std::make_shared<Node>(id, 0.0, 0.0, 0.0));
    EXPECT_FALSE(nodes.InsertMany(batch).has_value());
    EXPECT_FALSE(nodes.InsertMany(batch).has_value());  // same objects again: no-op
    EXPECT_EQ(nodes.size(), 4u);
    EXPECT_EQ(nodes[0].Id(), 1u);
    EXPECT_EQ(nodes.MaxId(), 9u);
    const auto clash = nodes.InsertMany({std::make_shared<Node>(2, 1.0, 0.0, 0.0)});
    ASSERT_TRUE(clash.has_value());
    EXPECT_EQ(*clash, 2u);
    EXPECT_EQ(nodes.size(), 4u);
    EXPECT_TRUE(nodes.Erase(5));
    EXPECT_FALSE(nodes.Contains(5));
}

}  // namespace
}  // namespace contact_app
