// SPDX-License-Identifier: BSD-3-Clause
// Builders, schemes, criteria and strategies on spring chains and oscillators with exact answers.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "contact_app/solving/builder_and_solvers/block_builder_and_solver.h"
#include "contact_app/solving/builder_and_solvers/elimination_builder_and_solver.h"
#include "contact_app/solving/convergence_criteria/composite_criteria.h"
#include "contact_app/solving/convergence_criteria/displacement_criteria.h"
#include "contact_app/solving/convergence_criteria/mixed_generic_criteria.h"
#include "contact_app/solving/convergence_criteria/residual_criteria.h"
#include "contact_app/solving/convergence_criteria/round_off_bound.h"
#include "contact_app/solving/linear_solvers/linear_solver_factory.h"
#include "contact_app/solving/schemes/bossak_scheme.h"
#include "contact_app/solving/strategies/line_search_strategy.h"
#include "solving_test_elements.h"

namespace contact_app {
namespace {

using testing::AddSprings;
using testing::MakeLine;
using testing::OscillatorElement;

/// A force @p force on node @p node_id (a massless, stiffness-free oscillator element).
void AddForce(ModelPart& part, IndexType element_id, IndexType node_id, double force) {
    part.AddElement(std::make_shared<OscillatorElement>(element_id, CreateGeometry("Point3D", {part.pGetNode(node_id)}),
                                                        0.0, 0.0, force));
}

BuilderAndSolver::Pointer MakeBuilder(bool block) {
    auto solver = CreateLinearSolver({});
    if (block) return std::make_shared<BlockBuilderAndSolver>(solver);
    return std::make_shared<EliminationBuilderAndSolver>(solver);
}

class SpringChainTest : public ::testing::TestWithParam<bool> {};

TEST_P(SpringChainTest, LinearChainGivesExactDisplacementsAndReaction) {
    Model model;
    ModelPart& part = MakeLine(model, 5);
    AddSprings(part, 2.0);
    AddForce(part, 100, 5, 3.0);
    part.GetNode(1).Fix(DISPLACEMENT_X);
    SolvingStrategy strategy(part, std::make_shared<Scheme>(), MakeBuilder(GetParam()));
    EXPECT_TRUE(strategy.Solve());
    for (IndexType id = 1; id <= 5; ++id)
        EXPECT_NEAR(part.GetNode(id).FastGetSolutionStepValue(DISPLACEMENT_X), 1.5 * double(id - 1), 1e-12);
    EXPECT_NEAR(part.GetNode(1).FastGetSolutionStepValue(REACTION_X), -3.0, 1e-12);
    EXPECT_NEAR(part.GetNode(5).X(), 4.0 + 6.0, 1e-12);  // the mesh moved
    EXPECT_EQ(strategy.GetBuilderAndSolver().GetEquationSystemSize(), GetParam() ? 5u : 4u);
}

TEST_P(SpringChainTest, PrescribedDisplacementsInterpolateLinearly) {
    Model model;
    ModelPart& part = MakeLine(model, 5);
    AddSprings(part, 7.0);
    part.GetNode(1).Fix(DISPLACEMENT_X);
    part.GetNode(5).Fix(DISPLACEMENT_X);
    part.GetNode(5).FastGetSolutionStepValue(DISPLACEMENT_X) = 0.4;
    auto criteria = std::make_shared<ResidualCriteria>(1e-10, 1e-14);
    NewtonRaphsonStrategy strategy(part, std::make_shared<Scheme>(), MakeBuilder(GetParam()), criteria);
    EXPECT_TRUE(strategy.Solve());
    EXPECT_NEAR(part.GetNode(3).FastGetSolutionStepValue(DISPLACEMENT_X), 0.2, 1e-12);
    // Holding the stretched chain takes +k·e at the pulled end and −k·e at the other.
    EXPECT_NEAR(part.GetNode(5).FastGetSolutionStepValue(REACTION_X), 7.0 * 0.1, 1e-12);
    EXPECT_NEAR(part.GetNode(1).FastGetSolutionStepValue(REACTION_X), -7.0 * 0.1, 1e-12);
    EXPECT_LE(strategy.GetIterationNumber(), 2);
}

TEST_P(SpringChainTest, NewtonConvergesQuadraticallyOnANonlinearSpring) {
    Model model;
    ModelPart& part = MakeLine(model, 2);
    AddSprings(part, 1.0, 1.0);
    AddForce(part, 100, 2, 10.0);
    part.GetNode(1).Fix(DISPLACEMENT_X);
    auto criteria = std::make_shared<DisplacementCriteria>(1e-12, 1e-16);
    NewtonRaphsonStrategy strategy(part, std::make_shared<Scheme>(), MakeBuilder(GetParam()), criteria, 30);
    EXPECT_TRUE(strategy.Solve());
    const double e = part.GetNode(2).FastGetSolutionStepValue(DISPLACEMENT_X);
    EXPECT_NEAR(e + e * e * e, 10.0, 1e-10);  // e = 2 exactly
    EXPECT_NEAR(e, 2.0, 1e-12);
    EXPECT_LE(strategy.GetIterationNumber(), 12);
    EXPECT_EQ(strategy.IterationHistory().size(), static_cast<std::size_t>(strategy.GetIterationNumber()));
}

INSTANTIATE_TEST_SUITE_P(BlockAndElimination, SpringChainTest, ::testing::Bool(),
                         [](const auto& info) { return info.param ? std::string("block") : std::string("elimination"); });

TEST(NewtonRaphsonStrategy, ReportsANonConvergedStepAndKeepsTheIterate) {
    Model model;
    ModelPart& part = MakeLine(model, 2);
    AddSprings(part, 1.0, 1.0);
    AddForce(part, 100, 2, 10.0);
    part.GetNode(1).Fix(DISPLACEMENT_X);
    auto criteria = std::make_shared<ResidualCriteria>(1e-12, 1e-16);
    NewtonRaphsonStrategy strategy(part, std::make_shared<Scheme>(), MakeBuilder(true), criteria, 2);
    EXPECT_FALSE(strategy.Solve());
    EXPECT_FALSE(strategy.LastStepConverged());
    EXPECT_EQ(strategy.GetIterationNumber(), 2);
    EXPECT_GT(part.GetNode(2).FastGetSolutionStepValue(DISPLACEMENT_X), 2.0);  // Newton from 0 overshoots
    EXPECT_THROW(strategy.SetMaxIterationNumber(0), InputError);
}

TEST(LineSearchStrategy, SolvesTheNonlinearSpringWithAdaptedSteps) {
    Model model;
    ModelPart& part = MakeLine(model, 2);
    AddSprings(part, 1.0, 1.0);
    AddForce(part, 100, 2, 10.0);
    part.GetNode(1).Fix(DISPLACEMENT_X);
    auto criteria = std::make_shared<ResidualCriteria>(1e-12, 1e-14);
    LineSearchStrategy strategy(part, std::make_shared<Scheme>(), MakeBuilder(true), criteria, 30);
    EXPECT_TRUE(strategy.Solve());
    EXPECT_NEAR(part.GetNode(2).FastGetSolutionStepValue(DISPLACEMENT_X), 2.0, 1e-10);
}

TEST(CompositeCriteria, AndNeedsBothOrNeedsOne) {
    Model model;
    ModelPart& part = MakeLine(model, 2);
    AddSprings(part, 1.0, 1.0);
    AddForce(part, 100, 2, 10.0);
    part.GetNode(1).Fix(DISPLACEMENT_X);
    auto loose = std::make_shared<DisplacementCriteria>(1.0, 1.0);    // always met
    auto strict = std::make_shared<ResidualCriteria>(1e-30, 1e-300);  // met only at an exact zero
    NewtonRaphsonStrategy with_or(part, std::make_shared<Scheme>(), MakeBuilder(true),
                                  std::make_shared<CompositeCriteria>(CompositeCriteria::Mode::Or, loose, strict), 5);
    EXPECT_TRUE(with_or.Solve());
    EXPECT_EQ(with_or.GetIterationNumber(), 1);
    NewtonRaphsonStrategy with_and(part, std::make_shared<Scheme>(), MakeBuilder(true),
                                   std::make_shared<CompositeCriteria>(CompositeCriteria::Mode::And, loose, strict), 3);
    with_and.Solve();
    EXPECT_EQ(with_and.GetIterationNumber(), 3);
}

TEST(RoundOffBound, ACorrectionBelowThePrecisionOfTheStateIsRoundOff) {
    const double eps = std::numeric_limits<double>::epsilon();
    const double state = 4.0;  // Σ z², ‖z‖ = 2
    EXPECT_TRUE(RoundOffBound::IsRoundOff(RoundOffBound::kRoundOffFactor * eps * 2.0, state, 1.0));
    EXPECT_FALSE(RoundOffBound::IsRoundOff(RoundOffBound::kRoundOffFactor * eps * 2.1, state, 1.0));
    EXPECT_FALSE(RoundOffBound::IsRoundOff(0.0, state, 1.0));  // no correction of a residual: no progress
    EXPECT_TRUE(RoundOffBound::IsRoundOff(0.0, state, 0.0));
}

TEST(ResidualCriteria, NewtonStopsWhenItsCorrectionIsRoundOff) {
    for (const bool by_residual : {true, false}) {
        Model model;
        ModelPart& part = MakeLine(model, 7);
        AddSprings(part, 3.3e10, 1.0);  // nodal forces of order 1e10: their round-off is far above 1e-300
        // Stretches of order 0.1 (residual) or 5 (increment: a round-off Δx above ε itself).
        const double load = by_residual ? 7.7e9 : 7.7e12;
        for (IndexType id = 2; id <= 7; ++id) AddForce(part, 100 + id, id, load / static_cast<double>(id));
        part.GetNode(1).Fix(DISPLACEMENT_X);
        auto residual = std::make_shared<ResidualCriteria>(1e-30, 1e-300);
        auto increment = std::make_shared<DisplacementCriteria>(1e-30, 1e-300);
        ConvergenceCriteria::Pointer criteria = residual;
        if (!by_residual) criteria = increment;
        NewtonRaphsonStrategy strategy(part, std::make_shared<Scheme>(), MakeBuilder(true), criteria, 30);
        EXPECT_TRUE(strategy.Solve()) << (by_residual ? "residual" : "displacement");
        EXPECT_TRUE(by_residual ? residual->LastAtRoundOff() : increment->LastAtRoundOff())
            << (by_residual ? "residual" : "displacement");
        const double e = part.GetNode(7).FastGetSolutionStepValue(DISPLACEMENT_X) -
                         part.GetNode(6).FastGetSolutionStepValue(DISPLACEMENT_X);
        EXPECT_NEAR(3.3e10 * (e + e * e * e), load / 7.0, 1e-14 * load);
    }
}

TEST(MasterSlaveConstraints, TyingTwoChainsMakesOneChain) {
    for (const bool block : {true, false}) {
        SCOPED_TRACE(block ? "block" : "elimination");
        Model model;
        ModelPart& part = MakeLine(model, 4);
        part.AddElement(std::make_shared<testing::SpringElement>(
            1, CreateGeometry("Line2D2", {part.pGetNode(1), part.pGetNode(2)}), 2.0));
        part.AddElement(std::make_shared<testing::SpringElement>(
            2, CreateGeometry("Line2D2", {part.pGetNode(3), part.pGetNode(4)}), 2.0));
        AddForce(part, 100, 4, 3.0);
        part.GetNode(1).Fix(DISPLACEMENT_X);
        // u3 = u2 + 0.1 (a tied pair with an offset)
        part.CreateNewMasterSlaveConstraint("LinearMasterSlaveConstraint", 1, part.GetNode(2), DISPLACEMENT_X,
                                            part.GetNode(3), DISPLACEMENT_X, 1.0, 0.1);
        auto criteria = std::make_shared<DisplacementCriteria>(1e-12, 1e-14);
        NewtonRaphsonStrategy strategy(part, std::make_shared<Scheme>(), MakeBuilder(block), criteria);
        EXPECT_TRUE(strategy.Solve());
        EXPECT_NEAR(part.GetNode(2).FastGetSolutionStepValue(DISPLACEMENT_X), 1.5, 1e-12);
        EXPECT_NEAR(part.GetNode(3).FastGetSolutionStepValue(DISPLACEMENT_X), 1.6, 1e-12);
        EXPECT_NEAR(part.GetNode(4).FastGetSolutionStepValue(DISPLACEMENT_X), 3.1, 1e-12);
    }
}

/// Free vibration of m ü + k u = 0 from u(0) = 1 with @p steps steps of @p dt; returns the history u_n.
std::vector<double> Oscillate(double damp_factor_m, double dt, int steps) {
    Model model;
    ModelPart& part = MakeLine(model, 1, 2);
    part.AddElement(std::make_shared<OscillatorElement>(1, CreateGeometry("Point3D", {part.pGetNode(1)}), 1.0,
                                                        4.0 * M_PI * M_PI));  // ω = 2π, period 1
    Node& node = part.GetNode(1);
    node.FastGetSolutionStepValue(DISPLACEMENT_X) = 1.0;
    node.FastGetSolutionStepValue(ACCELERATION_X) = -4.0 * M_PI * M_PI;  // consistent initial acceleration
    auto criteria = std::make_shared<DisplacementCriteria>(1e-12, 1e-16);
    NewtonRaphsonStrategy strategy(part, std::make_shared<BossakScheme>(damp_factor_m), MakeBuilder(true), criteria);
    std::vector<double> history{1.0};
    for (int n = 1; n <= steps; ++n) {
        part.CloneTimeStep(n * dt);
        EXPECT_TRUE(strategy.Solve());
        history.push_back(node.FastGetSolutionStepValue(DISPLACEMENT_X));
    }
    return history;
}

TEST(BossakScheme, NewmarkMatchesTheExactDiscreteSolution) {
    // Average acceleration applied to ü + ω²u = 0 gives u_n = cos(n θ), tan(θ/2) = ω Δt / 2:
    // no amplitude decay, period elongated to 2π Δt / θ.
    const double dt = 0.05, omega = 2.0 * M_PI;
    const auto history = Oscillate(0.0, dt, 60);
    const double theta = 2.0 * std::atan(0.5 * omega * dt);
    for (std::size_t n = 0; n < history.size(); ++n) EXPECT_NEAR(history[n], std::cos(double(n) * theta), 1e-9);
}

TEST(BossakScheme, PredictPrescribedKeepsTheFreeDofsAndIntegratesThePrescribedVelocity) {
    // Newmark (beta 1/4, gamma 1/2), dt = 0.1, u_n = (0.1, 0.2), v_n = (0.5, 0.3), a_n = (2, -1), v_y prescribed 0.4.
    for (const bool extrapolate : {false, true}) {
        SCOPED_TRACE(extrapolate ? "Predict" : "PredictPrescribed");
        Model model;
        ModelPart& part = MakeLine(model, 1);
        part.GetProcessInfo().SetValue(DOMAIN_SIZE, 2);
        Node& node = part.GetNode(1);
        node.FastGetSolutionStepValue(DISPLACEMENT) = Array3{0.1, 0.2, 0.0};
        node.FastGetSolutionStepValue(VELOCITY) = Array3{0.5, 0.3, 0.0};
        node.FastGetSolutionStepValue(ACCELERATION) = Array3{2.0, -1.0, 0.0};
        part.CloneTimeStep(0.1);
        node.Fix(VELOCITY_Y);
        node.FastGetSolutionStepValue(VELOCITY_Y) = 0.4;
        BossakScheme scheme(0.0);
        SparseMatrixType a;
        SystemVectorType dx, b;
        DofsArrayType dofs;
        scheme.InitializeSolutionStep(part, a, dx, b);
        if (extrapolate) scheme.Predict(part, dofs, a, dx, b);
        else scheme.PredictPrescribed(part);
        // Prescribed: 0.4 = 2/dt du - v_n gives du = 0.035 either way.
        EXPECT_NEAR(node.FastGetSolutionStepValue(DISPLACEMENT_Y), 0.235, 1e-14);
        EXPECT_NEAR(node.FastGetSolutionStepValue(VELOCITY_Y), 0.4, 1e-14);
        // Free: u_n + dt v_n + dt^2/2 a_n = 0.16, or kept at 0.1 with v = -v_n, a = -4/dt v_n - a_n.
        const double du = extrapolate ? 0.06 : 0.0;
        EXPECT_NEAR(node.FastGetSolutionStepValue(DISPLACEMENT_X), 0.1 + du, 1e-14);
        EXPECT_NEAR(node.FastGetSolutionStepValue(VELOCITY_X), 2.0 / 0.1 * du - 0.5, 1e-12);
        EXPECT_NEAR(node.FastGetSolutionStepValue(ACCELERATION_X), 4.0 / 0.01 * du - 4.0 / 0.1 * 0.5 - 2.0, 1e-10);
    }
    // The static scheme prescribes nothing beyond what the processes set.
    Model model;
    ModelPart& part = MakeLine(model, 1);
    part.GetNode(1).FastGetSolutionStepValue(DISPLACEMENT_X) = 0.3;
    part.CloneTimeStep(1.0);
    Scheme().PredictPrescribed(part);
    EXPECT_EQ(part.GetNode(1).FastGetSolutionStepValue(DISPLACEMENT_X), 0.3);
}

TEST(BossakScheme, BossakDampsHighFrequenciesToTheSpectralRadiusAtInfinity) {
    // For ω Δt → ∞ the Bossak amplification has spectral radius (1 + α_m) / (1 − α_m).
    const double alpha = -0.3;
    const auto history = Oscillate(alpha, 1.0e3, 40);
    const double rho = (1.0 + alpha) / (1.0 - alpha);
    // u_n = A ρⁿ cos(nφ + ψ) makes D_n = u_{n+1} u_{n−1} − u_n² proportional to ρ^{2n}.
    auto d = [&](int n) { return history[n + 1] * history[n - 1] - history[n] * history[n]; };
    const double measured = std::pow(d(30) / d(10), 1.0 / 40.0);
    EXPECT_NEAR(measured, rho, 1e-4);
    // At a resolved frequency the amplitude still decays, slightly.
    const auto resolved = Oscillate(alpha, 0.02, 100);
    double peak_late = 0.0;
    for (std::size_t n = 80; n <= 100; ++n) peak_late = std::max(peak_late, std::abs(resolved[n]));
    EXPECT_LT(peak_late, 1.0);
    EXPECT_GT(peak_late, 0.9);
    EXPECT_THROW(BossakScheme(-0.7), InputError);
}

}  // namespace
}  // namespace contact_app

namespace contact_app {
namespace {

TEST(MixedGenericCriteria, EachVariableMeetsItsOwnTolerance) {
    Model model;
    ModelPart& part = testing::MakeLine(model, 2);
    testing::AddSprings(part, 1.0, 1.0);
    part.AddElement(std::make_shared<testing::OscillatorElement>(
        100, CreateGeometry("Point3D", {part.pGetNode(2)}), 0.0, 0.0, 10.0));
    part.GetNode(1).Fix(DISPLACEMENT_X);
    auto tight = std::make_shared<MixedGenericCriteria>(
        std::vector<MixedGenericCriteria::Entry>{{&DISPLACEMENT, 1e-12, 1e-16}});
    NewtonRaphsonStrategy strategy(part, std::make_shared<Scheme>(), MakeBuilder(true), tight, 30);
    EXPECT_TRUE(strategy.Solve());
    EXPECT_NEAR(part.GetNode(2).FastGetSolutionStepValue(DISPLACEMENT_X), 2.0, 1e-12);
    EXPECT_LE(tight->LastRatio(0), 1e-12);
    EXPECT_NE(tight->LastNorms().find("DISPLACEMENT ratio"), std::string::npos);
    // A loose tolerance on the only variable stops after the first iteration.
    Model other;
    ModelPart& second = testing::MakeLine(other, 2);
    testing::AddSprings(second, 1.0, 1.0);
    second.AddElement(std::make_shared<testing::OscillatorElement>(
        100, CreateGeometry("Point3D", {second.pGetNode(2)}), 0.0, 0.0, 10.0));
    second.GetNode(1).Fix(DISPLACEMENT_X);
    auto loose = std::make_shared<MixedGenericCriteria>(
        std::vector<MixedGenericCriteria::Entry>{{&DISPLACEMENT, 10.0, 0.0}});
    NewtonRaphsonStrategy quick(second, std::make_shared<Scheme>(), MakeBuilder(true), loose, 30);
    EXPECT_TRUE(quick.Solve());
    EXPECT_EQ(quick.GetIterationNumber(), 1);
    EXPECT_THROW(MixedGenericCriteria({}), InputError);
}

}  // namespace
}  // namespace contact_app
