// SPDX-License-Identifier: BSD-3-Clause
// Whole-solver verification against closed forms: cantilever (Timoshenko beam), thick cylinder
// (Lamé, axisymmetric) and uniaxial Neo-Hookean stretch.
#include <cmath>
#include <iostream>
#include <vector>

#include <gtest/gtest.h>

#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/constitutive_law.h"
#include "contact_app/kernel/model.h"
#include "contact_app/kernel/registry.h"
#include "contact_app/kernel/variables.h"
#include "contact_app/solving/builder_and_solvers/block_builder_and_solver.h"
#include "contact_app/solving/convergence_criteria/displacement_criteria.h"
#include "contact_app/solving/linear_solvers/linear_solver_factory.h"
#include "contact_app/solving/strategies/newton_raphson_strategy.h"
#include "contact_app/structural/structural_registration.h"

namespace contact_app {
namespace {

ModelPart& NewModelPart(Model& model, int dimension) {
    RegisterContactApplication();
    RegisterStructuralMechanics();
    ModelPart& part = model.CreateModelPart("Structure", 2);
    for (const VariableData* variable : std::initializer_list<const VariableData*>{
             &DISPLACEMENT, &REACTION, &VOLUME_ACCELERATION, &POINT_LOAD, &LINE_LOAD, &POSITIVE_FACE_PRESSURE,
             &NEGATIVE_FACE_PRESSURE})
        part.AddNodalSolutionStepVariable(*variable);
    part.GetProcessInfo().SetValue(DOMAIN_SIZE, dimension);
    return part;
}

void AddDisplacementDofs(ModelPart& part, int dimension) {
    const Variable<double>* dofs[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
    const Variable<double>* reactions[3] = {&REACTION_X, &REACTION_Y, &REACTION_Z};
    for (const auto& node : part.Nodes())
        for (int k = 0; k < dimension; ++k) node->AddDof(*dofs[k], *reactions[k]);
}

Properties::Pointer Material(ModelPart& part, const std::string& law, double young, double poisson) {
    auto properties = part.CreateNewProperties(1);
    properties->SetValue(YOUNG_MODULUS, young);
    properties->SetValue(POISSON_RATIO, poisson);
    properties->SetValue(THICKNESS, 1.0);
    properties->SetValue(CONSTITUTIVE_LAW, Registry<ConstitutiveLaw>::Instance().Get(law).Clone());
    return properties;
}

/// Structured nx × ny quadrilateral mesh of [x0, x0+lx] × [0, ly]; node id = 1 + i + j (nx + 1).
void QuadMesh(ModelPart& part, const std::string& element, Properties::Pointer properties, int nx, int ny, double x0,
              double lx, double ly) {
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i)
            part.CreateNewNode(1 + i + j * (nx + 1), x0 + lx * i / nx, ly * j / ny, 0.0);
    IndexType id = 1;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const IndexType n0 = 1 + i + j * (nx + 1);
            part.CreateNewElement(element, id++, {n0, n0 + 1, n0 + 1 + (nx + 1), n0 + (nx + 1)}, properties);
        }
}

NewtonRaphsonStrategy MakeStrategy(ModelPart& part, int max_iterations = 20) {
    auto builder = std::make_shared<BlockBuilderAndSolver>(CreateLinearSolver({}));
    // Linear problems reach round-off (ratio ~1e-12) after the first solve.
    auto criteria = std::make_shared<DisplacementCriteria>(1e-10, 1e-14);
    return NewtonRaphsonStrategy(part, std::make_shared<Scheme>(), builder, criteria, max_iterations);
}

/// Tip deflection of a clamped plane-stress cantilever (length 10, height 1, ν = 0) under an end
/// shear load P split over the end nodes in proportion to the parabolic shear distribution.
double CantileverTipDeflection(int nx, int ny) {
    Model model;
    ModelPart& part = NewModelPart(model, 2);
    const double length = 10.0, height = 1.0, young = 1000.0, load = 1.0;
    auto properties = Material(part, "LinearElasticPlaneStress2DLaw", young, 0.0);
    QuadMesh(part, "SmallDisplacementElement2D4N", properties, nx, ny, 0.0, length, height);
    AddDisplacementDofs(part, 2);
    IndexType condition_id = 1;
    for (int j = 0; j <= ny; ++j) {
        Node& clamped = part.GetNode(1 + j * (nx + 1));
        clamped.Fix(DISPLACEMENT_X);
        clamped.Fix(DISPLACEMENT_Y);
        // Consistent nodal share ∫ N_j τ dy of the parabolic shear τ(y) = 6P y (h − y)/h³ (Simpson is exact).
        auto shear = [&](double y) { return 6.0 * load / (height * height * height) * y * (height - y); };
        const double h = height / ny, y = h * j;
        double share = 0.0;
        if (j > 0) share += h / 6.0 * (2.0 * shear(y - 0.5 * h) + shear(y));
        if (j < ny) share += h / 6.0 * (shear(y) + 2.0 * shear(y + 0.5 * h));
        auto condition = part.CreateNewCondition("PointLoadCondition2D1N", condition_id++, {IndexType(nx + 1 + j * (nx + 1))},
                                                 properties);
        condition->SetValue(POINT_LOAD, Array3(0.0, -share, 0.0));
    }
    auto strategy = MakeStrategy(part);
    EXPECT_TRUE(strategy.Solve());
    return -part.GetNode(nx + 1 + (ny / 2) * (nx + 1)).FastGetSolutionStepValue(DISPLACEMENT_Y);
}

TEST(StructuralVerification, CantileverConvergesToTimoshenkoBeamTheory) {
    const double length = 10.0, young = 1000.0, inertia = 1.0 / 12.0, area = 1.0, shear_modulus = young / 2.0;
    const double exact = length * length * length / (3.0 * young * inertia) + length / (5.0 / 6.0 * shear_modulus * area);
    // Fully integrated bilinear quads are over-stiff in bending; the error falls as O(h²).
    std::vector<double> deflections;
    for (const int refinement : {2, 4, 8, 16}) {
        deflections.push_back(CantileverTipDeflection(10 * refinement, 2 * refinement));
        std::cout << "cantilever " << 10 * refinement << "x" << 2 * refinement << ": relative error "
                  << std::abs(deflections.back() - exact) / exact << "\n";
    }
    const double order = std::log2((deflections[2] - deflections[1]) / (deflections[3] - deflections[2]));
    const double extrapolated = deflections[3] + (deflections[3] - deflections[2]) / (std::pow(2.0, order) - 1.0);
    std::cout << "cantilever: observed order " << order << ", Richardson-extrapolated error "
              << std::abs(extrapolated - exact) / exact << "\n";
    EXPECT_GT(order, 1.7);
    EXPECT_LT(order, 2.3);
    // With the parabolic end shear, Timoshenko's deflection (κ = 5/6) is the plane-stress one up to
    // the clamping detail; the extrapolated value lands within 1e-4 (measured 5e-5).
    EXPECT_LT(std::abs(extrapolated - exact) / exact, 1e-3);
}

TEST(StructuralVerification, ThickCylinderMatchesLame) {
    // Axisymmetric slice a ≤ r ≤ b, plane strain along z (u_z = 0), internal pressure p.
    // E large enough that the follower pressure on the moving mesh stays a 1e-6 effect.
    const double a = 1.0, b = 2.0, p = 10.0, young = 1.0e7, nu = 0.3;
    auto lame = [&](double r) {
        return (1.0 + nu) / young * a * a * p / (b * b - a * a) * ((1.0 - 2.0 * nu) * r + b * b / r);
    };
    double previous_error = 1.0;
    for (const int nx : {4, 8, 16}) {
        Model model;
        ModelPart& part = NewModelPart(model, 2);
        auto properties = Material(part, "LinearElasticAxisym2DLaw", young, nu);
        QuadMesh(part, "AxisymSmallDisplacementElement2D4N", properties, nx, 1, a, b - a, 0.1);
        AddDisplacementDofs(part, 2);
        for (const auto& node : part.Nodes()) node->Fix(DISPLACEMENT_Y);
        // Inner edge from (a, 0) up to (a, 0.1): its normal (t_y, −t_x) points to +r, into the material.
        auto condition = part.CreateNewCondition("AxisymLineLoadCondition2D2N", 1, {1, IndexType(1 + (nx + 1))}, properties);
        part.GetNode(1).FastGetSolutionStepValue(POSITIVE_FACE_PRESSURE) = p;
        part.GetNode(1 + (nx + 1)).FastGetSolutionStepValue(POSITIVE_FACE_PRESSURE) = p;
        (void)condition;
        auto strategy = MakeStrategy(part);
        EXPECT_TRUE(strategy.Solve());
        double error = 0.0;
        for (int i = 0; i <= nx; ++i) {
            const Node& node = part.GetNode(1 + i);
            error = std::max(error, std::abs(node.FastGetSolutionStepValue(DISPLACEMENT_X) - lame(node.X0())) / lame(a));
        }
        std::cout << "thick cylinder nx=" << nx << ": max relative error " << error << "\n";
        EXPECT_LT(error, previous_error);
        previous_error = error;
    }
    EXPECT_LT(previous_error, 5e-3);
}

TEST(StructuralVerification, NeoHookeanUniaxialStretchMatchesTheAnalyticStress) {
    // Unit cube, TL hexahedron, stretch λ along x, lateral faces free (uniaxial stress).
    const double young = 100.0, nu = 0.3, stretch = 1.4;
    const double lambda = young * nu / ((1 + nu) * (1 - 2 * nu)), mu = young / (2 * (1 + nu));
    Model model;
    ModelPart& part = NewModelPart(model, 3);
    auto properties = Material(part, "HyperElastic3DLaw", young, nu);
    const double corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    for (int i = 0; i < 8; ++i) part.CreateNewNode(i + 1, corners[i][0], corners[i][1], corners[i][2]);
    part.CreateNewElement("TotalLagrangianElement3D8N", 1, {1, 2, 3, 4, 5, 6, 7, 8}, properties);
    AddDisplacementDofs(part, 3);
    for (const auto& node : part.Nodes()) {
        if (node->X0() == 0.0) node->Fix(DISPLACEMENT_X);
        if (node->X0() == 1.0) {
            node->Fix(DISPLACEMENT_X);
            node->FastGetSolutionStepValue(DISPLACEMENT_X) = stretch - 1.0;
        }
        if (node->Y0() == 0.0) node->Fix(DISPLACEMENT_Y);  // symmetry planes
        if (node->Z0() == 0.0) node->Fix(DISPLACEMENT_Z);
    }
    auto strategy = MakeStrategy(part, 30);
    EXPECT_TRUE(strategy.Solve());
    // Lateral stretch s from S22 = λ ln J / s² + μ (1 − 1/s²) = 0 with J = λ_x s² (Newton on s).
    double s = 1.0;
    for (int i = 0; i < 50; ++i) {
        const double J = stretch * s * s;
        const double f = lambda * std::log(J) + mu * (s * s - 1.0);
        const double df = 2.0 * lambda / s + 2.0 * mu * s;
        s -= f / df;
    }
    const double J = stretch * s * s;
    const double S11 = lambda * std::log(J) / (stretch * stretch) + mu * (1.0 - 1.0 / (stretch * stretch));
    const double force = stretch * S11;  // first Piola–Kirchhoff times the unit reference area
    EXPECT_NEAR(1.0 + part.GetNode(7).FastGetSolutionStepValue(DISPLACEMENT_Y), s, 1e-9);
    double reaction = 0.0;
    for (const auto& node : part.Nodes())
        if (node->X0() == 1.0) reaction += node->FastGetSolutionStepValue(REACTION_X);
    EXPECT_NEAR(reaction, force, 1e-8 * force);
}

}  // namespace
}  // namespace contact_app
