// SPDX-License-Identifier: BSD-3-Clause
/// Block convergence of a contact system: displacement and multiplier blocks judged separately, the multiplier
/// block skipped without contact, the frictional split of the multipliers into normal / stick / slip parts.
#include <gtest/gtest.h>

#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/model.h"
#include "contact_app/solving/builder_and_solvers/block_builder_and_solver.h"
#include "contact_app/solving/linear_solvers/linear_solver_factory.h"
#include "custom_strategies/displacement_lagrange_multiplier_contact_criteria.h"

namespace contact_app::testing {
namespace {

/// One slave node (DISPLACEMENT_X/Y, VECTOR_LAGRANGE_MULTIPLIER_X/Y) with normal (0, 1).
struct OneNode {
    Model model;
    ModelPart* part = nullptr;
    Node* node = nullptr;
    std::vector<Dof*> dofs;
    BlockBuilderAndSolver builder{CreateLinearSolver(LinearSolverSettings{"umfpack"})};
    SparseMatrixType A;

    OneNode() {
        RegisterContactApplication();
        part = &model.CreateModelPart("Structure");
        part->AddNodalSolutionStepVariable(DISPLACEMENT);
        part->AddNodalSolutionStepVariable(NORMAL);
        part->AddNodalSolutionStepVariable(VECTOR_LAGRANGE_MULTIPLIER);
        node = part->CreateNewNode(1, 0.0, 0.0, 0.0).get();
        for (const auto* v :
             {&DISPLACEMENT_X, &DISPLACEMENT_Y, &VECTOR_LAGRANGE_MULTIPLIER_X, &VECTOR_LAGRANGE_MULTIPLIER_Y})
            dofs.push_back(&node->AddDof(*v));
        for (std::size_t i = 0; i < dofs.size(); ++i) dofs[i]->SetEquationId(i);
        node->FastGetSolutionStepValue(NORMAL) = Array3(0.0, 1.0, 0.0);
        node->Set(SLAVE, true);
        node->Set(ACTIVE, true);
        node->SetValue(FRICTION_COEFFICIENT, 0.3);
    }
    void Values(double ux, double uy, double lx, double ly) {
        node->FastGetSolutionStepValue(DISPLACEMENT) = Array3(ux, uy, 0.0);
        node->FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = Array3(lx, ly, 0.0);
    }
};

TEST(DisplacementLagrangeMultiplierContactCriteria, IncrementBlocksAreJudgedSeparately) {
    OneNode s;
    s.Values(1.0, 1.0, 0.0, -2.0);
    DisplacementLagrangeMultiplierContactCriteria criteria(ContactBlockMeasure::INCREMENT,
                                                           ContactBlockMeasure::INCREMENT, {});
    SystemVectorType dx(4), b = SystemVectorType::Zero(4);
    dx << 1e-6, 0.0, 0.0, 0.5;  // displacement converged (ratio ~7e-7), multiplier not (ratio 0.25)
    EXPECT_FALSE(criteria.PostCriteria(*s.part, s.dofs, s.A, dx, b, s.builder));
    EXPECT_NEAR(criteria.LastRatio(DisplacementLagrangeMultiplierContactCriteria::DISPLACEMENT), 1e-6 / std::sqrt(2.0),
                1e-15);
    EXPECT_NEAR(criteria.LastRatio(DisplacementLagrangeMultiplierContactCriteria::LM_NORMAL), 0.25, 1e-15);
    EXPECT_TRUE(criteria.BlockConverged(DisplacementLagrangeMultiplierContactCriteria::DISPLACEMENT));
    dx[3] = 1e-6;
    EXPECT_TRUE(criteria.PostCriteria(*s.part, s.dofs, s.A, dx, b, s.builder));
}

TEST(DisplacementLagrangeMultiplierContactCriteria, MultipliersAreNotJudgedWithoutContactUnlessRequired) {
    OneNode s;
    s.node->Set(ACTIVE, false);
    s.Values(1.0, 1.0, 0.0, -2.0);
    SystemVectorType dx(4), b = SystemVectorType::Zero(4);
    dx << 0.0, 0.0, 1.0, 1.0;
    DisplacementLagrangeMultiplierContactCriteria lax(ContactBlockMeasure::INCREMENT, ContactBlockMeasure::INCREMENT,
                                                      {});
    EXPECT_TRUE(lax.PostCriteria(*s.part, s.dofs, s.A, dx, b, s.builder));
    ContactCriteriaTolerances strict;
    strict.ensure_contact = true;
    DisplacementLagrangeMultiplierContactCriteria ensure(ContactBlockMeasure::INCREMENT, ContactBlockMeasure::INCREMENT,
                                                         strict);
    EXPECT_THROW(ensure.PostCriteria(*s.part, s.dofs, s.A, dx, b, s.builder), ConvergenceError);
}

TEST(DisplacementLagrangeMultiplierContactCriteria, ResidualRatioIsToTheStepStartResidual) {
    OneNode s;
    s.Values(0.0, 0.0, 0.0, 0.0);
    DisplacementLagrangeMultiplierContactCriteria criteria(ContactBlockMeasure::RESIDUAL,
                                                           ContactBlockMeasure::INCREMENT, {});
    EXPECT_TRUE(criteria.GetActualizeRHSflag());
    SystemVectorType dx = SystemVectorType::Zero(4), b(4);
    b << 3.0, 4.0, 0.0, 0.0;
    criteria.InitializeSolutionStep(*s.part, s.dofs, s.A, dx, b, s.builder);
    b << 3e-5, 4e-5, 0.0, 0.0;
    EXPECT_TRUE(criteria.PostCriteria(*s.part, s.dofs, s.A, dx, b, s.builder));
    EXPECT_NEAR(criteria.LastRatio(DisplacementLagrangeMultiplierContactCriteria::DISPLACEMENT), 1e-5, 1e-15);
    EXPECT_NEAR(criteria.LastAbsolute(DisplacementLagrangeMultiplierContactCriteria::DISPLACEMENT), 2.5e-5, 1e-15);
}

TEST(DisplacementLagrangeMultiplierContactCriteria, FrictionalSplitProjectsOnTheNormal) {
    OneNode s;
    s.Values(1.0, 1.0, 0.5, -2.0);
    ContactCriteriaTolerances tolerances;
    tolerances.split_frictional = true;
    tolerances.ratio_normal_tangent_threshold = 0.0;
    DisplacementLagrangeMultiplierContactCriteria criteria(ContactBlockMeasure::INCREMENT,
                                                           ContactBlockMeasure::INCREMENT, tolerances);
    SystemVectorType dx(4), b = SystemVectorType::Zero(4);
    dx << 0.0, 0.0, 0.05, 0.0;  // tangential increment only: the normal block is converged, the stick one is not
    EXPECT_FALSE(criteria.PostCriteria(*s.part, s.dofs, s.A, dx, b, s.builder));
    using C = DisplacementLagrangeMultiplierContactCriteria;
    EXPECT_TRUE(criteria.BlockConverged(C::LM_NORMAL));
    EXPECT_FALSE(criteria.BlockConverged(C::LM_STICK));
    EXPECT_NEAR(criteria.LastRatio(C::LM_STICK), 0.1, 1e-15);  // |Δλ_t| / |λ_t| = 0.05 / 0.5
    s.node->Set(SLIP, true);
    EXPECT_FALSE(criteria.PostCriteria(*s.part, s.dofs, s.A, dx, b, s.builder));
    EXPECT_FALSE(criteria.BlockConverged(C::LM_SLIP));
    EXPECT_TRUE(criteria.BlockConverged(C::LM_STICK));
}

}  // namespace
}  // namespace contact_app::testing

namespace contact_app::testing {
namespace {

TEST(DisplacementLagrangeMultiplierContactCriteria, BlockWithoutStepStartResidualUsesItsFirstResidual) {
    OneNode s;
    s.Values(0.0, 0.0, 0.0, -1.0);
    DisplacementLagrangeMultiplierContactCriteria criteria(ContactBlockMeasure::RESIDUAL,
                                                           ContactBlockMeasure::RESIDUAL, {});
    SystemVectorType dx = SystemVectorType::Zero(4), b(4);
    b << 1.0, 0.0, 0.0, 0.0;  // the multiplier block has no residual at the step start
    criteria.InitializeSolutionStep(*s.part, s.dofs, s.A, dx, b, s.builder);
    b << 1e-3, 0.0, 0.0, 2.0;  // first iteration: the multiplier residual becomes the reference
    EXPECT_FALSE(criteria.PostCriteria(*s.part, s.dofs, s.A, dx, b, s.builder));
    using C = DisplacementLagrangeMultiplierContactCriteria;
    EXPECT_NEAR(criteria.LastRatio(C::LM_NORMAL), 1.0, 1e-15);
    b << 1e-6, 0.0, 0.0, 1e-5;  // relative 5e-6 of that reference although far above the absolute tolerance
    EXPECT_TRUE(criteria.PostCriteria(*s.part, s.dofs, s.A, dx, b, s.builder));
    EXPECT_NEAR(criteria.LastRatio(C::LM_NORMAL), 5e-6, 1e-15);
}

}  // namespace
}  // namespace contact_app::testing
