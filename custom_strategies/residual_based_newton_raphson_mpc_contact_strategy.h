// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>

#include "contact_app/solving/strategies/newton_raphson_strategy.h"
#include "custom_strategies/mpc_contact_criteria.h"

namespace contact_app {

/// Settings of the MPC contact Newton strategy (mpc_contact_settings keys of the same names).
struct MPCContactStrategySettings {
    /// Outer active-set loops when the ProcessInfo is INTERACTION (simplified semi-smooth Newton).
    int inner_loop_iterations = 5;
    /// Rebuild every pair's constraint (T, c) at each Newton iteration (pairs flagged INTERACTION), not only at the
    /// start of the step.
    bool update_each_nl_iteration = false;
    /// Node-to-node enforcement: accepted for compatibility, not implemented (as in the reference).
    bool enforce_ntn = false;
};

/// Newton–Raphson for the MPC contact route (Kratos ResidualBasedNewtonRaphsonMPCContactStrategy,
/// docs/theory/contact_strategies.md §3). The contact is a set of ContactMasterSlaveConstraints u_s = T u_m + c living
/// in
/// "ComputingContact" (a sub model part of the assembled part, so the builder sees them); the criterion
/// (And(structural, MPCContactCriteria)) switches pairs and constraints on and off.
/// - InitializeSolutionStep: nodal weights NODAL_PAUX (number of SLAVE conditions of "Contact" holding the node),
///   then the base (the pairs rebuild their constraints from the start-of-step state).
/// - Predict: the base prediction (which imposes u_s = T u_m + c) of what the step prescribes only (the scheme's
///   PredictPrescribed, as the mortar contact strategy: no extrapolation through the contact surface in dynamics),
///   then the weighted gaps at the predicted state.
/// - Each Newton iteration: weights, InitializeNonLinIteration, the constraints rebuilt at the current state if
///   update_each_nl_iteration or if the last criterion check changed the active set (an inactive slave node loses
///   its rows; the reference waits for the next step), u_s := T u_m + c on the active constraints (a rebuilt or
///   switched-on constraint is satisfied exactly before the solve: the builder only eliminates increments),
///   build/solve/update, reactions (the contact forces the criterion reads), criterion.
/// - ProcessInfo INTERACTION (simplified_semi_smooth_newton): up to inner_loop_iterations such Newton loops, each
///   followed by a check of the internal MPCContactCriteria; stops when the set no longer changes.
class ResidualBasedNewtonRaphsonMPCContactStrategy : public NewtonRaphsonStrategy {
public:
    /// @throws InputError if inner_loop_iterations < 1
    ResidualBasedNewtonRaphsonMPCContactStrategy(ModelPart& rModelPart, Scheme::Pointer scheme,
                                                 BuilderAndSolver::Pointer builder,
                                                 ConvergenceCriteria::Pointer criteria, int max_iterations = 30,
                                                 StrategySettings settings = {},
                                                 MPCContactStrategySettings mpc_settings = {});

    void Initialize() override;
    void InitializeSolutionStep() override;
    void Predict() override;
    bool SolveSolutionStep() override;

    /// @brief NODAL_PAUX := number of SLAVE conditions of "Contact" (under the root of @p rModelPart) holding the
    ///        node, on every node of "Contact". No-op without a "Contact" part.
    static void ComputeNodalWeights(ModelPart& rModelPart);
    /// Outer loops used by the last step (1 without INTERACTION on the ProcessInfo).
    int GetInnerLoopIterations() const { return mInnerLoops; }
    const MPCContactStrategySettings& MPCSettings() const { return mMPCSettings; }

protected:
    void PredictUnknowns() override;

private:
    /// One Newton loop as described above. @return the criterion's verdict.
    bool NewtonLoop();
    void ComputeExplicitContributions();
    /// Every pair of "ComputingContact" rebuilds its constraint at the current configuration, flagged INTERACTION so
    /// that it refers the gap part of its constant to the current displacement.
    void RefreshConstraints();

    MPCContactStrategySettings mMPCSettings;
    std::shared_ptr<MPCContactCriteria> mActiveSetCriteria = std::make_shared<MPCContactCriteria>();
    int mInnerLoops = 0;
    bool mRefreshConstraints = false;
};

}  // namespace contact_app
