// SPDX-License-Identifier: BSD-3-Clause
// Interface preprocessing on the Kratos reference meshes and small hand-built ones: interface condition counts,
// outward normals, reuse, flags, properties; the nodal size, normal check and master/slave processes.
#include <string>

#include <gtest/gtest.h>

#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/io/model_part_io.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/model.h"
#include "custom_processes/find_nodal_h_process.h"
#include "custom_processes/interface_preprocess_condition.h"
#include "custom_processes/master_slave_process.h"
#include "custom_processes/normal_check_process.h"
#include "custom_utilities/contact_utilities.h"
#include "tests/cpp/kratos_cases.h"

namespace contact_app {
namespace {

ModelPart& ReadReference(Model& model, const std::string& file) {
    RegisterContactApplication();
    ModelPart& part = model.CreateModelPart("Structure", 2);
    part.AddNodalSolutionStepVariable(DISPLACEMENT);
    part.AddNodalSolutionStepVariable(NODAL_H);
    ModelPartIO(std::string(CONTACT_APP_KRATOS_CASES) + "/" + file).ReadModelPart(part);
    return part;
}

/// The root element holding every node of @p geometry.
const Element& Parent(const ModelPart& root, const Geometry& face) {
    for (const auto& element : root.Elements()) {
        std::size_t found = 0;
        for (std::size_t i = 0; i < face.size(); ++i)
            for (std::size_t j = 0; j < element->GetGeometry().size(); ++j)
                found += element->GetGeometry()[j].Id() == face[i].Id() ? 1 : 0;
        if (found == face.size()) return *element;
    }
    throw std::runtime_error("no parent element");
}

/// Unit normal at the reference centre (lines and quadrilaterals: 0; triangles: (1/3, 1/3)).
Array3 CenterNormal(const Geometry& face) {
    return face.UnitNormal(face.size() == 3 ? Array3(1.0 / 3, 1.0 / 3, 0) : Array3(Array3::Zero()));
}

/// Every condition of @p part points out of its parent element: n · (face centre − element centre) > 0.
void ExpectOutwardNormals(const ModelPart& part) {
    for (const auto& condition : part.Conditions()) {
        const Geometry& face = condition->GetGeometry();
        const Element& parent = Parent(part.GetRootModelPart(), face);
        const double outward = CenterNormal(face).dot(face.Center() - parent.GetGeometry().Center());
        EXPECT_GT(outward, 0.0) << "condition " << condition->Id() << " on " << face.NodeIdsString();
    }
}

TEST(InterfacePreprocess, test_2d_patch_nodes_only_part_gets_one_line_per_body) {
    CONTACT_SKIP_WITHOUT_KRATOS_CASES();
    Model model;
    ModelPart& root = ReadReference(model, "ALM_frictionless_contact_test_2D/hyper_simple_patch_test");
    ModelPart& contact = root.GetSubModelPart("Contact_Part");
    ASSERT_EQ(contact.NumberOfConditions(), 0u);
    InterfacePreprocessCondition preprocess(root);
    // Contact_Part holds nodes 3, 4 (top edge of element 1) and 5, 6 (bottom edge of element 2).
    EXPECT_EQ(preprocess.GenerateInterfacePart(contact), 2u);
    ASSERT_EQ(contact.NumberOfConditions(), 2u);
    EXPECT_EQ(root.NumberOfConditions(), 2u);
    ExpectOutwardNormals(contact);
    for (const auto& condition : contact.Conditions()) {
        EXPECT_EQ(condition->GetGeometry().Name(), "Line2D2");
        EXPECT_TRUE(condition->Is(INTERFACE));
        const double expected_y = condition->GetGeometry()[0].Id() <= 4 ? 1.0 : -1.0;  // body 1 below, body 2 above
        EXPECT_NEAR(CenterNormal(condition->GetGeometry())[1], expected_y, 1e-14);
        EXPECT_EQ(condition->pGetProperties(), Parent(root, condition->GetGeometry()).pGetProperties());
    }
    for (const auto& node : contact.Nodes()) EXPECT_TRUE(node->Is(INTERFACE));
    // Idempotent: the existing interface conditions are reused.
    EXPECT_EQ(preprocess.GenerateInterfacePart(contact), 0u);
    EXPECT_EQ(root.NumberOfConditions(), 2u);
    // Another part over the same nodes reuses the interface condition instead of duplicating it.
    ModelPart& side = root.GetSubModelPart("Contact_Part_1");
    EXPECT_EQ(preprocess.GenerateInterfacePart(side), 0u);
    EXPECT_EQ(side.NumberOfConditions(), 1u);
    EXPECT_EQ(root.NumberOfConditions(), 2u);
}

TEST(InterfacePreprocess, test_2d_taylor_patch_ids_continue_after_the_load_conditions) {
    CONTACT_SKIP_WITHOUT_KRATOS_CASES();
    Model model;
    ModelPart& root = ReadReference(model, "ALM_frictionless_contact_test_2D/taylor_patch_test");
    const IndexType max_id = root.Conditions().MaxId();
    ModelPart& contact = root.GetSubModelPart("Contact_Part");
    InterfacePreprocessCondition preprocess(root);
    // Foundation top y = 5: x = 0, 2, 4, 5, 6, 7, 8 (6 edges); punch bottom: x = 4, 4.67, 5.33, 6 (3 edges).
    ASSERT_EQ(preprocess.GenerateInterfacePart(contact, false, 3), 9u);
    ExpectOutwardNormals(contact);
    IndexType expected_id = max_id;
    for (const auto& condition : contact.Conditions()) {
        EXPECT_EQ(condition->Id(), ++expected_id);
        EXPECT_EQ(condition->pGetProperties()->Id(), 3u);
        const bool foundation = root.GetSubModelPart("Parts_foundation").HasNode(condition->GetGeometry()[0].Id());
        EXPECT_NEAR(CenterNormal(condition->GetGeometry())[1], foundation ? 1.0 : -1.0, 1e-14);
    }
}

TEST(InterfacePreprocess, test_3d_sloped_patch_gets_two_quadrilaterals) {
    CONTACT_SKIP_WITHOUT_KRATOS_CASES();
    Model model;
    ModelPart& root = ReadReference(model, "ALM_frictionless_contact_test_3D/3D_contact_simplest_patch_matching_slope_test");
    ModelPart& contact = root.GetSubModelPart("Contact_Part");
    for (const auto& node : root.GetSubModelPart("Parts_Parts_Nodes1").Nodes()) node->Set(SLAVE, true);
    for (const auto& node : root.GetSubModelPart("Parts_Parts_Nodes2").Nodes()) node->Set(MASTER, true);
    InterfacePreprocessCondition preprocess(root);
    ASSERT_EQ(preprocess.GenerateInterfacePart(contact), 2u);
    EXPECT_EQ(root.NumberOfConditions(), 3u);  // plus the surface load
    ExpectOutwardNormals(contact);
    for (const auto& condition : contact.Conditions()) {
        EXPECT_EQ(condition->GetGeometry().Name(), "Quadrilateral3D4");
        EXPECT_GT(condition->Id(), 1u);
        const bool upper_body = root.GetSubModelPart("Parts_Parts_Nodes1").HasNode(condition->GetGeometry()[0].Id());
        EXPECT_EQ(condition->Is(SLAVE), upper_body);
        EXPECT_EQ(condition->Is(MASTER), !upper_body);
        // The upper body's lower face looks down, the lower body's upper face up.
        EXPECT_LT(CenterNormal(condition->GetGeometry())[2] * (upper_body ? 1.0 : -1.0), -0.5);
    }
}

TEST(InterfacePreprocess, test_whole_skin_of_the_main_model_part) {
    CONTACT_SKIP_WITHOUT_KRATOS_CASES();
    Model model2d, model3d;
    ModelPart& root2d = ReadReference(model2d, "ALM_frictionless_contact_test_2D/hyper_simple_patch_test");
    ModelPart& skin2d = root2d.CreateSubModelPart("Contact").CreateSubModelPart("ContactSub0");
    EXPECT_EQ(InterfacePreprocessCondition(root2d).GenerateSkinModelPart(skin2d), 2u * 4u);  // two separate quads
    EXPECT_EQ(skin2d.NumberOfNodes(), 8u);
    EXPECT_EQ(root2d.GetSubModelPart("Contact").NumberOfConditions(), 8u);
    ExpectOutwardNormals(skin2d);
    ModelPart& root3d =
        ReadReference(model3d, "ALM_frictionless_contact_test_3D/3D_contact_simplest_patch_matching_slope_test");
    ModelPart& skin3d = root3d.CreateSubModelPart("Skin");
    EXPECT_EQ(InterfacePreprocessCondition(root3d).GenerateSkinModelPart(skin3d), 2u * 6u);  // two separate hexahedra
    ExpectOutwardNormals(skin3d);
}

/// A unit square split into two elements sharing the edge x = 1 (given node orders); nodes 1..6.
ModelPart& TwoQuads(Model& model, bool clockwise_first) {
    RegisterContactApplication();
    ModelPart& root = model.CreateModelPart("Structure");
    const double coordinates[6][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}, {2, 1}};
    for (int i = 0; i < 6; ++i) root.CreateNewNode(i + 1, coordinates[i][0], coordinates[i][1], 0.0);
    auto properties = root.CreateNewProperties(1);
    root.CreateNewElement("Element2D4N", 1, clockwise_first ? std::vector<IndexType>{1, 4, 3, 2}
                                                            : std::vector<IndexType>{1, 2, 3, 4},
                          properties);
    root.CreateNewElement("Element2D4N", 2, {2, 5, 6, 3}, properties);
    return root;
}

TEST(InterfacePreprocess, test_inverted_element_and_inner_faces) {
    Model model;
    ModelPart& root = TwoQuads(model, true);
    ModelPart& part = root.CreateSubModelPart("Interface");
    part.AddNodes({2, 3, 4});  // edge 2-3 is shared by both elements: not a boundary face
    EXPECT_EQ(InterfacePreprocessCondition(root).GenerateInterfacePart(part), 1u);  // only the top edge 3-4
    ExpectOutwardNormals(part);
    EXPECT_NEAR(CenterNormal(part.Conditions()[0].GetGeometry())[1], 1.0, 1e-14);
}

TEST(InterfacePreprocess, test_quadratic_elements_need_simplify_geometry) {
    RegisterContactApplication();
    Model model;
    ModelPart& root = model.CreateModelPart("Structure");
    const double coordinates[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
    for (int i = 0; i < 6; ++i) root.CreateNewNode(i + 1, coordinates[i][0], coordinates[i][1], 0.0);
    root.CreateNewElement("Element2D6N", 1, {1, 2, 3, 4, 5, 6}, root.CreateNewProperties(1));
    ModelPart& part = root.CreateSubModelPart("Interface");
    part.AddNodes({1, 2, 4});
    InterfacePreprocessCondition preprocess(root);
    try {
        preprocess.GenerateInterfacePart(part);
        ADD_FAILURE() << "expected InputError";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("simplify_geometry"), std::string::npos) << error.what();
    }
    ASSERT_EQ(preprocess.GenerateInterfacePart(part, true), 1u);
    EXPECT_EQ(part.Conditions()[0].GetGeometry().NodeIdsString(), "[1, 2]");
}

TEST(InterfacePreprocess, test_find_nodal_h_on_a_regular_grid) {
    RegisterContactApplication();
    for (const bool historical : {true, false}) {
        Model model;
        ModelPart& root = model.CreateModelPart("Structure");
        if (historical) root.AddNodalSolutionStepVariable(NODAL_H);
        // 3 × 2 quadrilaterals of 0.5 × 0.25: every node's shortest element edge is 0.25.
        const int nx = 3, ny = 2;
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) root.CreateNewNode(1 + i + j * (nx + 1), 0.5 * i, 0.25 * j, 0.0);
        auto properties = root.CreateNewProperties(1);
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const IndexType a = 1 + i + j * (nx + 1);
                root.CreateNewElement("Element2D4N", 1 + i + j * nx, {a, a + 1, a + nx + 2, a + nx + 1}, properties);
            }
        root.CreateNewNode(99, 5.0, 5.0, 0.0);  // isolated: 0
        FindNodalHProcess(root).Execute();
        for (const auto& node : root.Nodes()) {
            const double h = historical ? node->FastGetSolutionStepValue(NODAL_H) : node->GetValue(NODAL_H);
            EXPECT_DOUBLE_EQ(h, node->Id() == 99 ? 0.0 : 0.25) << node->Id();
            EXPECT_DOUBLE_EQ(ContactUtilities::NodalH(*node), h);
        }
    }
}

TEST(InterfacePreprocess, test_find_nodal_h_on_the_2d_patch) {
    CONTACT_SKIP_WITHOUT_KRATOS_CASES();
    Model model;
    ModelPart& root = ReadReference(model, "ALM_frictionless_contact_test_2D/hyper_simple_patch_test");
    FindNodalHProcess(root).Execute();
    for (IndexType id = 1; id <= 8; ++id)  // unit square, then a 1 × 0.999 rectangle
        EXPECT_NEAR(root.GetNode(id).FastGetSolutionStepValue(NODAL_H), id <= 4 ? 1.0 : 0.999, 1e-14) << id;
}

TEST(InterfacePreprocess, test_normal_check_flips_inward_conditions_only) {
    Model model;
    ModelPart& root = TwoQuads(model, false);
    ModelPart& part = root.CreateSubModelPart("Contact").CreateSubModelPart("Sub");
    auto properties = root.pGetProperties(1);
    // Counter-clockwise element edges point out: 1→2 and 5→6 do, 4→3 and 6→5 point in.
    part.CreateNewCondition("LineCondition2D2N", 1, {1, 2}, properties);
    auto wrong = part.CreateNewCondition("LineCondition2D2N", 2, {4, 3}, properties);
    wrong->Set(SLAVE, true);
    wrong->SetValue(NODAL_AREA, 4.5);
    part.CreateNewCondition("LineCondition2D2N", 3, {5, 6}, properties);
    part.CreateNewCondition("LineCondition2D2N", 4, {6, 5}, properties);
    NormalCheckProcess check(root.GetSubModelPart("Contact"));
    check.Execute();
    EXPECT_EQ(check.NumberOfFlippedConditions(), 2u);
    ExpectOutwardNormals(part);
    const Condition& flipped = root.GetSubModelPart("Contact.Sub").GetCondition(2);
    EXPECT_EQ(flipped.GetGeometry().NodeIdsString(), "[3, 4]");
    EXPECT_TRUE(flipped.Is(SLAVE));
    EXPECT_TRUE(flipped.Is(MARKER));
    EXPECT_DOUBLE_EQ(flipped.GetValue(NODAL_AREA), 4.5);
    EXPECT_EQ(&root.GetCondition(2), &flipped);
    check.Execute();
    EXPECT_EQ(check.NumberOfFlippedConditions(), 0u);
    EXPECT_THROW(NormalCheckProcess(root, 0.0), InputError);
}

TEST(InterfacePreprocess, test_normal_check_in_3d) {
    CONTACT_SKIP_WITHOUT_KRATOS_CASES();
    Model model;
    ModelPart& root = ReadReference(model, "ALM_frictionless_contact_test_3D/3D_contact_simplest_patch_matching_slope_test");
    ModelPart& contact = root.GetSubModelPart("Contact_Part");
    InterfacePreprocessCondition(root).GenerateInterfacePart(contact);
    NormalCheckProcess check(contact);
    check.Execute();
    EXPECT_EQ(check.NumberOfFlippedConditions(), 0u);
    // A copy of one interface face with the reversed node order points into its element.
    const Geometry& face = contact.Conditions()[0].GetGeometry();
    ModelPart& wrong = root.CreateSubModelPart("Wrong");
    wrong.CreateNewCondition("SurfaceCondition3D4N", 100, {face[0].Id(), face[3].Id(), face[2].Id(), face[1].Id()},
                             root.pGetProperties(0));
    NormalCheckProcess whole(root);
    whole.Execute();
    EXPECT_EQ(whole.NumberOfFlippedConditions(), 1u);
    EXPECT_TRUE(root.GetCondition(100).Is(MARKER));
    ExpectOutwardNormals(root);
}

TEST(InterfacePreprocess, test_master_slave_process_derives_flags) {
    Model model;
    ModelPart& root = TwoQuads(model, false);
    auto properties = root.pGetProperties(1);
    root.CreateNewCondition("LineCondition2D2N", 1, {3, 4}, properties);
    root.CreateNewCondition("LineCondition2D2N", 2, {5, 6}, properties);
    root.CreateNewCondition("LineCondition2D2N", 3, {6, 3}, properties);
    for (IndexType id : {3, 4, 6}) root.GetNode(id).Set(SLAVE, true);
    MasterSlaveProcess(root).Execute();
    EXPECT_TRUE(root.GetCondition(1).Is(SLAVE) && root.GetCondition(1).IsNot(MASTER));
    EXPECT_TRUE(root.GetCondition(2).Is(MASTER) && root.GetCondition(2).IsNot(SLAVE));
    EXPECT_TRUE(root.GetCondition(3).Is(SLAVE));
    EXPECT_TRUE(root.GetNode(5).Is(MASTER) && root.GetNode(5).IsNot(SLAVE));
    EXPECT_TRUE(root.GetNode(6).Is(SLAVE) && root.GetNode(6).IsNot(MASTER));
}

}  // namespace
}  // namespace contact_app
