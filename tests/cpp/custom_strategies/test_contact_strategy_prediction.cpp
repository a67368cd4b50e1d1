// SPDX-License-Identifier: BSD-3-Clause
/// The contact strategies predict only what the step prescribes (docs/architecture.md, contact strategies): in
/// dynamics the free DoFs start the step at their last converged value, where the plain Newton strategy extrapolates
/// with the Bossak predictor. A prescribed velocity is integrated by all of them.
#include <memory>

#include <gtest/gtest.h>

#include "../solving/solving_test_elements.h"
#include "contact_app/solving/builder_and_solvers/block_builder_and_solver.h"
#include "contact_app/solving/convergence_criteria/displacement_criteria.h"
#include "contact_app/solving/linear_solvers/linear_solver_factory.h"
#include "contact_app/solving/schemes/bossak_scheme.h"
#include "custom_strategies/residual_based_newton_raphson_contact_strategy.h"
#include "custom_strategies/residual_based_newton_raphson_mpc_contact_strategy.h"

namespace contact_app::testing {
namespace {

enum class Kind { Newton, Contact, MPCContact };

/// One node, u_n = (0.1, 0.2), v_n = (0.5, 0.3), a_n = (2, −1), v_y prescribed 0.4, Newmark, Δt = 0.1: the node's
/// DISPLACEMENT after the strategy's Predict.
Array3 PredictedDisplacement(Kind kind) {
    Model model;
    ModelPart& part = MakeLine(model, 1);
    part.GetProcessInfo().SetValue(DOMAIN_SIZE, 2);
    Node& node = part.GetNode(1);
    node.AddDof(DISPLACEMENT_Y, REACTION_Y);
    node.FastGetSolutionStepValue(DISPLACEMENT) = Array3{0.1, 0.2, 0.0};
    node.FastGetSolutionStepValue(VELOCITY) = Array3{0.5, 0.3, 0.0};
    node.FastGetSolutionStepValue(ACCELERATION) = Array3{2.0, -1.0, 0.0};
    part.AddElement(std::make_shared<OscillatorElement>(1, CreateGeometry("Point3D", {part.pGetNode(1)}), 1.0, 1.0));
    part.CloneTimeStep(0.1);
    node.Fix(VELOCITY_Y);
    node.FastGetSolutionStepValue(VELOCITY_Y) = 0.4;
    auto scheme = std::make_shared<BossakScheme>(0.0);
    auto builder = std::make_shared<BlockBuilderAndSolver>(CreateLinearSolver({}));
    auto criteria = std::make_shared<DisplacementCriteria>(1e-12, 1e-14);
    std::unique_ptr<SolvingStrategy> strategy;
    if (kind == Kind::Newton)
        strategy = std::make_unique<NewtonRaphsonStrategy>(part, scheme, builder, criteria);
    else if (kind == Kind::Contact)
        strategy = std::make_unique<ResidualBasedNewtonRaphsonContactStrategy>(part, scheme, builder, criteria);
    else
        strategy = std::make_unique<ResidualBasedNewtonRaphsonMPCContactStrategy>(part, scheme, builder, criteria);
    strategy->Initialize();
    strategy->InitializeSolutionStep();
    strategy->Predict();
    return node.FastGetSolutionStepValue(DISPLACEMENT);
}

TEST(ContactStrategyPrediction, FreeDofsStayAtTheLastConvergedStateInDynamics) {
    // Prescribed: 0.4 = 2/dt du − v_n, du = 0.035, for every strategy.
    for (const Kind kind : {Kind::Newton, Kind::Contact, Kind::MPCContact})
        EXPECT_NEAR(PredictedDisplacement(kind)[1], 0.235, 1e-14);
    // Free: extrapolated to u_n + dt v_n + dt²/2 a_n = 0.16 by the plain Newton strategy, kept at 0.1 by contact.
    EXPECT_NEAR(PredictedDisplacement(Kind::Newton)[0], 0.16, 1e-14);
    EXPECT_EQ(PredictedDisplacement(Kind::Contact)[0], 0.1);
    EXPECT_EQ(PredictedDisplacement(Kind::MPCContact)[0], 0.1);
}

}  // namespace
}  // namespace contact_app::testing
