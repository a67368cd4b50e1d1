// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "contact_app/solving/convergence_criteria/convergence_criteria.h"

namespace contact_app {

/// How a block of unknowns is judged converged.
enum class ContactBlockMeasure {
    INCREMENT,  ///< ‖Δx‖ / ‖x‖ and ‖Δx‖ / n
    RESIDUAL    ///< Σr² / Σr²(first iteration of the step) and Σr² / n (squared, as the reference)
};

/// Tolerances of the two blocks (displacement, multiplier) and of the frictional split of the multipliers.
struct ContactCriteriaTolerances {
    double displacement_relative = 1.0e-4, displacement_absolute = 1.0e-9;
    double lm_relative = 1.0e-4, lm_absolute = 1.0e-9;
    /// Frictional split: stick and slip tangential blocks (used when split_frictional).
    double stick_relative = 1.0e-4, stick_absolute = 1.0e-9;
    double slip_relative = 1.0e-4, slip_absolute = 1.0e-9;
    /// The tangential blocks also count as converged when |tangent| / |normal| ≤ this ratio.
    double ratio_normal_tangent_threshold = 1.0e-4;
    /// With no active node the multiplier block counts as converged unless contact is required.
    bool ensure_contact = false;
    /// Split the vector multipliers into normal, stick-tangential and slip-tangential blocks.
    bool split_frictional = false;
    /// Every active node slips (no stick block).
    bool pure_slip = false;
};

/// Convergence of a displacement–multiplier (mortar contact) system by blocks (Kratos
/// DisplacementLagrangeMultiplier[Residual|Mixed][Frictional]ContactCriteria, docs/theory/contact_strategies.md §4).
/// Displacement DoFs are DISPLACEMENT_X/Y/Z (and ROTATION_*); multiplier DoFs LAGRANGE_MULTIPLIER_CONTACT_PRESSURE,
/// VECTOR_LAGRANGE_MULTIPLIER_X/Y/Z and SCALAR_LAGRANGE_MULTIPLIER; other DoFs count with the displacements. Only free,
/// unconstrained equations count. Residual ratios are ‖r‖ / ‖r₀‖ with r₀ the larger of the step-start residual and
/// the residual at the predicted state, or the first non-zero one for a block that had none (the reference compares
/// squared norms, which squares its tolerances). A block whose correction is at round-off (RoundOffBound) is
/// converged too. The frictional split projects each node's multiplier on its NORMAL: λ_n = (λ·n) n, λ_t = λ − λ_n
/// (the reference uses the component-wise product λ_c n_c, which is not a projection); nodes with μ ≈ 0 count as
/// normal only.
class DisplacementLagrangeMultiplierContactCriteria : public ConvergenceCriteria {
public:
    DisplacementLagrangeMultiplierContactCriteria(ContactBlockMeasure displacement_measure,
                                                  ContactBlockMeasure lm_measure, ContactCriteriaTolerances tolerances);

    void InitializeSolutionStep(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                                const SystemVectorType& rDx, const SystemVectorType& rB,
                                const BuilderAndSolver& rBuilder) override;
    void InitializePredictedResidual(DofsArrayType& rDofSet, const SystemVectorType& rB,
                                     const BuilderAndSolver& rBuilder) override;
    bool PostCriteria(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                      const SystemVectorType& rDx, const SystemVectorType& rB,
                      const BuilderAndSolver& rBuilder) override;
    bool GetActualizeRHSflag() const override;
    std::string LastNorms() const override;
    std::string Info() const override;

    /// Block indices of the last norms.
    enum Block { DISPLACEMENT = 0, LM_NORMAL = 1, LM_STICK = 2, LM_SLIP = 3, NUM_BLOCKS = 4 };
    double LastRatio(Block block) const { return mRatio[block]; }
    double LastAbsolute(Block block) const { return mAbsolute[block]; }
    bool BlockConverged(Block block) const { return mConverged[block]; }

private:
    struct Sums {
        double value[NUM_BLOCKS] = {0.0, 0.0, 0.0, 0.0};
        double increment[NUM_BLOCKS] = {0.0, 0.0, 0.0, 0.0};
        double residual[NUM_BLOCKS] = {0.0, 0.0, 0.0, 0.0};
        /// Σ z² of RoundOffBound.
        double state[NUM_BLOCKS] = {0.0, 0.0, 0.0, 0.0};
        std::size_t count[NUM_BLOCKS] = {0, 0, 0, 0};
        std::size_t active_nodes = 0;
    };
    Sums Accumulate(const DofsArrayType& rDofSet, const SystemVectorType& rDx, const SystemVectorType& rB,
                    const BuilderAndSolver& rBuilder) const;
    ContactBlockMeasure MeasureOf(Block block) const {
        return block == DISPLACEMENT ? mDisplacementMeasure : mLMMeasure;
    }

    ContactBlockMeasure mDisplacementMeasure, mLMMeasure;
    ContactCriteriaTolerances mTolerances;
    double mInitialResidual[NUM_BLOCKS] = {0.0, 0.0, 0.0, 0.0};
    double mRatio[NUM_BLOCKS] = {0.0, 0.0, 0.0, 0.0};
    double mAbsolute[NUM_BLOCKS] = {0.0, 0.0, 0.0, 0.0};
    bool mConverged[NUM_BLOCKS] = {false, false, false, false};
    bool mAtRoundOff[NUM_BLOCKS] = {false, false, false, false};
};

}  // namespace contact_app
