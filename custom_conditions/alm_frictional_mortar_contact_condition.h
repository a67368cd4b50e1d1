// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "custom_conditions/mortar_contact_axisym_condition.h"
#include "custom_conditions/mortar_contact_family_condition.h"

namespace contact_app {

/// ALM frictional (Coulomb) mortar contact, vector multiplier λ_j = VECTOR_LAGRANGE_MULTIPLIER
/// (docs/theory/contact_residuals.md
/// §5). With g̃_j = −n_j·(D x1 − M x2)_j, P_j = I − n_j n_jᵀ, λ̄_n = k n·λ + ε g̃: inactive RHS_λ = −k²/ε λ_n n
/// − k²/(κε) PᵀPλ; slip S_j[δ(kλ + εg̃n)], RHS_λ = k g̃ n − k/ε Pᵀ(kPλ + μ λ̄_n t); stick S_j[δ(kλ + εg̃n + κε s)],
/// RHS_λ = k g̃ n + k Pᵀ s, s the objective or non-objective slip (switch on OPERATOR_THRESHOLD, recorded in
/// MODIFIED). k = SCALE_FACTOR, κ = TANGENT_FACTOR, ε = INITIAL_PENALTY, δ = DYNAMIC_FACTOR, μ = FRICTION_COEFFICIENT,
/// t = TANGENT_XI (held constant). LHS = −∂RHS/∂q by AD. Registers ALM[NV]FrictionalMortarContactCondition{2D2N,
/// 3D3N,3D4N,3D3N4N,3D4N3N}; local system [master u, slave u, slave λ] of size d(2n_s + n_m). The non-objective
/// slip uses the true step increment x − (X0 + d(1)) (reference bug B1 fixed); buffer size 2 suffices.
template <int TDim, int TNumNodes, bool TNormalVariation, int TNumNodesMaster = TNumNodes>
class AugmentedLagrangianMethodFrictionalMortarContactCondition
    : public MortarContactFamilyCondition<TDim, TNumNodes, FrictionalCase::FRICTIONAL, TNormalVariation,
                                          TNumNodesMaster> {
public:
    using BaseType =
        MortarContactFamilyCondition<TDim, TNumNodes, FrictionalCase::FRICTIONAL, TNormalVariation, TNumNodesMaster>;
    using typename BaseType::ADScalar;
    template <class T>
    using State = typename BaseType::template State<T>;
    template <class T>
    using LocalVector = typename BaseType::template LocalVector<T>;
    using BaseType::BaseType;
    using BaseType::Create;

    Condition::Pointer Create(IndexType new_id, Geometry::Pointer slave, Properties::Pointer properties,
                              Geometry::Pointer master) const override;

protected:
    void AddResidual(const State<double>& state, const ProcessInfo& rCurrentProcessInfo,
                     LocalVector<double>& rhs) const override;
    void AddResidual(const State<ADScalar>& state, const ProcessInfo& rCurrentProcessInfo,
                     LocalVector<ADScalar>& rhs) const override;

private:
    template <class T>
    void AddFrictionalResidual(const State<T>& state, const ProcessInfo& rCurrentProcessInfo,
                               LocalVector<T>& rhs) const;
};

/// Axisymmetric variant (2D2N only, MortarContactAxisymCondition): every Gauss weight (current and start-of-step
/// operators, explicit gap and slip) times 2π r / THICKNESS. Registers
/// ALM[NV]FrictionalAxisymMortarContactCondition2D2N.
template <int TNumNodes, bool TNormalVariation>
using AugmentedLagrangianMethodFrictionalMortarContactAxisymCondition = MortarContactAxisymCondition<
    AugmentedLagrangianMethodFrictionalMortarContactCondition<2, TNumNodes, TNormalVariation>>;

}  // namespace contact_app
