// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "contact_app/solving/convergence_criteria/convergence_criteria.h"
#include "custom_conditions/contact_condition_registration.h"

namespace contact_app {

/// Mean nodal normals of the "Contact" part under the root of @p rModelPart (current configuration) and the slave /
/// master normals of every pair in "ComputingContact". No-op without a "Contact" part.
void UpdateContactNormals(ModelPart& rModelPart);

/// The active-set (and stick/slip) convergence of a mortar contact formulation (Kratos
/// BaseMortarConvergenceCriteria and its family criteria, docs/theory/contact_strategies.md §4,
/// docs/theory/active_set.md).
/// It is combined with the user's criterion by AND: a step converges when the unknowns do and the sets stop
/// changing.
/// - InitializeSolutionStep: mean nodal normals of the "Contact" part, condition NORMALs of the pairs, the pairs'
///   weighted gaps and slips with those normals, tangents.
/// - PreCriteria: the same when CONSIDER_NORMAL_VARIATION ≠ 0 (normals follow the deformation inside the step),
///   else the tangents alone; adaptive penalty when ADAPT_PENALTY.
/// - PostCriteria: the family's active-set update (ActiveSetUtilities) on the weighted gaps and slips the contact
///   strategy computed after the update; converged iff no flag changed and no slip direction turned.
///   ACTIVE_SET_CONVERGED (and SLIP_SET_CONVERGED) are stored in the ProcessInfo. ALM friction also counts the
///   slipping nodes whose traction is not dissipative (λτ·ũτ < 0), reported by LastNorms.
/// - FinalizeSolutionStep (penalty friction): TANGENT_SLIP := τ/(κε), the elastic slip the next step starts from.
/// The criteria find the parts by name under the root model part: "Contact" (slave nodes, skin conditions) and
/// "ComputingContact" (the pairs).
class BaseMortarConvergenceCriteria : public ConvergenceCriteria {
public:
    /// Which set update the family uses (a MortarType's criterion).
    using Family = MortarCriterionFamily;

    /// @param[in] family the contact family whose active (and slip) set update is applied
    /// @param[in] pure_slip frictional families: every active node slips (the slip set is not judged)
    explicit BaseMortarConvergenceCriteria(Family family, bool pure_slip = false);

    void InitializeSolutionStep(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                                const SystemVectorType& rDx, const SystemVectorType& rB,
                                const BuilderAndSolver& rBuilder) override;
    bool PreCriteria(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                     const SystemVectorType& rDx, const SystemVectorType& rB) override;
    bool PostCriteria(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                      const SystemVectorType& rDx, const SystemVectorType& rB,
                      const BuilderAndSolver& rBuilder) override;
    void FinalizeSolutionStep(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                              const SystemVectorType& rDx, const SystemVectorType& rB) override;
    std::string LastNorms() const override;
    std::string Info() const override;

    /// Flips of the last update: {ACTIVE, SLIP}.
    std::size_t LastActiveFlips() const { return mActiveFlips; }
    std::size_t LastSlipFlips() const { return mSlipFlips; }
    /// Active and slipping slave nodes after the last update.
    std::size_t ActiveNodes() const { return mActiveNodes; }
    std::size_t SlipNodes() const { return mSlipNodes; }
    /// ALM friction: slipping nodes of the last update whose traction points against the slip (λτ·ũτ < 0).
    std::size_t NonDissipativeNodes() const { return mNonDissipativeNodes; }

    /// Recomputes the nodal mean normals of "Contact", the NORMAL of every pair and, for the frictional families,
    /// the nodal slip direction TANGENT_XI (docs/theory/contact_residuals.md §2, docs/theory/active_set.md §3). Public
    /// for the strategies and tests.
    void UpdateNormalsAndTangents(ModelPart& rModelPart) const;
    /// Only the nodal slip directions TANGENT_XI of the frictional families.
    void UpdateTangents(ModelPart& rModelPart) const;

private:
    bool IsFrictional() const { return mFamily == Family::ALM_FRICTIONAL || mFamily == Family::PENALTY_FRICTIONAL; }
    void CountSets(ModelPart& rModelPart);
    void CountNonDissipative(const ModelPart& rContact);

    Family mFamily;
    bool mPureSlip;
    std::size_t mActiveFlips = 0, mSlipFlips = 0, mActiveNodes = 0, mSlipNodes = 0,
                mNonDissipativeNodes = 0;
};

}  // namespace contact_app
