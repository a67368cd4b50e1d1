// SPDX-License-Identifier: BSD-3-Clause
// FindPenetratingNodes: nodes behind the nearest master face with opposed normals, at any depth.
#include <gtest/gtest.h>

#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/model.h"
#include "custom_processes/penetration_check.h"

namespace contact_app {
namespace {

/// Master: the plane z = 0 in 4 × 4 unit quads, NORMAL +z (the master body is below it).
struct Plane {
    Plane() {
        RegisterContactApplication();
        part = &model.CreateModelPart("Structure");
        part->AddNodalSolutionStepVariable(NORMAL);
        auto properties = part->CreateNewProperties(1);
        for (int i = 0; i <= 4; ++i)
            for (int j = 0; j <= 4; ++j) part->CreateNewNode(1 + i * 5 + j, i, j, 0.0);
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                const IndexType a = 1 + i * 5 + j;
                auto face = part->CreateNewCondition("SurfaceCondition3D4N", part->Conditions().MaxId() + 1,
                                                     {a, a + 5, a + 6, a + 1}, properties);
                face->SetValue(NORMAL, Array3(0, 0, 1));
                masters.push_back(face.get());
                centres.push_back(face->GetGeometry().Center());
            }
        tree.Build(centres);
    }
    Node& Slave(double x, double y, double z, const Array3& normal) {
        auto node = part->CreateNewNode(1000 + part->Nodes().size(), x, y, z);
        node->FastGetSolutionStepValue(NORMAL) = normal;
        return *node;
    }
    Model model;
    ModelPart* part = nullptr;
    std::vector<Condition*> masters;
    std::vector<Array3> centres;
    SearchTree tree;
};

TEST(PenetrationCheck, NodesBehindTheMasterWithOpposedNormalsAtAnyDepth) {
    Plane plane;
    const Array3 down(0, 0, -1);
    std::vector<Node*> nodes = {&plane.Slave(1.5, 1.5, -0.2, down), &plane.Slave(2.5, 0.5, -30.0, down),
                                &plane.Slave(1.5, 1.5, 0.2, down),   // in front: open gap
                                &plane.Slave(1.5, 2.5, -0.2, -down),  // same orientation
                                &plane.Slave(9.0, 9.0, -0.2, down)};  // beside the master surface
    const auto hits = FindPenetratingNodes(nodes, plane.masters, plane.tree, std::sqrt(0.5), nullptr);
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_EQ(hits[0].node, nodes[0]);
    EXPECT_NEAR(hits[0].depth, 0.2, 1e-14);
    EXPECT_EQ(hits[0].master->GetGeometry().Center()[0], 1.5);
    EXPECT_EQ(hits[1].node, nodes[1]);
    EXPECT_NEAR(hits[1].depth, 30.0, 1e-12);
}

TEST(PenetrationCheck, FacesOfTheNodesOwnBodyAreSkipped) {
    Plane plane;
    std::vector<Node*> nodes = {&plane.Slave(1.5, 1.5, -0.2, Array3(0, 0, -1))};
    const auto own = [](const Node&, const Condition&) { return true; };
    EXPECT_TRUE(FindPenetratingNodes(nodes, plane.masters, plane.tree, std::sqrt(0.5), own).empty());
}

TEST(PenetrationCheck, ProjectAlongHitsAndMisses) {
    Plane plane;
    const Condition& face = *plane.masters[0];  // [0, 1]²
    EXPECT_NEAR(*ProjectAlong(Array3(0.5, 0.5, 2.0), Array3(0, 0, -1), face), 2.0, 1e-14);
    EXPECT_NEAR(*ProjectAlong(Array3(0.5, 0.5, -2.0), Array3(0, 0, -1), face), -2.0, 1e-14);
    EXPECT_FALSE(ProjectAlong(Array3(1.5, 0.5, 2.0), Array3(0, 0, -1), face).has_value());
    EXPECT_FALSE(ProjectAlong(Array3(0.5, 0.5, 2.0), Array3(1, 0, 0), face).has_value());
}

}  // namespace
}  // namespace contact_app
