// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "custom_conditions/mortar_contact_family_condition.h"

namespace contact_app {

/// ALM frictionless mortar contact with a vector multiplier λ_j = VECTOR_LAGRANGE_MULTIPLIER per slave node
/// (docs/theory/contact_residuals.md §4). With g̃_j = −n_j·(D x1 − M x2)_j and P_j = I − n_j n_jᵀ:
/// active node: S_j[δ_j (k λ_j + ε_j g̃_j n_j)] on the displacement rows (the full vector k λ_j, tangential
/// part included), RHS_λj += k g̃_j n_j − k²/ε_j P_jᵀ P_j λ_j (the tangential part is regularised to zero);
/// inactive node: RHS_λj += −k²/ε_j λ_j. k = SCALE_FACTOR (ProcessInfo), ε_j = INITIAL_PENALTY and
/// δ_j = DYNAMIC_FACTOR (nodal, non-historical; δ = 1 when absent; δ only scales the displacement rows).
/// LHS = −∂RHS/∂q by AD. Registers ALM[NV]FrictionlessComponentsMortarContactCondition{2D2N,3D3N,3D4N,3D3N4N,
/// 3D4N3N} (no axisymmetric variant); local system [master u, slave u, slave λ (d per node)] of size d(2n_s + n_m).
template <int TDim, int TNumNodes, bool TNormalVariation, int TNumNodesMaster = TNumNodes>
class AugmentedLagrangianMethodFrictionlessComponentsMortarContactCondition
    : public MortarContactFamilyCondition<TDim, TNumNodes, FrictionalCase::FRICTIONLESS_COMPONENTS, TNormalVariation,
                                          TNumNodesMaster> {
public:
    using BaseType = MortarContactFamilyCondition<TDim, TNumNodes, FrictionalCase::FRICTIONLESS_COMPONENTS,
                                                  TNormalVariation, TNumNodesMaster>;
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

}  // namespace contact_app
