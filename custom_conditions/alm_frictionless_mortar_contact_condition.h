// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "custom_conditions/mortar_contact_axisym_condition.h"
#include "custom_conditions/mortar_contact_family_condition.h"

namespace contact_app {

/// ALM frictionless mortar contact, scalar multiplier λ_j = LAGRANGE_MULTIPLIER_CONTACT_PRESSURE per slave
/// node (docs/theory/contact_residuals.md §3). With g̃_j = −n_j·(D x1 − M x2)_j and λ̄_j = k λ_j + ε_j g̃_j:
/// active node: RHS_u1,k += δ_j λ̄_j D_jk n_j, RHS_u2,l −= δ_j λ̄_j M_jl n_j, RHS_λj += k g̃_j;
/// inactive node: RHS_λj += −k²/ε_j λ_j. k = SCALE_FACTOR (ProcessInfo), ε_j = INITIAL_PENALTY and
/// δ_j = DYNAMIC_FACTOR (nodal, non-historical; δ = 1 when the node has none). LHS = −∂RHS/∂q by AD.
/// Registers ALM[NV]FrictionlessMortarContactCondition{2D2N,3D3N,3D4N,3D3N4N,3D4N3N}; local system
/// [master u, slave u, λ] of size d(n_s + n_m) + n_s.
template <int TDim, int TNumNodes, bool TNormalVariation, int TNumNodesMaster = TNumNodes>
class AugmentedLagrangianMethodFrictionlessMortarContactCondition
    : public MortarContactFamilyCondition<TDim, TNumNodes, FrictionalCase::FRICTIONLESS, TNormalVariation,
                                          TNumNodesMaster> {
public:
    using BaseType =
        MortarContactFamilyCondition<TDim, TNumNodes, FrictionalCase::FRICTIONLESS, TNormalVariation, TNumNodesMaster>;
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
};

/// Axisymmetric variant (2D2N only, MortarContactAxisymCondition): every Gauss weight times 2π r / THICKNESS, r =
/// x-coordinate of the point (differentiated exactly by the AD tangent). Registers
/// ALM[NV]FrictionlessAxisymMortarContactCondition2D2N.
template <int TNumNodes, bool TNormalVariation>
using AugmentedLagrangianMethodFrictionlessMortarContactAxisymCondition = MortarContactAxisymCondition<
    AugmentedLagrangianMethodFrictionlessMortarContactCondition<2, TNumNodes, TNormalVariation>>;

}  // namespace contact_app
