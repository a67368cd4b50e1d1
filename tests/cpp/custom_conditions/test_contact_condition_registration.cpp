// SPDX-License-Identifier: BSD-3-Clause
/// The contact condition table: the ALM / penalty contact names are the 58 of docs/registered_conditions.md (registered
/// names), decoded consistently.
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
        "PenaltyFrictionlessMortarContactCondition3D4N3N", "PenaltyNVFrictionlessMortarContactCondition3D4N3N",
        "ALMFrictionalMortarContactCondition2D2N", "ALMNVFrictionalMortarContactCondition2D2N",
        "ALMFrictionalAxisymMortarContactCondition2D2N", "ALMNVFrictionalAxisymMortarContactCondition2D2N",
        "ALMFrictionalMortarContactCondition3D3N", "ALMNVFrictionalMortarContactCondition3D3N",
        "ALMFrictionalMortarContactCondition3D4N", "ALMNVFrictionalMortarContactCondition3D4N",
        "ALMFrictionalMortarContactCondition3D3N4N", "ALMNVFrictionalMortarContactCondition3D3N4N",
        "ALMFrictionalMortarContactCondition3D4N3N", "ALMNVFrictionalMortarContactCondition3D4N3N",
        "PenaltyFrictionalMortarContactCondition2D2N", "PenaltyNVFrictionalMortarContactCondition2D2N",
        "PenaltyFrictionalAxisymMortarContactCondition2D2N", "PenaltyNVFrictionalAxisymMortarContactCondition2D2N",
        "PenaltyFrictionalMortarContactCondition3D3N", "PenaltyNVFrictionalMortarContactCondition3D3N",
        "PenaltyFrictionalMortarContactCondition3D4N", "PenaltyNVFrictionalMortarContactCondition3D4N",
        "PenaltyFrictionalMortarContactCondition3D3N4N", "PenaltyNVFrictionalMortarContactCondition3D3N4N",
        "PenaltyFrictionalMortarContactCondition3D4N3N", "PenaltyNVFrictionalMortarContactCondition3D4N3N"};
    ASSERT_EQ(spec.size(), 58u);
    // The ALM / Penalty contact names decoded by the table are exactly the spec's 58 (other families may be added).
    std::vector<std::string> names;
    for (const auto& row : RegisteredContactConditionNames())
        if (row.name.rfind("ALM", 0) == 0 || row.name.rfind("Penalty", 0) == 0) names.push_back(row.name);
    std::sort(names.begin(), names.end());
    auto sorted_spec = spec;
    std::sort(sorted_spec.begin(), sorted_spec.end());
    EXPECT_EQ(names, sorted_spec);
    for (const auto& name : spec) EXPECT_TRUE(Registry<Condition>::Instance().Has(name)) << name;
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

namespace contact_app::testing {
namespace {

TEST(ContactConditionRegistration, MeshTyingAndMPCNamesAreRegisteredAndDecoded) {
    RegisterContactConditions();
    const std::vector<std::tuple<std::string, int, int, int, int, int>> pairs = {
        // suffix, dim, n_s, n_m, mesh-tying size (DISPLACEMENT), MPC size
        {"2D2N", 2, 2, 2, 12, 8}, {"3D3N", 3, 3, 3, 27, 18}, {"3D4N", 3, 4, 4, 36, 24},
        {"3D3N4N", 3, 3, 4, 30, 21}, {"3D4N3N", 3, 4, 3, 33, 21}};
    int found = 0;
    for (const auto& [suffix, dim, ns, nm, tying_size, mpc_size] : pairs)
        for (const auto& [family, size] :
             {std::pair<std::string, int>{"MeshTying", tying_size}, std::pair<std::string, int>{"MPC", mpc_size}}) {
            const std::string name =
                family + (family == "MeshTying" ? "MortarCondition" : "MortarContactCondition") + suffix;
            ASSERT_TRUE(Registry<Condition>::Instance().Has(name)) << name;
            const auto& row = DecodedName(name);
            EXPECT_EQ(row.family, family) << name;
            EXPECT_FALSE(row.normal_variation) << name;
            EXPECT_FALSE(row.axisymmetric) << name;
            EXPECT_EQ(row.dim, dim) << name;
            EXPECT_EQ(row.num_slave, ns) << name;
            EXPECT_EQ(row.num_master, nm) << name;
            EXPECT_EQ(row.matrix_size, size) << name;
            ++found;
        }
    EXPECT_EQ(found, 10);
    for (const auto& row : RegisteredContactConditionNames())
        if (row.family == "MeshTying" || row.family == "MPC") --found;
    EXPECT_EQ(found, 0);  // no NV / axisymmetric variants
    EXPECT_FALSE(Registry<Condition>::Instance().Has("MeshTyingNVMortarCondition2D2N"));
    EXPECT_FALSE(Registry<Condition>::Instance().Has("MPCNVMortarContactCondition2D2N"));
}

}  // namespace
}  // namespace contact_app::testing
