// SPDX-License-Identifier: BSD-3-Clause
// 3D surface loads: closed-polyhedron pressure balance, face-pressure signs, total force A·s.
#include <gtest/gtest.h>

#include <random>

#include "load_condition_test_utilities.h"

namespace contact_app::testing {
namespace {

TEST(SurfaceLoadCondition3D, UniformPressureOnDisplacedCubeHasZeroNetForce) {
    LoadConditionModel model;
    model.AddNodes({Array3(0, 0, 0), Array3(1, 0, 0), Array3(1, 1, 0), Array3(0, 1, 0), Array3(0, 0, 1),
                    Array3(1, 0, 1), Array3(1, 1, 1), Array3(0, 1, 1)});
    // Faces ordered so that (x_1 − x_0) × (x_3 − x_0) points out.
    const std::vector<std::vector<IndexType>> faces{{1, 4, 3, 2}, {5, 6, 7, 8}, {1, 2, 6, 5},
                                                    {4, 8, 7, 3}, {1, 5, 8, 4}, {2, 3, 7, 6}};
    for (std::size_t f = 0; f < faces.size(); ++f)
        model.AddCondition("SurfaceLoadCondition3D4N", f + 1, faces[f]).SetValue(NEGATIVE_FACE_PRESSURE, 2.0);
    // Undisplaced: the top face is pushed along its geometry normal +z with p·A = 2 (docs/theory/structural.md §3).
    const Vector top = Rhs(model.part->GetCondition(2));
    EXPECT_NEAR(top[2] + top[5] + top[8] + top[11], 2.0, 1e-14);
    std::mt19937 rng(4);
    DisplaceRandomly(*model.part, rng, 0.2, 3);  // warped quadrilaterals
    EXPECT_LT(NetForce(*model.part, 3).norm(), 1e-13);
}

TEST(SurfaceLoadCondition3D, UniformPressureOnDisplacedTetrahedronHasZeroNetForce) {
    LoadConditionModel model;
    model.AddNodes({Array3(0, 0, 0), Array3(1, 0, 0), Array3(0, 1, 0), Array3(0, 0, 1)});
    const std::vector<std::vector<IndexType>> faces{{1, 3, 2}, {1, 2, 4}, {1, 4, 3}, {2, 3, 4}};
    for (std::size_t f = 0; f < faces.size(); ++f)
        model.AddCondition("SurfaceLoadCondition3D3N", f + 1, faces[f]).SetValue(POSITIVE_FACE_PRESSURE, 1.5);
    std::mt19937 rng(9);
    DisplaceRandomly(*model.part, rng, 0.15, 3);
    EXPECT_LT(NetForce(*model.part, 3).norm(), 1e-13);
}

TEST(SurfaceLoadCondition3D, SurfaceLoadTotalIsCurrentAreaTimesLoad) {
    for (const bool quadrilateral : {false, true}) {
        LoadConditionModel model;
        model.AddNodes({Array3(0, 0, 0), Array3(2, 0, 0), Array3(2, 3, 0), Array3(0, 3, 0)});
        Condition& face = quadrilateral ? model.AddCondition("SurfaceLoadCondition3D4N", 1, {1, 2, 3, 4})
                                        : model.AddCondition("SurfaceLoadCondition3D3N", 1, {1, 2, 3});
        // Shear the face out of plane: area of the parallelogram / triangle grows by √(1 + 0.5²).
        for (IndexType id : {3, 4}) Displace(model.part->GetNode(id), Array3(0.0, 0.0, 1.5));
        const double area = (quadrilateral ? 6.0 : 3.0) * std::sqrt(1.25);
        face.SetValue(SURFACE_LOAD, Array3(1.0, -2.0, 0.5));
        model.properties->SetValue(THICKNESS, 0.1);
        const Array3 net = NetForce(*model.part, 3);
        EXPECT_LT((net - area * Array3(1.0, -2.0, 0.5)).norm(), 1e-13) << (quadrilateral ? "quad" : "triangle");
    }
}

TEST(SurfaceLoadCondition3D, NodalLoadsAreHistoricalOnly) {
    LoadConditionModel model(true, false);
    model.AddNodes({Array3(0, 0, 0), Array3(1, 0, 0), Array3(0, 1, 0)});
    for (const auto& node : model.part->Nodes()) {
        node->SetValue(SURFACE_LOAD, Array3(1.0, 1.0, 1.0));  // not read (docs/theory/structural.md §3)
        node->SetValue(NEGATIVE_FACE_PRESSURE, 1.0);           // not read
    }
    Condition& face = model.AddCondition("SurfaceLoadCondition3D3N", 1, {1, 2, 3});
    EXPECT_EQ(Rhs(face), Vector::Zero(9));
}

}  // namespace
}  // namespace contact_app::testing
