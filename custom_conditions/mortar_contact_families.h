// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "custom_conditions/mortar_contact_axisym_condition.h"
#include "custom_conditions/mortar_contact_family_condition.h"

/// The five registered contact families under their Kratos class names: each is MortarContactFamilyCondition with its
/// friction policy, whose residual (an AddFamilyResidual overload) the family's .cpp defines and instantiates
/// (alm_frictionless_mortar_contact_condition.cpp, ..., penalty_frictional_mortar_contact_condition.cpp).

namespace contact_app {

/// ALM frictionless mortar contact, scalar multiplier λ_j = LAGRANGE_MULTIPLIER_CONTACT_PRESSURE per slave
/// node (docs/theory/contact_residuals.md §3). With g̃_j = −n_j·(D x1 − M x2)_j and λ̄_j = k λ_j + ε_j g̃_j:
/// active node: RHS_u1,k += δ_j λ̄_j D_jk n_j, RHS_u2,l −= δ_j λ̄_j M_jl n_j, RHS_λj += k g̃_j;
/// inactive node: RHS_λj += −k²/ε_j λ_j. k = SCALE_FACTOR (ProcessInfo), ε_j = INITIAL_PENALTY and
/// δ_j = DYNAMIC_FACTOR (nodal, non-historical; δ = 1 when the node has none). LHS = −∂RHS/∂q by AD.
/// Registers ALM[NV]FrictionlessMortarContactCondition{2D2N,3D3N,3D4N,3D3N4N,3D4N3N}; local system
/// [master u, slave u, λ] of size d(n_s + n_m) + n_s.
template <int TDim, int TNumNodes, bool TNormalVariation, int TNumNodesMaster = TNumNodes>
using AugmentedLagrangianMethodFrictionlessMortarContactCondition =
    MortarContactFamilyCondition<TDim, TNumNodes, FrictionalCase::FRICTIONLESS, TNormalVariation, TNumNodesMaster>;

/// Axisymmetric variant (2D2N only, MortarContactAxisymCondition): every Gauss weight times 2π r / THICKNESS, r =
/// x-coordinate of the point (differentiated exactly by the AD tangent). Registers
/// ALM[NV]FrictionlessAxisymMortarContactCondition2D2N.
template <int TNumNodes, bool TNormalVariation>
using AugmentedLagrangianMethodFrictionlessMortarContactAxisymCondition =
    MortarContactAxisymCondition<
        AugmentedLagrangianMethodFrictionlessMortarContactCondition<2, TNumNodes, TNormalVariation>>;

/// ALM frictionless mortar contact with a vector multiplier λ_j = VECTOR_LAGRANGE_MULTIPLIER per slave node
/// (docs/theory/contact_residuals.md §4). With g̃_j = −n_j·(D x1 − M x2)_j and P_j = I − n_j n_jᵀ:
/// active node: S_j[δ_j (k λ_j + ε_j g̃_j n_j)] on the displacement rows (the full vector k λ_j, tangential
/// part included), RHS_λj += k g̃_j n_j − k²/ε_j P_jᵀ P_j λ_j (the tangential part is regularised to zero);
/// inactive node: RHS_λj += −k²/ε_j λ_j. k = SCALE_FACTOR (ProcessInfo), ε_j = INITIAL_PENALTY and
/// δ_j = DYNAMIC_FACTOR (nodal, non-historical; δ = 1 when absent; δ only scales the displacement rows).
/// LHS = −∂RHS/∂q by AD. Registers ALM[NV]FrictionlessComponentsMortarContactCondition{2D2N,3D3N,3D4N,3D3N4N,
/// 3D4N3N} (no axisymmetric variant); local system [master u, slave u, slave λ (d per node)] of size d(2n_s + n_m).
template <int TDim, int TNumNodes, bool TNormalVariation, int TNumNodesMaster = TNumNodes>
using AugmentedLagrangianMethodFrictionlessComponentsMortarContactCondition =
    MortarContactFamilyCondition<TDim, TNumNodes, FrictionalCase::FRICTIONLESS_COMPONENTS, TNormalVariation,
                                 TNumNodesMaster>;

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
using AugmentedLagrangianMethodFrictionalMortarContactCondition =
    MortarContactFamilyCondition<TDim, TNumNodes, FrictionalCase::FRICTIONAL, TNormalVariation, TNumNodesMaster>;

/// Axisymmetric variant (2D2N only, MortarContactAxisymCondition): every Gauss weight (current and start-of-step
/// operators, explicit gap and slip) times 2π r / THICKNESS. Registers
/// ALM[NV]FrictionalAxisymMortarContactCondition2D2N.
template <int TNumNodes, bool TNormalVariation>
using AugmentedLagrangianMethodFrictionalMortarContactAxisymCondition =
    MortarContactAxisymCondition<
        AugmentedLagrangianMethodFrictionalMortarContactCondition<2, TNumNodes, TNormalVariation>>;

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
using PenaltyMethodFrictionlessMortarContactCondition =
    MortarContactFamilyCondition<TDim, TNumNodes, FrictionalCase::FRICTIONLESS_PENALTY, TNormalVariation,
                                 TNumNodesMaster>;

/// Axisymmetric variant (2D2N only, MortarContactAxisymCondition): every Gauss weight times 2π r / THICKNESS, r =
/// x-coordinate of the point (differentiated exactly by the AD tangent). Registers
/// Penalty[NV]FrictionlessAxisymMortarContactCondition2D2N.
template <int TNumNodes, bool TNormalVariation>
using PenaltyMethodFrictionlessMortarContactAxisymCondition =
    MortarContactAxisymCondition<PenaltyMethodFrictionlessMortarContactCondition<2, TNumNodes, TNormalVariation>>;

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
using PenaltyMethodFrictionalMortarContactCondition =
    MortarContactFamilyCondition<TDim, TNumNodes, FrictionalCase::FRICTIONAL_PENALTY, TNormalVariation,
                                 TNumNodesMaster>;

/// Axisymmetric variant (2D2N only, MortarContactAxisymCondition): every Gauss weight (current and start-of-step
/// operators, explicit gap and slip) times 2π r / THICKNESS. Registers
/// Penalty[NV]FrictionalAxisymMortarContactCondition2D2N.
template <int TNumNodes, bool TNormalVariation>
using PenaltyMethodFrictionalMortarContactAxisymCondition =
    MortarContactAxisymCondition<PenaltyMethodFrictionalMortarContactCondition<2, TNumNodes, TNormalVariation>>;

}  // namespace contact_app
