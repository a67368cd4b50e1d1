// SPDX-License-Identifier: BSD-3-Clause
// Degenerate faces: the reason for each kind, the model parts named, the checked unit normal.
#include <string>

#include <gtest/gtest.h>

#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/face_checks.h"
#include "contact_app/kernel/model.h"

namespace contact_app {
namespace {

/// Root "Structure" with nodes 1..4 at the given points and sub model parts Contact > Slave.
struct Mesh {
    Model model;
    ModelPart* root;
    ModelPart* slave;
    explicit Mesh(const std::vector<Array3>& points) {
        RegisterContactApplication();
        root = &model.CreateModelPart("Structure");
        for (std::size_t i = 0; i < points.size(); ++i)
            root->CreateNewNode(i + 1, points[i][0], points[i][1], points[i][2]);
        slave = &root->CreateSubModelPart("Contact").CreateSubModelPart("Slave");
    }
    const Condition& Add(const std::string& name, IndexType id, const std::vector<IndexType>& nodes) {
        return *slave->CreateNewCondition(name, id, nodes, root->pGetProperties(0));
    }
};

const std::vector<Array3> kSquare = {Array3(0, 0, 0), Array3(1, 0, 0), Array3(1, 1, 0), Array3(0, 1, 0)};

TEST(FaceChecks, ReasonNamesWhyAFaceIsDegenerate) {
    Mesh mesh({Array3(0, 0, 0), Array3(1, 0, 0), Array3(2, 0, 0), Array3(0, 0, 0), Array3(0, 0, 5)});
    const auto reason = [&](const std::string& name, IndexType id, const std::vector<IndexType>& nodes) {
        return DegenerateFaceReason(mesh.Add(name, id, nodes).GetGeometry());
    };
    EXPECT_EQ(reason("LineCondition2D2N", 1, {2, 2}), "zero length: node 2 is listed twice");
    EXPECT_EQ(reason("LineCondition2D2N", 2, {1, 4}), "zero length: nodes 1 and 4 are at the same point");
    EXPECT_EQ(reason("LineCondition2D2N", 3, {1, 5}), "zero length: nodes 1 and 5 are at the same point in the x-y plane");
    EXPECT_EQ(reason("SurfaceCondition3D3N", 4, {1, 2, 3}), "zero area: its corners are collinear");
    EXPECT_EQ(reason("SurfaceCondition3D4N", 5, {1, 2, 3, 2}), "zero area: node 2 is listed twice");
    EXPECT_EQ(reason("LineCondition2D2N", 6, {1, 2}), "");
    EXPECT_EQ(reason("LineCondition3D2N", 7, {1, 1}), "");  // an edge in 3D is not a face
}

TEST(FaceChecks, RegularAndCollapsedFacesPass) {
    Mesh mesh(kSquare);
    EXPECT_EQ(DegenerateFaceReason(mesh.Add("SurfaceCondition3D4N", 1, {1, 2, 3, 4}).GetGeometry()), "");
    // A quadrilateral with one collapsed edge is a triangle: it has an area (loads integrate it).
    EXPECT_EQ(DegenerateFaceReason(mesh.Add("SurfaceCondition3D4N", 2, {1, 2, 3, 3}).GetGeometry()), "");
    // A bow-tie quadrilateral has zero vector area.
    EXPECT_NE(DegenerateFaceReason(mesh.Add("SurfaceCondition3D4N", 3, {1, 3, 2, 4}).GetGeometry()).find("crosses itself"),
              std::string::npos);
}

TEST(FaceChecks, UnitNormalOfADegenerateConditionNamesItAndItsModelParts) {
    Mesh mesh(kSquare);
    mesh.root->CreateSubModelPart("Other").AddConditions(std::vector<IndexType>{});
    const Condition& line = mesh.Add("LineCondition2D2N", 7, {3, 3});
    try {
        ConditionUnitNormal(line, *mesh.root, Array3::Zero());
        FAIL();
    } catch (const InputError& error) {
        EXPECT_STREQ(error.what(),
                     "condition 7 (Line2D2 with nodes [3, 3]) of model part \"Structure.Contact.Slave\" is a degenerate "
                     "face, zero length: node 3 is listed twice\n"
                     "  expected: a line of non-zero length or a face of non-zero area, so that its normal is defined\n"
                     "  fix:      correct the node ids of the condition, or remove it from the mesh");
    }
    const Condition& good = mesh.Add("LineCondition2D2N", 8, {1, 2});
    EXPECT_TRUE(ConditionUnitNormal(good, *mesh.slave, Array3::Zero()).isApprox(Array3(0, -1, 0)));
    // A collapsed corner of a quadrilateral: non-zero area, zero normal at that corner.
    const Condition& collapsed = mesh.Add("SurfaceCondition3D4N", 9, {1, 2, 3, 3});
    mesh.root->GetSubModelPart("Other").AddConditions(std::vector<IndexType>{9});
    try {
        ConditionUnitNormal(collapsed, *mesh.slave, Array3(1, 1, 0));
        FAIL();
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("condition 9 (Quadrilateral3D4 with nodes [1, 2, 3, 3]) of model parts "
                               "\"Structure.Contact.Slave\", \"Structure.Other\""),
                  std::string::npos)
            << message;
        EXPECT_NE(message.find("zero normal at local point (1, 1, 0)"), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace contact_app
