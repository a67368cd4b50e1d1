// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "custom_conditions/mortar_contact_axisym_condition.h"
#include "custom_conditions/mortar_contact_family_condition.h"

namespace contact_app {

/// Penalty frictional (Coulomb) mortar contact, displacement DoFs only (docs/theory/contact_residuals.md §7). With the
/// nodal penalty pressure λ̄_j = ε_j η_j G_j (G_j = Σ_c g̃^c_j over the node's pairs, η_j = Σ_c a_c² / A_j²; the reference
/// pushes each pair with its own ε g̃^c: docs/theory/mortar.md §7 "Nodal penalty"), an active node adds
/// S_j[δ_j(λ̄_j n_j + τ_j)], τ_j = −μ_j λ̄_j t_j (SLIP) or
/// κ ε_j s_j (stick), s_j the objective or non-objective slip of the step (switch on OPERATOR_THRESHOLD recorded
/// in MODIFIED, as the ALM family); inactive nodes add nothing. ε = INITIAL_PENALTY, δ = DYNAMIC_FACTOR,
/// μ = FRICTION_COEFFICIENT, t = TANGENT_XI (constant), κ = TANGENT_FACTOR. LHS = −∂RHS/∂q by AD. Deviations from
/// the reference (B2): the tangential traction is spread with D, M like the normal one (the reference weights it
/// with D − D_old, M − M_old, so it vanishes for small sliding), and the reference always uses the objective slip.
/// Registers Penalty[NV]FrictionalMortarContactCondition{2D2N,3D3N,3D4N,3D3N4N,3D4N3N}; size d(n_s + n_m).
template <int TDim, int TNumNodes, bool TNormalVariation, int TNumNodesMaster = TNumNodes>
class PenaltyMethodFrictionalMortarContactCondition
    : public MortarContactFamilyCondition<TDim, TNumNodes, FrictionalCase::FRICTIONAL_PENALTY, TNormalVariation,
                                          TNumNodesMaster> {
public:
    using BaseType = MortarContactFamilyCondition<TDim, TNumNodes, FrictionalCase::FRICTIONAL_PENALTY,
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

private:
    template <class T>
    void AddFrictionalResidual(const State<T>& state, const ProcessInfo& rCurrentProcessInfo,
                               LocalVector<T>& rhs) const;
};

/// Axisymmetric variant (2D2N only, MortarContactAxisymCondition): every Gauss weight (current and start-of-step
/// operators, explicit gap and slip) times 2π r / THICKNESS. Registers
/// Penalty[NV]FrictionalAxisymMortarContactCondition2D2N.
template <int TNumNodes, bool TNormalVariation>
using PenaltyMethodFrictionalMortarContactAxisymCondition =
    MortarContactAxisymCondition<PenaltyMethodFrictionalMortarContactCondition<2, TNumNodes, TNormalVariation>>;

}  // namespace contact_app
