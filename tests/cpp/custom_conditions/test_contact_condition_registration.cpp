// SPDX-License-Identifier: BSD-3-Clause
/// The contact condition table: registered names are the spec's ALM frictionless, ALM frictionless components and
/// penalty frictionless names (condition_classes.md, registered names), decoded consistently.
#include <algorithm>

#include "contact_condition_test_utilities.h"

namespace contact_app::testing {
namespace {

TEST(ContactConditionRegistration, RegistersExactlyTheImplementedFamiliesNames) {
    RegisterContactConditions();
    RegisterContactConditions();  // idempotent
    const std::vector<std::string> spec = {
        "ALMFrictionlessMortarContactCondition2D2N", "ALMNVFrictionlessMortarContactCondition2D2N",
        "ALMFrictionlessAxisymMortarContactCondition2D2N", "ALMNVFrictionlessAxisymMortarContactCondition2D2N",
        "ALMFrictionlessMortarContactCondition3D3N", "ALMNVFrictionlessMortarContactCondition3D3N",
        "ALMFrictionlessMortarContactCondition3D4N", "ALMNVFrictionlessMortarContactCondition3D4N",
        "ALMFrictionlessMortarContactCondition3D3N4N", "ALMNVFrictionlessMortarContactCondition3D3N4N",
        "ALMFrictionlessMortarContactCondition3D4N3N", "ALMNVFrictionlessMortarContactCondition3D4N3N",
        "ALMFrictionlessComponentsMortarContactCondition2D2N", "ALMNVFrictionlessComponentsMortarContactCondition2D2N",
        "ALMFrictionlessComponentsMortarContactCondition3D3N", "ALMNVFrictionlessComponentsMortarContactCondition3D3N",
        "ALMFrictionlessComponentsMortarContactCondition3D4N", "ALMNVFrictionlessComponentsMortarContactCondition3D4N",
        "ALMFrictionlessComponentsMortarContactCondition3D3N4N",
        "ALMNVFrictionlessComponentsMortarContactCondition3D3N4N",
        "ALMFrictionlessComponentsMortarContactCondition3D4N3N",
        "ALMNVFrictionlessComponentsMortarContactCondition3D4N3N",
        "PenaltyFrictionlessMortarContactCondition2D2N", "PenaltyNVFrictionlessMortarContactCondition2D2N",
        "PenaltyFrictionlessAxisymMortarContactCondition2D2N", "PenaltyNVFrictionlessAxisymMortarContactCondition2D2N",
        "PenaltyFrictionlessMortarContactCondition3D3N", "PenaltyNVFrictionlessMortarContactCondition3D3N",
        "PenaltyFrictionlessMortarContactCondition3D4N", "PenaltyNVFrictionlessMortarContactCondition3D4N",
        "PenaltyFrictionlessMortarContactCondition3D3N4N", "PenaltyNVFrictionlessMortarContactCondition3D3N4N",
        "PenaltyFrictionlessMortarContactCondition3D4N3N", "PenaltyNVFrictionlessMortarContactCondition3D4N3N"};
    ASSERT_EQ(spec.size(), 34u);
    auto names = RegisteredContactNames();
    std::sort(names.begin(), names.end());
    auto sorted_spec = spec;
    std::sort(sorted_spec.begin(), sorted_spec.end());
    EXPECT_EQ(names, sorted_spec);
    for (const auto& name : spec) EXPECT_TRUE(Registry<Condition>::Instance().Has(name)) << name;
    EXPECT_FALSE(Registry<Condition>::Instance().Has("ALMFrictionalMortarContactCondition2D2N"));
    EXPECT_FALSE(Registry<Condition>::Instance().Has("PenaltyFrictionalMortarContactCondition2D2N"));
    EXPECT_FALSE(Registry<Condition>::Instance().Has("ALMFrictionlessComponentsAxisymMortarContactCondition2D2N"));
}

TEST(ContactConditionRegistration, DecodedDimensionsMatchThePrototypeGeometries) {
    RegisterContactConditions();
    for (const auto& row : RegisteredContactConditionNames()) {
        const auto& prototype = dynamic_cast<const PairedCondition&>(Registry<Condition>::Instance().Get(row.name));
        EXPECT_EQ(static_cast<int>(prototype.GetParentGeometry().size()), row.num_slave) << row.name;
        EXPECT_EQ(static_cast<int>(prototype.GetPairedGeometry().size()), row.num_master) << row.name;
        EXPECT_EQ(prototype.GetParentGeometry().WorkingSpaceDimension(), row.dim) << row.name;
        EXPECT_EQ(row.name.find("NV") != std::string::npos, row.normal_variation) << row.name;
        EXPECT_EQ(row.name.find("Axisym") != std::string::npos, row.axisymmetric) << row.name;
    }
}

}  // namespace
}  // namespace contact_app::testing
