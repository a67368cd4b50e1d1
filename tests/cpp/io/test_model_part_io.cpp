// SPDX-License-Identifier: BSD-3-Clause
// Reading .mdpa files: the Kratos reference meshes and a table of malformed inputs.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/io/model_part_io.h"
#include "contact_app/kernel/model.h"
#include "contact_app/kernel/registry.h"
#include "contact_app/kernel/variables.h"
#include "tests/cpp/kratos_cases.h"

namespace contact_app {
namespace {

ModelPart& NewStructure(Model& model) {
    ModelPart& part = model.CreateModelPart("Structure", 2);
    part.AddNodalSolutionStepVariable(DISPLACEMENT);
    part.AddNodalSolutionStepVariable(REACTION);
    part.AddNodalSolutionStepVariable(TEMPERATURE);
    return part;
}

struct ReferenceCase {
    const char* file;
    std::size_t nodes, elements, conditions, sub_model_parts;
    const char* interface_part;
    std::size_t interface_nodes;
};

class ReferenceMeshTest : public ::testing::TestWithParam<ReferenceCase> {};

TEST_P(ReferenceMeshTest, ReadsTheCountsOfTheFile) {
    CONTACT_SKIP_WITHOUT_KRATOS_CASES();
    RegisterContactApplication();
    const ReferenceCase& reference = GetParam();
    Model model;
    ModelPart& part = NewStructure(model);
    ModelPartIO(std::string(CONTACT_APP_KRATOS_CASES) + "/" + reference.file).ReadModelPart(part);
    EXPECT_EQ(part.NumberOfNodes(), reference.nodes);
    EXPECT_EQ(part.NumberOfElements(), reference.elements);
    EXPECT_EQ(part.NumberOfConditions(), reference.conditions);
    EXPECT_EQ(part.NumberOfSubModelParts(), reference.sub_model_parts);
    EXPECT_EQ(part.GetSubModelPart(reference.interface_part).NumberOfNodes(), reference.interface_nodes);
    EXPECT_TRUE(part.HasProperties(0));
    // Every element node is a node of the root, and sub model part entities belong to the root.
    for (const auto& element : part.Elements())
        for (std::size_t i = 0; i < element->GetGeometry().PointsNumber(); ++i)
            EXPECT_TRUE(part.HasNode(element->GetGeometry()[i].Id()));
    for (ModelPart* sub : part.SubModelParts())
        for (const auto& node : sub->Nodes()) EXPECT_EQ(part.pGetNode(node->Id()), node);
}

INSTANTIATE_TEST_SUITE_P(
    KratosCases, ReferenceMeshTest,
    ::testing::Values(
        ReferenceCase{"ALM_frictional_contact_test_2D/hyper_simple_patch_test", 8, 2, 0, 6, "Contact_Part", 4},
        ReferenceCase{"ALM_frictionless_contact_test_2D/hyper_simple_patch_test", 8, 2, 0, 8, "Contact_Part", 4},
        ReferenceCase{"ALM_frictionless_contact_test_2D/taylor_patch_test", 37, 21, 7, 7, "Contact_Part", 11},
        ReferenceCase{"ALM_frictionless_contact_test_3D/3D_contact_simplest_patch_matching_slope_test", 16, 2, 1, 8,
                      "Contact_Part", 8},
        ReferenceCase{"mesh_tying_test/simple_patch_test_2D", 24, 12, 0, 6, "Tying_Part", 8},
        ReferenceCase{"mpc_contact_tests/2D_contact_simplest_patch_matching_test", 8, 2, 2, 6, "Contact_Part_Slave", 2},
        ReferenceCase{"penalty_frictional_contact_test_2D/hyper_simple_patch_test", 8, 2, 0, 6, "Contact_Part", 4},
        ReferenceCase{"penalty_frictionless_contact_test_2D/hyper_simple_patch_test", 8, 2, 0, 6, "Contact_Part", 4}));

/// Writes @p text to a temporary .mdpa file and returns its path without the extension.
std::string WriteMdpa(const std::string& name, const std::string& text) {
    const auto path = std::filesystem::temp_directory_path() / ("contact_app_test_" + name);
    std::ofstream(path.string() + ".mdpa") << text;
    return path.string();
}

const char* const kValidMesh = R"(Begin ModelPartData
// a comment line
End ModelPartData
Begin Properties 1
  YOUNG_MODULUS 2.1e5
  POISSON_RATIO 0.3
  VOLUME_ACCELERATION [3] (0.0, -9.81, 0.0)
  Begin Table TEMPERATURE YOUNG_MODULUS
    0.0 1.0
    100.0 0.5
  End Table
End Properties
Begin Table 7 TIME PRESSURE
  0.0 0.0
  1.0 10.0
End Table
Begin Nodes
  3 1.0 1.0 0.0
  1 0.0 0.0 0.0
  2 1.0 0.0 0.0
  4 0.0 1.0 0.0
End Nodes
Begin Elements Element2D4N// GUI group identifier: glued comment
  1 1 1 2 3 4
End Elements
Begin Conditions LineCondition2D2N
  5 1 1 2
End Conditions
Begin Geometries Triangle2D3
  9 1 2 3
End Geometries
Begin Constraints LinearMasterSlaveConstraint DISPLACEMENT_X
  1 0.0 [0.25, 0.75] 4 1 2
End Constraints
Begin NodalData DISPLACEMENT_Y
  1 1 0.5
  2 0 -0.25
End NodalData
Begin NodalData DISPLACEMENT
  3 0 [3](1.0,2.0,3.0)
End NodalData
Begin NodalData SLAVE
  4
End NodalData
Begin ElementalData THICKNESS
  1 0.1
End ElementalData
Begin ConditionalData PRESSURE
  5 3.5
End ConditionalData
Begin SubModelPart Outer
  Begin SubModelPartData
    DENSITY 7850.0
  End SubModelPartData
  Begin SubModelPartTables
    7
  End SubModelPartTables
  Begin SubModelPartNodes
    1 2
  End SubModelPartNodes
  Begin SubModelPart Inner
    Begin SubModelPartNodes
      3
    End SubModelPartNodes
    Begin SubModelPartConditions
      5
    End SubModelPartConditions
  End SubModelPart
End SubModelPart
)";

TEST(ModelPartIO, ReadsEveryBlockKindWithItsValues) {
    RegisterContactApplication();
    Model model;
    ModelPart& part = NewStructure(model);
    ModelPartIO(WriteMdpa("valid", kValidMesh)).ReadModelPart(part);

    EXPECT_EQ(part.NumberOfNodes(), 4u);
    EXPECT_EQ(part.Nodes()[0].Id(), 1u);  // sorted by id although listed out of order
    const Properties& properties = part.GetProperties(1);
    EXPECT_DOUBLE_EQ(properties.GetValue(YOUNG_MODULUS), 2.1e5);
    EXPECT_DOUBLE_EQ(properties.GetValue(VOLUME_ACCELERATION)[1], -9.81);
    EXPECT_DOUBLE_EQ(properties.GetTable(TEMPERATURE, YOUNG_MODULUS).GetValue(50.0), 0.75);
    EXPECT_DOUBLE_EQ(part.GetTable(7).GetValue(0.5), 5.0);
    EXPECT_EQ(part.GetElement(1).GetGeometry().Name(), "Quadrilateral2D4");
    EXPECT_DOUBLE_EQ(part.GetElement(1).GetGeometry().Area(), 1.0);
    EXPECT_EQ(&part.GetElement(1).GetProperties(), &properties);
    EXPECT_DOUBLE_EQ(part.GetElement(1).GetValue(THICKNESS), 0.1);
    EXPECT_DOUBLE_EQ(part.GetCondition(5).GetValue(PRESSURE), 3.5);
    EXPECT_EQ(part.pGetGeometry(9)->Name(), "Triangle2D3");

    const Node& node1 = part.GetNode(1);
    EXPECT_DOUBLE_EQ(node1.GetSolutionStepValue(DISPLACEMENT_Y), 0.5);
    EXPECT_TRUE(node1.IsFixed(DISPLACEMENT_Y));
    EXPECT_FALSE(part.GetNode(2).IsFixed(DISPLACEMENT_Y));
    EXPECT_DOUBLE_EQ(part.GetNode(2).GetSolutionStepValue(DISPLACEMENT_Y), -0.25);
    EXPECT_DOUBLE_EQ(part.GetNode(3).GetSolutionStepValue(DISPLACEMENT)[2], 3.0);
    EXPECT_TRUE(part.GetNode(4).Is(SLAVE));
    EXPECT_FALSE(part.GetNode(3).Is(SLAVE));

    ASSERT_EQ(part.NumberOfMasterSlaveConstraints(), 1u);
    Matrix relation;
    Vector constant;
    part.GetMasterSlaveConstraint(1).CalculateLocalSystem(relation, constant, part.GetProcessInfo());
    EXPECT_EQ(relation.rows(), 1);
    EXPECT_DOUBLE_EQ(relation(0, 1), 0.75);
    EXPECT_EQ(part.GetMasterSlaveConstraint(1).GetSlaveDofsVector()[0]->Id(), 4u);
    EXPECT_EQ(part.GetMasterSlaveConstraint(1).GetMasterDofsVector()[1]->Id(), 2u);

    ModelPart& outer = part.GetSubModelPart("Outer");
    EXPECT_DOUBLE_EQ(outer.GetValue(DENSITY), 7850.0);
    EXPECT_EQ(outer.NumberOfNodes(), 3u);  // 1, 2 and node 3 of the nested part
    EXPECT_EQ(outer.NumberOfTables(), 1u);
    ModelPart& inner = model.GetModelPart("Structure.Outer.Inner");
    EXPECT_EQ(inner.NumberOfNodes(), 1u);
    EXPECT_EQ(inner.NumberOfConditions(), 1u);
    EXPECT_TRUE(outer.HasCondition(5));
}

struct MalformedCase {
    const char* name;
    std::string text;
    int line;              // expected line in the message (0: no line, e.g. missing file)
    const char* contains;  // expected fragment of the reason
};

class MalformedMdpaTest : public ::testing::TestWithParam<MalformedCase> {};

TEST_P(MalformedMdpaTest, GivesFileLineAndReason) {
    RegisterContactApplication();
    const MalformedCase& bad = GetParam();
    Model model;
    ModelPart& part = NewStructure(model);
    const std::string path = WriteMdpa(bad.name, bad.text);
    try {
        ModelPartIO(path).ReadModelPart(part);
        FAIL() << "no error for " << bad.name;
    } catch (const InputError& error) {
        const std::string message = error.what();
        SCOPED_TRACE(message);
        EXPECT_NE(message.find(bad.contains), std::string::npos);
        if (bad.line > 0) EXPECT_NE(message.find(path + ".mdpa:" + std::to_string(bad.line) + ":"), std::string::npos);
    }
}

const std::string kNodes = "Begin Nodes\n 1 0 0 0\n 2 1 0 0\n 3 1 1 0\n 4 0 1 0\nEnd Nodes\n";  // lines 1-6

INSTANTIATE_TEST_SUITE_P(
    Table, MalformedMdpaTest,
    ::testing::Values(
        MalformedCase{"unknown_block", "Begin Nodez\nEnd Nodez\n", 1, "did you mean \"Nodes\""},
        MalformedCase{"missing_end", "Begin Nodes\n 1 0 0 0\n", 2, "ends inside the \"Nodes\" block opened at line 1"},
        MalformedCase{"wrong_end", "Begin Nodes\n 1 0 0 0\nEnd Elements\n", 3, "expected \"End Nodes\""},
        MalformedCase{"short_node_line", "Begin Nodes\n 1 0 0\nEnd Nodes\n", 2, "needs 4 values (id x y z), found 3"},
        MalformedCase{"bad_coordinate", "Begin Nodes\n 1 0 zero 0\nEnd Nodes\n", 2, "\"zero\" is not a valid coordinate y"},
        MalformedCase{"negative_node_id", "Begin Nodes\n -1 0 0 0\nEnd Nodes\n", 2, "not a valid node id"},
        MalformedCase{"duplicate_node", "Begin Nodes\n 1 0 0 0\n 1 1 0 0\nEnd Nodes\n", 3,
                      "node 1 is defined twice (first at line 2)"},
        MalformedCase{"unknown_element", kNodes + "Begin Elements Element2D4M\n 1 0 1 2 3 4\nEnd Elements\n", 7,
                      "did you mean \"Element2D4N\""},
        MalformedCase{"wrong_node_count", kNodes + "Begin Elements Element2D4N\n 1 0 1 2 3\nEnd Elements\n", 8,
                      "needs 4 node ids after its id and property id, found 3"},
        MalformedCase{"undefined_node", kNodes + "Begin Conditions LineCondition2D2N\n 1 0 1 9\nEnd Conditions\n", 8,
                      "uses node 9, which is not defined"},
        MalformedCase{"unknown_variable", "Begin Properties 0\n YOUNGS_MODULUS 1.0\nEnd Properties\n", 2,
                      "did you mean \"YOUNG_MODULUS\""},
        MalformedCase{"bad_vector", "Begin Properties 0\n VOLUME_ACCELERATION [3](1.0,2.0)\nEnd Properties\n", 2,
                      "is not a 3-vector"},
        MalformedCase{"nodal_data_not_historical", kNodes + "Begin NodalData PRESSURE\n 1 0 1.0\nEnd NodalData\n", 8,
                      "AddNodalSolutionStepVariable"},
        MalformedCase{"sub_model_part_unknown_node",
                      kNodes + "Begin SubModelPart A\n Begin SubModelPartNodes\n 1 77\n End SubModelPartNodes\nEnd SubModelPart\n",
                      10, "node 77"},
        MalformedCase{"unknown_sub_block", "Begin SubModelPart A\n Begin SubModelPartNode\n End SubModelPartNode\nEnd SubModelPart\n",
                      2, "did you mean \"SubModelPartNodes\""},
        MalformedCase{"text_outside_block", "Nodes 1 2 3\n", 1, "expected \"Begin <Block>\""},
        MalformedCase{"duplicate_element",
                      kNodes + "Begin Elements Element2D4N\n 1 0 1 2 3 4\nEnd Elements\nBegin Elements Element2D4N\n 1 0 1 2 3 4\nEnd Elements\n",
                      12, "element 1 is defined twice"},
        MalformedCase{"table_row", "Begin Table 1 TIME PRESSURE\n 0.0\nEnd Table\n", 2, "needs two numbers"}),
    [](const ::testing::TestParamInfo<MalformedCase>& info) { return std::string(info.param.name); });

const std::string kLine = kNodes + "Begin Conditions LineCondition2D2N\n";  // condition rows from line 8

// Numbers that are not finite, ids beyond what is stored, ids of 0, truncated lines, absurd sizes and
// bytes that are not text: each a file:line error (issue 16).
INSTANTIATE_TEST_SUITE_P(
    Untrusted, MalformedMdpaTest,
    ::testing::Values(
        MalformedCase{"nan_coordinate", "Begin Nodes\n 1 0 0 0\n 2 nan 0 0\nEnd Nodes\n", 3, "non-finite coordinate x \"nan\""},
        MalformedCase{"inf_coordinate", "Begin Nodes\n 1 0 0 -inf\nEnd Nodes\n", 2, "non-finite coordinate z \"-inf\""},
        MalformedCase{"overflowing_coordinate", "Begin Nodes\n 1 0 1e999 0\nEnd Nodes\n", 2,
                      "non-finite coordinate y \"1e999\""},
        MalformedCase{"node_id_beyond_64_bits", "Begin Nodes\n 99999999999999999999999 0 0 0\n 99999999999999999999998 1 0 0\nEnd Nodes\n",
                      2, "node id \"99999999999999999999999\" is beyond the largest id 9223372036854775807"},
        MalformedCase{"node_id_beyond_int64", "Begin Nodes\n 9223372036854775808 0 0 0\nEnd Nodes\n", 2,
                      "is beyond the largest id"},
        MalformedCase{"element_id_beyond_64_bits", kNodes + "Begin Elements Element2D4N\n 18446744073709551616 0 1 2 3 4\nEnd Elements\n",
                      8, "element id \"18446744073709551616\" is beyond"},
        MalformedCase{"condition_node_id_beyond_64_bits", kLine + " 1 0 1 99999999999999999999\nEnd Conditions\n", 8,
                      "node id \"99999999999999999999\" is beyond"},
        MalformedCase{"property_id_beyond_64_bits", "Begin Properties 123456789012345678901234567890\nEnd Properties\n", 1,
                      "property id \"123456789012345678901234567890\" is beyond"},
        MalformedCase{"table_id_beyond_64_bits", "Begin Table 99999999999999999999 TIME PRESSURE\nEnd Table\n", 1,
                      "table id \"99999999999999999999\" is beyond"},
        MalformedCase{"constraint_id_beyond_64_bits",
                      kNodes + "Begin Constraints LinearMasterSlaveConstraint DISPLACEMENT_X\n 99999999999999999999 0.0 [1.0] 1 2\nEnd Constraints\n",
                      8, "constraint id \"99999999999999999999\" is beyond"},
        MalformedCase{"sub_model_part_id_beyond_64_bits",
                      kNodes + "Begin SubModelPart A\n Begin SubModelPartNodes\n 1 99999999999999999999\n End SubModelPartNodes\nEnd SubModelPart\n",
                      9, "is beyond the largest id"},
        MalformedCase{"element_id_zero", kNodes + "Begin Elements Element2D4N\n 0 0 1 2 3 4\nEnd Elements\n", 8, "element id 0 is invalid"},
        MalformedCase{"condition_id_zero", kLine + " 0 0 1 2\nEnd Conditions\n", 8, "condition id 0 is invalid"},
        MalformedCase{"geometry_id_zero", kNodes + "Begin Geometries Triangle2D3\n 0 1 2 3\nEnd Geometries\n", 8, "geometry id 0 is invalid"},
        MalformedCase{"constraint_id_zero",
                      kNodes + "Begin Constraints LinearMasterSlaveConstraint DISPLACEMENT_X\n 0 0.0 [1.0] 1 2\nEnd Constraints\n",
                      8, "constraint id 0"},
        MalformedCase{"negative_element_id", kNodes + "Begin Elements Element2D4N\n -3 0 1 2 3 4\nEnd Elements\n", 8,
                      "\"-3\" is not a valid element id"},
        MalformedCase{"negative_node_in_condition", kLine + " 1 0 1 -2\nEnd Conditions\n", 8, "\"-2\" is not a valid node id"},
        MalformedCase{"nan_nodal_data", kNodes + "Begin NodalData DISPLACEMENT_X\n 2 1 nan\nEnd NodalData\n", 8,
                      "non-finite nodal value \"nan\""},
        MalformedCase{"inf_nodal_vector", kNodes + "Begin NodalData DISPLACEMENT\n 2 0 [3](0,inf,0)\nEnd NodalData\n", 8,
                      "non-finite vector component \"inf\""},
        MalformedCase{"nan_elemental_data",
                      kNodes + "Begin Elements Element2D4N\n 1 0 1 2 3 4\nEnd Elements\nBegin ElementalData THICKNESS\n 1 NaN\nEnd ElementalData\n",
                      11, "non-finite real value \"NaN\""},
        MalformedCase{"inf_conditional_data", kLine + " 1 0 1 2\nEnd Conditions\nBegin ConditionalData PRESSURE\n 1 infinity\nEnd ConditionalData\n",
                      11, "non-finite real value \"infinity\""},
        MalformedCase{"nan_property", "Begin Properties 1\n YOUNG_MODULUS 2e5\n POISSON_RATIO nan\nEnd Properties\n", 3,
                      "non-finite real value \"nan\""},
        MalformedCase{"overflowing_property", "Begin Properties 1\n DENSITY -1e400\nEnd Properties\n", 2, "non-finite real value \"-1e400\""},
        MalformedCase{"nan_model_part_data", "Begin ModelPartData\n TIME nan\nEnd ModelPartData\n", 2, "non-finite real value"},
        MalformedCase{"nan_property_table", "Begin Properties 1\n Begin Table TEMPERATURE YOUNG_MODULUS\n 0 1\n nan 2\n End Table\nEnd Properties\n",
                      4, "non-finite table x \"nan\""},
        MalformedCase{"inf_table", "Begin Table 1 TIME PRESSURE\n 0.0 0.0\n 1.0 inf\nEnd Table\n", 3, "non-finite table y \"inf\""},
        MalformedCase{"nan_constraint_constant",
                      kNodes + "Begin Constraints LinearMasterSlaveConstraint DISPLACEMENT_X\n 1 nan [1.0] 1 2\nEnd Constraints\n",
                      8, "non-finite constraint constant \"nan\""},
        MalformedCase{"inf_constraint_weight",
                      kNodes + "Begin Constraints LinearMasterSlaveConstraint DISPLACEMENT_X\n 1 0 [0.5, inf] 1 2 3\nEnd Constraints\n",
                      8, "non-finite vector component \"inf\""},
        MalformedCase{"nan_matrix_entry", "Begin Properties 1\n CONSTITUTIVE_MATRIX [2,2]((1,0),(0,nan))\nEnd Properties\n", 2,
                      "non-finite matrix entry \"nan\""},
        MalformedCase{"absurd_matrix_columns", "Begin Properties 1\n CONSTITUTIVE_MATRIX [1,999999999999]((1))\nEnd Properties\n", 2,
                      "has 1 entries, expected 999999999999"},
        MalformedCase{"absurd_vector_size", "Begin Properties 1\n INITIAL_STRAIN_VECTOR [99999999999999999999](1,2)\nEnd Properties\n", 2,
                      "vector size \"99999999999999999999\" is beyond"},
        MalformedCase{"integer_beyond_int", "Begin Properties 1\n DOMAIN_SIZE -99999999999\nEnd Properties\n", 2,
                      "integer value \"-99999999999\" is beyond the range of an integer"},
        MalformedCase{"truncated_element", kNodes + "Begin Elements Element2D4N\n 1\nEnd Elements\n", 8,
                      "needs 4 node ids after its id and property id, found 0"},
        MalformedCase{"truncated_constraint",
                      kNodes + "Begin Constraints LinearMasterSlaveConstraint DISPLACEMENT_X\n 1 0.0 [1.0]\nEnd Constraints\n", 8,
                      "a constraint line needs"},
        MalformedCase{"truncated_nodal_data", kNodes + "Begin NodalData DISPLACEMENT_X\n 2\nEnd NodalData\n", 8,
                      "needs: node_id is_fixed value, found 1 words"},
        MalformedCase{"truncated_elemental_data",
                      kNodes + "Begin Elements Element2D4N\n 1 0 1 2 3 4\nEnd Elements\nBegin ElementalData THICKNESS\n 1\nEnd ElementalData\n",
                      11, "needs: id value, found 1 words"},
        MalformedCase{"truncated_property", "Begin Properties 1\n YOUNG_MODULUS\nEnd Properties\n", 2, "has no value"},
        MalformedCase{"truncated_begin", "Begin\n", 1, "expected \"Begin <Block>\""},
        MalformedCase{"truncated_end", "Begin Nodes\n 1 0 0 0\nEnd\n", 3, "expected \"End Nodes\""},
        MalformedCase{"truncated_properties_header", "Begin Properties\nEnd Properties\n", 1, "needs one property id"},
        MalformedCase{"truncated_table_header", "Begin Table 1 TIME\nEnd Table\n", 1, "needs <id> <input_variable> <output_variable>"},
        MalformedCase{"file_ends_in_sub_model_part", "Begin SubModelPart A\n Begin SubModelPartNodes\n", 2,
                      "ends inside the \"SubModelPartNodes\" block"},
        MalformedCase{"non_utf8_sub_model_part_name", "Begin SubModelPart Contact\xff\xfe\nEnd SubModelPart\n", 1,
                      "byte 0xff at byte offset 26 (column 27) is not UTF-8"},
        MalformedCase{"non_utf8_in_a_comment", "// mesh\nBegin Nodes // caf\xe9\nEnd Nodes\n", 2,
                      "byte 0xe9 at byte offset 26 (column 19) is not UTF-8"},
        MalformedCase{"utf16_surrogate_bytes", "Begin Nodes // \xed\xa0\x80\nEnd Nodes\n", 1, "byte 0xed at byte offset 15"},
        MalformedCase{"overlong_utf8", "Begin Nodes // \xc0\xaf\nEnd Nodes\n", 1, "byte 0xc0 at byte offset 15"},
        MalformedCase{"nul_byte", std::string("Begin Nodes\n 1 0 0") + '\0' + " 0\nEnd Nodes\n", 2,
                      "a NUL byte at byte offset 18 (column 7) is not text"},
        MalformedCase{"degenerate_contact_line",
                      kLine + " 1 0 1 2\n 2 0 3 3\nEnd Conditions\nBegin SubModelPart Contact_Part\n Begin SubModelPartConditions\n"
                              "  1 2\n End SubModelPartConditions\nEnd SubModelPart\n",
                      9,
                      "condition 2 (Line2D2 with nodes [3, 3]) of model part \"Structure.Contact_Part\" is a degenerate face, "
                      "zero length: node 3 is listed twice\n  expected: a line of non-zero length"},
        MalformedCase{"coincident_nodes_of_a_line",
                      kNodes + "Begin Nodes\n 5 1 1 0\nEnd Nodes\nBegin Conditions LineCondition2D2N\n 4 0 3 5\nEnd Conditions\n", 11,
                      "condition 4 (Line2D2 with nodes [3, 5]) of model part \"Structure\" is a degenerate face, zero length: "
                      "nodes 3 and 5 are at the same point"},
        MalformedCase{"collinear_triangle",
                      "Begin Nodes\n 1 0 0 0\n 2 1 0 0\n 3 2 0 0\nEnd Nodes\nBegin Conditions SurfaceCondition3D3N\n 1 0 1 2 3\n"
                      " 2 0 3 2 1\nEnd Conditions\n",
                      7, "condition 1 (Triangle3D3 with nodes [1, 2, 3]) of model part \"Structure\" is a degenerate face, zero "
                         "area: its corners are collinear (1 more condition of the mesh is degenerate)"},
        MalformedCase{"huge_token_quoted_briefly", "Begin Nodes\n " + std::string(20000, '7') + "x 0 0 0\nEnd Nodes\n", 2,
                      "… (20001 characters)\" is not a valid node id"}),
    [](const ::testing::TestParamInfo<MalformedCase>& info) { return std::string(info.param.name); });

TEST(ModelPartIO, CollapsedQuadrilateralFaceIsRead) {
    RegisterContactApplication();
    Model model;
    ModelPart& part = NewStructure(model);
    // One collapsed edge leaves a triangle with an area: a load face, not a degenerate one.
    ModelPartIO(WriteMdpa("collapsed", kNodes + "Begin Conditions SurfaceCondition3D4N\n 1 0 1 2 3 3\nEnd Conditions\n"))
        .ReadModelPart(part);
    EXPECT_EQ(part.NumberOfConditions(), 1u);
}

TEST(ModelPartIO, UnderflowingValuesReadAsZeroAndUtf8NamesAreKept) {
    RegisterContactApplication();
    Model model;
    ModelPart& part = NewStructure(model);
    ModelPartIO(WriteMdpa("underflow", "Begin Nodes // noeud déplacé\n 1 1e-400 0 0\nEnd Nodes\n"
                                       "Begin SubModelPart Contacto_ñ\nEnd SubModelPart\n"))
        .ReadModelPart(part);
    EXPECT_EQ(part.GetNode(1).X(), 0.0);
    EXPECT_TRUE(part.HasSubModelPart("Contacto_ñ"));
}

/// The message of the InputError that reading @p path raises ("" if none).
std::string ReadError(const std::string& path) {
    Model model;
    ModelPart& part = model.CreateModelPart("Structure");
    try {
        ModelPartIO(path).ReadModelPart(part);
    } catch (const InputError& error) {
        return error.what();
    }
    return "";
}

TEST(ModelPartIO, FolderDeviceAndFifoAreRefusedWithoutReading) {
    const auto folder = std::filesystem::temp_directory_path() / "contact_app_test_folder.mdpa";
    std::filesystem::create_directories(folder);
    EXPECT_NE(ReadError(folder.string()).find("contact_app_test_folder.mdpa\" is a folder"), std::string::npos);
    EXPECT_NE(ReadError("/dev/zero").find("cannot open the mesh file \"/dev/zero.mdpa\""), std::string::npos);
    const auto device = std::filesystem::temp_directory_path() / "contact_app_test_device.mdpa";
    std::filesystem::remove(device);
    std::filesystem::create_symlink("/dev/zero", device);  // would be read forever
    EXPECT_NE(ReadError(device.string()).find("contact_app_test_device.mdpa\" is not a regular file"), std::string::npos);
    std::filesystem::remove(device);
    const auto fifo = std::filesystem::temp_directory_path() / "contact_app_test_fifo.mdpa";
    std::filesystem::remove(fifo);
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    // Opening a FIFO for reading would wait for a writer: the check must come first.
    EXPECT_NE(ReadError(fifo.string()).find("is not a regular file"), std::string::npos);
    std::filesystem::remove(fifo);
}

TEST(ModelPartIO, MissingFileNamesThePath) {
    Model model;
    ModelPart& part = model.CreateModelPart("Structure");
    try {
        ModelPartIO("/nonexistent/mesh").ReadModelPart(part);
        FAIL();
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("/nonexistent/mesh.mdpa"), std::string::npos);
    }
}

}  // namespace
}  // namespace contact_app
