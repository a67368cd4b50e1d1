// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "contact_app/solving/convergence_criteria/convergence_criteria.h"

namespace contact_app {

/// Active-set (and stick/slip) convergence of the MPC contact route (Kratos MPCContactCriteria,
/// docs/theory/active_set.md §4). For each SLAVE node of "Contact":
/// \f$ p = (F\cdot n)/A_\ell \f$, ACTIVE ⇔ \f$ p < -f_R E \f$ or \f$ \tilde g/A < -10^{-10} h \f$ (h = NODAL_H, else
/// \f$\sqrt{A_\ell}\f$: a gap just closed by the constraint is zero up to round-off), with F the contact force,
/// n = NORMAL, \f$A_\ell\f$ = NODAL_MAUX (lumped slave area, computed if absent), \f$f_R\f$ =
/// REACTION_CHECK_STIFFNESS_FACTOR (ProcessInfo, 1e-12 if absent), E the largest YOUNG_MODULUS of the elements.
/// Frictional (SLIP model part): stick ⇔ μ > 0 and \f$|F_\tau| \le -\mu F\cdot n\f$ ([BUG?] B9 done right: the
/// reference compares a traction with a force), μ = FRICTION_COEFFICIENT of the node.
/// F: the slave node's own REACTION. The elimination builder writes the reaction of every constraint slave DoF,
/// which is the force the constraint exerts on the slave side; it replaces the reference's mortar mapping of the
/// master reactions (−1 × mapped master reaction), which equals it up to the mapping error. Inactive (unconstrained)
/// slave nodes carry no contact force (F = 0): only their gap can activate them.
/// Pair conditions of "ComputingContact" whose slave nodes are all inactive are switched off with their constraint
/// (CONSTRAINT_POINTER); the others on. Converged iff no ACTIVE (or SLIP) flag changed.
class MPCContactCriteria : public ConvergenceCriteria {
public:
    MPCContactCriteria() = default;

    /// CONTACT_FORCE := 0 on the slave nodes, WEIGHTED_GAP(1) := WEIGHTED_GAP, g̃ and NODAL_AREA recomputed
    /// (ContactUtilities::ComputeExplicitContributionConditions on "ComputingContact").
    bool PreCriteria(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                     const SystemVectorType& rDx, const SystemVectorType& rB) override;
    /// The active-set update described above (only when NL_ITERATION_NUMBER > 0).
    /// Writes NORMAL_CONTACT_STRESS = p (active nodes), TANGENTIAL_CONTACT_STRESS (frictional, active nodes:
    /// |F_τ|/A_ℓ in stick, −μ(F·n)/A_ℓ in slip) and CONTACT_FORCE ((F·n)n/NODAL_PAUX frictionless, F/NODAL_PAUX
    /// frictional) on the slave nodes, and the traction in the names the other families use:
    /// AUGMENTED_NORMAL_CONTACT_PRESSURE = p, AUGMENTED_TANGENT_CONTACT_PRESSURE = F_τ/A_ℓ (the friction it imposes;
    /// zero on inactive nodes).
    /// @throws InputError if the model part has no "Contact" sub model part
    bool PostCriteria(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                      const SystemVectorType& rDx, const SystemVectorType& rB,
                      const BuilderAndSolver& rBuilder) override;
    std::string LastNorms() const override;
    std::string Info() const override { return "MPCContactCriteria"; }

    /// Flips of the last update (ACTIVE and SLIP) and the active / slipping slave nodes after it.
    std::size_t LastActiveFlips() const { return mActiveFlips; }
    std::size_t LastSlipFlips() const { return mSlipFlips; }
    std::size_t ActiveNodes() const { return mActiveNodes; }
    std::size_t SlipNodes() const { return mSlipNodes; }
    /// Largest change |e_new − e_old| of a slipping node's unit slip direction in the last update (0 if none).
    double LastMaxDirectionTurn() const { return mMaxTurn; }

    /// @brief NODAL_MAUX := Σ over the SLAVE conditions of "Contact" holding the node of |face| / (its number of nodes)
    ///        (current configuration), on every node of "Contact". No-op without a "Contact" part.
    static void ComputeLumpedSlaveArea(ModelPart& rModelPart);

private:
    std::size_t mActiveFlips = 0, mSlipFlips = 0, mActiveNodes = 0, mSlipNodes = 0;
    double mMaxTurn = 0.0;
};

}  // namespace contact_app
