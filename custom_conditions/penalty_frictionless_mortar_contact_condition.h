// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "custom_conditions/mortar_contact_axisym_condition.h"
#include "custom_conditions/mortar_contact_family_condition.h"

namespace contact_app {

/// Penalty frictionless mortar contact, displacement DoFs only (docs/theory/contact_residuals.md §6). With
/// G_j = Σ_c g̃^c_j the node's weighted gap over all its pairs (g̃ = −n_j·(D x1 − M x2)_j per pair) and
/// η_j = Σ_c a_c² / A_j², the augmented pressure of an active node is λ̄_j = ε_j η_j G_j and
/// RHS_u1,k += δ_j λ̄_j D_jk n_j, RHS_u2,l −= δ_j λ̄_j M_jl n_j; an inactive node contributes nothing (its rows
/// and columns stay zero). On a uniform gap this is the reference's pair-wise ε g̃^c; unlike it, the partial gaps
/// of a node's pairs (of either sign on a curved non-matching face) do not push and pull it separately
/// (docs/theory/mortar.md §7 "Nodal penalty"). The blocks coupling two pairs of a node are added by
/// NodalPenaltyCoupling from GetNodalGapCoupling. ε_j = INITIAL_PENALTY and δ_j = DYNAMIC_FACTOR (nodal,
/// non-historical; δ = 1 when the node has none). LHS = −∂RHS/∂q by AD. Registers Penalty[NV]FrictionlessMortarContactCondition
/// {2D2N,3D3N,3D4N,3D3N4N,3D4N3N}; local system [master u, slave u] of size d(n_s + n_m).
template <int TDim, int TNumNodes, bool TNormalVariation, int TNumNodesMaster = TNumNodes>
class PenaltyMethodFrictionlessMortarContactCondition
    : public MortarContactFamilyCondition<TDim, TNumNodes, FrictionalCase::FRICTIONLESS_PENALTY, TNormalVariation,
                                          TNumNodesMaster> {
public:
    using BaseType = MortarContactFamilyCondition<TDim, TNumNodes, FrictionalCase::FRICTIONLESS_PENALTY,
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

/// Axisymmetric variant (2D2N only, MortarContactAxisymCondition): every Gauss weight times 2π r / THICKNESS, r =
/// x-coordinate of the point (differentiated exactly by the AD tangent). Registers
/// Penalty[NV]FrictionlessAxisymMortarContactCondition2D2N.
template <int TNumNodes, bool TNormalVariation>
using PenaltyMethodFrictionlessMortarContactAxisymCondition =
    MortarContactAxisymCondition<PenaltyMethodFrictionlessMortarContactCondition<2, TNumNodes, TNormalVariation>>;

}  // namespace contact_app
