// SPDX-License-Identifier: BSD-3-Clause
// Nodal normals: mean nodal normal of a model part, condition normals, AD derivatives of face normals.
#include <gtest/gtest.h>

#include "automatic_differentiation/ad_helpers.h"
#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/model.h"
#include "contact_app/kernel/variables.h"
#include "custom_utilities/mortar_normals.h"
#include "tests/cpp/custom_utilities/mortar_test_utilities.h"

namespace contact_app {
namespace {

TEST(MortarNormals, test_mean_nodal_normal_of_a_folded_surface) {
    RegisterContactApplication();
    Model model;
    ModelPart& part = model.CreateModelPart("Contact");
    part.AddNodalSolutionStepVariable(NORMAL);
    part.CreateNewNode(1, 0, 0, 0);
    part.CreateNewNode(2, 1, 0, 0);
    part.CreateNewNode(3, 1, 1, 0);
    part.CreateNewNode(4, 0, 1, 0);
    part.CreateNewNode(5, 2, 0, 1);  // second quad folded up by 45°
    part.CreateNewNode(6, 2, 1, 1);
    auto properties = part.CreateNewProperties(0);
    part.CreateNewCondition("SurfaceCondition3D4N", 1, {1, 2, 3, 4}, properties);
    part.CreateNewCondition("SurfaceCondition3D4N", 2, {2, 5, 6, 3}, properties);
    ComputeNodesMeanNormalModelPart(part);
    const Array3 n1(0, 0, 1), n2 = Array3(-1, 0, 1).normalized();
    EXPECT_LT((part.GetNode(1).FastGetSolutionStepValue(NORMAL) - n1).norm(), 1e-14);
    EXPECT_LT((part.GetNode(5).FastGetSolutionStepValue(NORMAL) - n2).norm(), 1e-14);
    EXPECT_LT((part.GetNode(2).FastGetSolutionStepValue(NORMAL) - (n1 + n2).normalized()).norm(), 1e-14);
    EXPECT_LT((part.GetCondition(2).GetValue(NORMAL) - n2).norm(), 1e-14);
}

TEST(MortarNormals, test_mean_nodal_normal_errors_name_the_fix) {
    Model model;
    ModelPart& part = model.CreateModelPart("Contact");
    part.CreateNewNode(1, 0, 0, 0);
    EXPECT_THROW(ComputeNodesMeanNormalModelPart(part), InputError);
    part.AddNodalSolutionStepVariable(NORMAL);
    part.GetNode(1).Set(INTERFACE, true);
    try {
        ComputeNodesMeanNormalModelPart(part);
        FAIL() << "expected InputError";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("node 1"), std::string::npos);
    }
}

TEST(MortarNormals, test_face_normal_matches_kernel_convention_and_fd) {
    // 2D: (t_y, −t_x)/|t|.
    NodeCoordinates<double, 2, 2> line;
    line << 1, 0, 0, 0;
    EXPECT_LT((FaceCenterUnitNormal<2, 2, double>(line) - Eigen::Vector2d(0, 1)).norm(), 1e-15);
    // Warped quadrilateral: nodal normals against central differences.
    NodeCoordinates<double, 3, 4> quad;
    quad << 0, 0, 0, 1, 0, 0.2, 1.1, 1, -0.1, 0, 0.9, 0.3;
    const auto ad = FaceNodalUnitNormals<3, 4, Dual<24>>(Seed<24>(quad));  // the instantiated 3D4N size
    const double h = 1e-6;
    double worst = 0.0;
    for (int q = 0; q < 12; ++q) {
        auto plus = quad, minus = quad;
        plus(q / 3, q % 3) += h;
        minus(q / 3, q % 3) -= h;
        const auto fd = (FaceNodalUnitNormals<3, 4, double>(plus) - FaceNodalUnitNormals<3, 4, double>(minus)) / (2 * h);
        worst = std::max(worst, (Derivative(ad, q) - fd).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(worst, 1e-8);
    // Degenerate face: zero normal, no NaN.
    NodeCoordinates<double, 3, 3> flat = NodeCoordinates<double, 3, 3>::Zero();
    EXPECT_TRUE((FaceCenterUnitNormal<3, 3, double>(flat).isZero()));
}

}  // namespace
}  // namespace contact_app
