// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <type_traits>
#include <variant>

#include "custom_conditions/frictional_mortar_contact_common.h"
#include "custom_conditions/penalty_mortar_contact_condition.h"

namespace contact_app {

/// The base a contact family's intermediate builds on: PenaltyMortarContactCondition for the two penalty families,
/// MortarContactCondition for the ALM ones.
template <int TDim, int TNumNodes, FrictionalCase TFrictional, bool TNormalVariation, int TNumNodesMaster>
using MortarContactFamilyBase =
    std::conditional_t<TFrictional == FrictionalCase::FRICTIONLESS_PENALTY ||
                           TFrictional == FrictionalCase::FRICTIONAL_PENALTY,
                       PenaltyMortarContactCondition<TDim, TNumNodes, TFrictional, TNormalVariation, TNumNodesMaster>,
                       MortarContactCondition<TDim, TNumNodes, TFrictional, TNormalVariation, TNumNodesMaster>>;

/// What the five contact families share beyond their base, chosen by the friction policy TFrictional: the state
/// encoding, the explicit pass and, for the two Coulomb families (FRICTIONAL, FRICTIONAL_PENALTY), the start-of-step
/// ("previous") mortar operators D_old, M_old of X0 + d(1) with their life cycle and restart state, the objective /
/// non-objective slip switch recorded in MODIFIED and the frictional checks (frictionless_mortar_contact_common.h,
/// frictional_mortar_contact_common.h; docs/theory/contact_residuals.md §2, §5, §7), and the DoF list, multiplier
/// values and multiplier checks, which the policy fixes. A family is this class with its friction policy (the Kratos
/// class, e.g. AugmentedLagrangianMethodFrictionalMortarContactCondition, is the policy FRICTIONAL) and its residual,
/// an overload
///   template <int TDim, int TNS, bool TNV, int TNM, class TState, class T, int TSize>
///   void AddFamilyResidual(const MortarContactFamilyCondition<TDim, TNS, FrictionalCase::X, TNV, TNM>& rCondition,
///                          const TState& s, const ProcessInfo& rCurrentProcessInfo, Eigen::Matrix<T, TSize, 1>& rhs);
/// in namespace contact_app, defined and documented in the family's .cpp (alm_frictional_mortar_contact_condition.cpp,
/// ...), which includes mortar_contact_family_condition_impl.h and instantiates the class
/// (CONTACT_APP_INSTANTIATE_CONTACT_FAMILY).
template <int TDim, int TNumNodes, FrictionalCase TFrictional, bool TNormalVariation, int TNumNodesMaster>
class MortarContactFamilyCondition
    : public MortarContactFamilyBase<TDim, TNumNodes, TFrictional, TNormalVariation, TNumNodesMaster> {
public:
    using BaseType = MortarContactFamilyBase<TDim, TNumNodes, TFrictional, TNormalVariation, TNumNodesMaster>;
    /// A Coulomb family: it keeps the previous operators and measures a slip.
    static constexpr bool IsFrictional =
        TFrictional == FrictionalCase::FRICTIONAL || TFrictional == FrictionalCase::FRICTIONAL_PENALTY;
    /// A family with one multiplier per slave node and dimension (VECTOR_LAGRANGE_MULTIPLIER).
    static constexpr bool HasVectorMultiplier =
        TFrictional == FrictionalCase::FRICTIONAL || TFrictional == FrictionalCase::FRICTIONLESS_COMPONENTS;
    using typename BaseType::ADScalar;
    using typename BaseType::NormalScalar;
    template <class T>
    using State = typename BaseType::template State<T>;
    template <class T>
    using LocalVector = typename BaseType::template LocalVector<T>;
    using BaseType::BaseType;
    using BaseType::Create;

    /// @param[in] new_id id of the new pair
    /// @param[in] slave,master the faces of the new pair (shared)
    /// @param[in] properties its properties (shared)
    /// @return a new pair of this family
    Condition::Pointer Create(IndexType new_id, Geometry::Pointer slave, Properties::Pointer properties,
                              Geometry::Pointer master) const override;
    /// Base reset plus (Coulomb) the previous operators (zero, not initialized).
    void Initialize(const ProcessInfo& rCurrentProcessInfo) override;
    /// Coulomb: computes the start-of-step operators once per step (X0 + d(1)).
    void InitializeSolutionStep(const ProcessInfo& rCurrentProcessInfo) override;
    /// Coulomb: lets the next step recompute the previous operators.
    void FinalizeSolutionStep(const ProcessInfo& rCurrentProcessInfo) override;
    /// Frictionless: Σ_i 2^i over the slave nodes that are ACTIVE. Coulomb: Σ_i s_i 3^i, s_i = 0 inactive,
    /// 1 active-slip, 2 active-stick.
    int GetActiveInactiveValue() const override;
    /// Adds the pair's weighted gap g̃ to the historical WEIGHTED_GAP and D_jj (= ∫Φ_j N_j, dual basis only) to the
    /// non-historical NODAL_AREA of the slave nodes (or flags ISOLATED); Coulomb: also the weighted slip (objective
    /// iff not MODIFIED) to the historical WEIGHTED_SLIP. Unlike the reference, whose penalty explicit contribution
    /// hard-codes the plane case, the axisymmetric variants weight all by 2π r / t, as their implicit operators
    /// (docs/theory/contact_residuals.md §9).
    void AddExplicitContribution(const ProcessInfo& rCurrentProcessInfo) override;
    /// Base checks, then the family's multipliers on the slave nodes (LAGRANGE_MULTIPLIER_CONTACT_PRESSURE for ALM
    /// frictionless, VECTOR_LAGRANGE_MULTIPLIER for ALM frictionless components and ALM frictional: historical and
    /// DoFs); Coulomb: WEIGHTED_SLIP (historical) and a buffer ≥ 2.
    int Check(const ProcessInfo& rCurrentProcessInfo) const override;
    /// @param[out] rElementalDofList [master DISPLACEMENT_*, slave DISPLACEMENT_*] and the slave multipliers:
    ///             LAGRANGE_MULTIPLIER_CONTACT_PRESSURE (ALM frictionless), VECTOR_LAGRANGE_MULTIPLIER_* node by node
    ///             (ALM frictionless components, ALM frictional), none (penalty)
    /// @param[in] rCurrentProcessInfo not read
    /// @throws InputError if a DoF is missing
    void GetDofList(DofsVectorType& rElementalDofList, const ProcessInfo& rCurrentProcessInfo) const override;
    /// Paired-condition state plus (Coulomb) the previous operators and their flags (restart with a consistent slip).
    void Save(Serializer& rSerializer) const override;
    void Load(Serializer& rSerializer) override;
    /// Coulomb: what the family residual measures the slip of the step with (frictional_detail::MakeSlipData).
    /// @param[in] needs_slip whether some slave node is active (only then are the start-of-step coordinates read)
    frictional_detail::SlipData<TDim, TNumNodes, TNumNodesMaster> SlipOfStep(bool needs_slip) const;

protected:
    /// The λ block of q, in GetDofList's order (empty for a penalty family).
    typename BaseType::MultiplierVector MultiplierValues() const override;
    /// Coulomb: records the objective switch of this configuration in MODIFIED.
    void InitializeResidual(const MortarOperators<double, TNumNodes, TNumNodesMaster>& operators,
                            const ProcessInfo& rCurrentProcessInfo) override;
    /// The family's residual for the double and the AD scalar alike: the AddFamilyResidual overload of this friction
    /// policy, defined in the family's .cpp, which instantiates the class.
    void AddResidual(const State<double>& state, const ProcessInfo& rCurrentProcessInfo,
                     LocalVector<double>& rhs) const override;
    void AddResidual(const State<ADScalar>& state, const ProcessInfo& rCurrentProcessInfo,
                     LocalVector<ADScalar>& rhs) const override;
    /// The same over the nodal normals: the penalty families without NV only (the others never couple them).
    void AddResidual(const State<NormalScalar>& state, const ProcessInfo& rCurrentProcessInfo,
                     LocalVector<NormalScalar>& rhs) const override;

private:
    /// The start-of-step operators of a Coulomb family (nothing for a frictionless one).
    std::conditional_t<IsFrictional, PreviousMortarOperators<TNumNodes, TNumNodesMaster>,
                       std::monostate>
        mPreviousMortarOperators;
};

}  // namespace contact_app
