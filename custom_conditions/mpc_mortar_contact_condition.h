// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "custom_conditions/paired_condition.h"
#include "custom_conditions/previous_mortar_operators.h"
#include "custom_utilities/mortar_types.h"

namespace contact_app {

/// Full (unpruned) constraint of one pair: rows (slave node i, component a) = i·d + a, columns (master node j,
/// component b) = j·d + b.
struct MPCConstraintRelation {
    Matrix relation;  ///< d n_s × d n_m
    Vector constant;  ///< d n_s
    /// d n_s × d n_s: a normal-only row of slave node i (component a* = argmax |n_a|) depends on the node's other
    /// components, n·u_s = n·(Q u_m) + c solved for u_s,a* (docs/theory/mortar.md §9).
    Matrix slave_coupling;
    /// The test relation of the rows (same shapes as relation and slave_coupling), empty when it is the relation
    /// itself: a slipping node's row tests with v = n − μe instead of n, which carries the Coulomb force μ|λ| along
    /// its slip direction e with the normal constraint force λ (docs/theory/mortar.md §9).
    Matrix test_relation;
    Matrix test_slave_coupling;
};

/// Mortar contact imposed through a multipoint constraint (Kratos MPCMortarContactCondition,
/// docs/theory/contact_residuals.md §11, docs/registered_conditions.md). The condition contributes a zero LHS and a RHS
/// that is zero
/// except for the explicit Coulomb slip force (SLIP condition, SLIP slave nodes); the contact itself is the
/// ContactMasterSlaveConstraint stored in its CONSTRAINT_POINTER value, u_s = T u_m + c on the DISPLACEMENT DoFs,
/// which the condition rebuilds from Q = D⁻¹M (current configuration, dual basis when Ae succeeds) in
/// Initialize, InitializeSolutionStep (unless BLOCKED) and InitializeNonLinearIteration (only if the condition
/// Is(INTERACTION)): frictionless (normal-only: one scalar row n·u_s = n·(Q u_m) + c per node, solved for the
/// component with the largest |n_a|, the other slave components stay free), frictional (SLIP condition: slip nodes
/// normal-only, stick nodes full Q) or tying (RIGID condition: full Q), each row weighted by the pair's share a_i/A_i
/// of the node, then the rows and columns with an absolute sum ≤ 1e−12 are pruned and the constraint DoF lists reset
/// to the surviving ones.
/// c closes WEIGHTED_GAP from the displacement it was computed at (the start of the step; the current iterate in a
/// rebuild, INTERACTION) and, on stick rows, keeps the start-of-step tangential offset (docs/theory/mortar.md §9).
/// Registers MPCMortarContactCondition{2D2N,3D3N,3D4N,3D3N4N,3D4N3N}; local system [master u, slave u].
template <int TDim, int TNumNodes, int TNumNodesMaster = TNumNodes>
class MPCMortarContactCondition : public PairedCondition {
public:
    static constexpr int MatrixSize = TDim * (TNumNodes + TNumNodesMaster);
    /// Rows / columns of T whose absolute sum is at most this are pruned from the constraint.
    /// (The reference prunes at 1e−4: that drops the small share of a pair that a sliding face has just entered, and
    /// the node's rows then no longer sum to one; measured on the 3D stick–slip block: 1.6e−5 of the normal force
    /// lost, docs/theory/mortar.md §9.)
    static constexpr double PruneTolerance = 1.0e-12;
    using Operators = MortarOperators<double, TNumNodes, TNumNodesMaster>;

    using PairedCondition::PairedCondition;
    using PairedCondition::Create;
    Condition::Pointer Create(IndexType new_id, Geometry::Pointer slave, Properties::Pointer properties,
                              Geometry::Pointer master) const override;

    /// Previous operators if Is(SLIP), then a first constraint update with an empty ProcessInfo. Nothing on the first
    /// call after Load: the restored operators, paired normal and constraint are the state the saving run had.
    void Initialize(const ProcessInfo& rCurrentProcessInfo) override;
    /// Unless Is(BLOCKED): previous operators if Is(SLIP), then the constraint update.
    void InitializeSolutionStep(const ProcessInfo& rCurrentProcessInfo) override;
    /// The constraint update, only if the condition Is(INTERACTION).
    void InitializeNonLinearIteration(const ProcessInfo& rCurrentProcessInfo) override;
    /// Previous operators recomputed if Is(SLIP) (start of the next step).
    void FinalizeSolutionStep(const ProcessInfo& rCurrentProcessInfo) override;

    /// [master DISPLACEMENT_*, slave DISPLACEMENT_*]. @throws InputError if a DoF is missing
    void GetDofList(DofsVectorType& rElementalDofList, const ProcessInfo& rCurrentProcessInfo) const override;
    /// Adds the pair's weighted gap to the historical WEIGHTED_GAP, D_jj to NODAL_AREA (dual only) and, if
    /// Is(SLIP), the weighted slip (previous operators) to the historical WEIGHTED_SLIP; sets ISOLATED afresh.
    void AddExplicitContribution(const ProcessInfo& rCurrentProcessInfo) override;
    /// @throws InputError: unpaired, wrong node counts, a node without DISPLACEMENT (historical) or its DoFs, a
    ///         slave node without NORMAL / WEIGHTED_GAP (historical)
    int Check(const ProcessInfo& rCurrentProcessInfo) const override;
    std::string Info() const override;
    /// Base state plus the previous mortar operators (a restart resumes with a consistent slip).
    void Save(Serializer& rSerializer) const override;
    void Load(Serializer& rSerializer) override;

    /// @brief T and c of the pair before pruning (docs/theory/contact_residuals.md §11), from the current coordinates.
    /// @throws InputError if an active slave node has no positive NODAL_PAUX
    MPCConstraintRelation ComputeConstraintRelation(const ProcessInfo& rCurrentProcessInfo) const;
    /// @brief Q = D⁻¹M of the pair (exposed for the tests). The reference zeroes a row with a negative entry; the dual
    ///        basis puts one in a row of every pair as soon as the faces slide by any amount, and the node then lost
    ///        that pair's share of its constraint and of its friction (docs/theory/mortar.md §9). Weighted by the area
    ///        shares, the pairs' rows assemble to the node's mortar row Σ_c M^c / Σ_c D^c_ii, negative entries
    ///        included.
    static Eigen::Matrix<double, TNumNodes, TNumNodesMaster> ComputeQ(const Operators& operators, bool dual);
    /// Rebuilds the constraint of CONSTRAINT_POINTER (no-op without one): ComputeConstraintRelation, pruning (a column
    /// stays if the relation or the test relation uses it), SetDofList, SetLocalSystem and SetTestRelation.
    void UpdateConstraint(const ProcessInfo& rCurrentProcessInfo);

    const Operators& GetPreviousMortarOperators() const { return mPreviousMortarOperators.operators; }
    bool PreviousMortarOperatorsInitialized() const { return mPreviousMortarOperators.initialized; }

protected:
    /// @brief A zero RHS: the Coulomb force of a slipping node is carried by the constraint's test relation
    ///        (MPCConstraintRelation::test_relation), not by a nodal force. The LHS is zero except, if Is(SLIP), the
    ///        tangent of the slip direction of every SLIP slave node i whose TANGENT_XI e is the direction of its slip
    ///        of the step s (+WEIGHTED_SLIP made tangent to n): the Coulomb force f = μ|λ| s/|s| (λ = REACTION·n) turns
    ///        with s, df = μ|λ| P ds/|s|, P = I − ŝŝᵀ − nnᵀ, and this pair's share of ds is M⁰_ij du_m,j − D⁰_ik du_s,k
    ///        (start-of-step operators); f reaches the slave and, by −Q_ij, the masters. The row of the component the
    ///        normal row is solved for is left out (docs/theory/mortar.md §9).
    /// @param[out] pLhs MatrixSize² (null: not asked for)
    /// @param[out] pRhs MatrixSize, zero (null: not asked for)
    /// @param[in] rCurrentProcessInfo the segmentation settings of the current operators
    void CalculateConditionSystem(Matrix* pLhs, Vector* pRhs, const ProcessInfo& rCurrentProcessInfo) override;

private:
    Operators CurrentOperators(const ProcessInfo& rCurrentProcessInfo, bool& dual) const;
    void ComputePreviousOperators(const ProcessInfo& rCurrentProcessInfo);

    PreviousMortarOperators<TNumNodes, TNumNodesMaster> mPreviousMortarOperators;
    bool mRestored = false;  ///< set by Load, consumed by the next Initialize
};

}  // namespace contact_app
