// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>
#include <cstddef>

#include "contact_app/kernel/node.h"

namespace contact_app {

class ModelPart;
class ProcessInfo;

/// Semi-smooth Newton active-set and stick/slip updates of the mortar contact families (Kratos
/// ActiveSetUtilities, docs/theory/active_set.md). Each function evaluates the
/// SLAVE nodes of the sub model part "Contact" of @p model_part (of @p model_part itself when it has no such
/// child), writes AUGMENTED_NORMAL_CONTACT_PRESSURE (and AUGMENTED_TANGENT_CONTACT_PRESSURE for friction) as
/// non-historical values and returns the number of flips (0 = the set converged). Nothing is evaluated (0 is
/// returned) unless @p model_part Is(INTERACTION) (full semi-smooth Newton) or NL_ITERATION_NUMBER == 1.
/// Inputs: k = ProcessInfo SCALE_FACTOR, ε = nodal INITIAL_PENALTY if the node has it else the ProcessInfo one,
/// g̃ = WEIGHTED_GAP, ũτ = WEIGHTED_SLIP, n = NORMAL, μ = nodal FRICTION_COEFFICIENT, κ = TANGENT_FACTOR and
/// SLIP_THRESHOLD (ProcessInfo, default 0). Comparisons are strict ("< 0").
/// Deviations (docs/theory/mortar.md §8): the stick/slip test and the slip direction use the trial traction λ̄τ of
/// TrialTangentialTraction on every node (the reference scales its slip term by SLIP_AUGMENTATION_COEFFICIENT, 0 by
/// default, on slipping nodes, and takes the direction from λτ alone, which never turns in 3D); a slip node whose
/// direction turned by more than kSlipDirectionTolerance (weighted by its friction bound) since the build counts as a
/// slip-set change; the penalty
/// slip traction has the orientation of its stick value (reference [BUG?] B10); an ALM node with μ < machine ε
/// always slips (the reference's Coulomb test is 0/0 there and the node flips between stick and slip).
namespace ActiveSetUtilities {

/// |t_new − t_build| (unit vectors, ≈ radians) above which a slipping node has turned, scaled by the node's share
/// μ|λ̄n| / max_j μ|λ̄n,j| of the largest friction bound (a node without friction may turn freely).
inline constexpr double kSlipDirectionTolerance = 1e-4;

/// The factor c_t/ε of the ALM slip law's trial λ̄τ = k Pλ + c_t P ũτ: max(κ, 1). κ (TANGENT_FACTOR) is the ratio of
/// the stick penalty to the normal one; the slip law only needs the direction of λ̄τ, and a converged slip state does
/// not depend on c_t > 0, but with c_t = κε small (the users' models run κ = 0.025) a slowly slipping node's direction
/// equation is stiff only over rotations θ ≲ √(2 c_t|ũτ| / μ|λ̄n|) and Newton over-rotates (docs/theory/mortar.md §8).
inline double SlipTrialFactor(double tangent_factor) {
    return tangent_factor > 1.0 ? tangent_factor : 1.0;
}

/// How far beyond a turn the raised slip trial's linearisation reaches: θ_f = 2θ (RaiseSlipTrialFactor).
inline constexpr double kSlipTurnMargin = 2.0;

/// The factor c_t/ε of a slave node's slip direction: its SLIP_TRIAL_FACTOR when set (> 0), else SlipTrialFactor(κ).
double SlipTrialFactor(const Node& node, const ProcessInfo& process_info);

/// Sets SLIP_TRIAL_FACTOR := max(κ, 1) on the SLAVE nodes of @p rContact (at the start of a step). The ALM frictional
/// set update raises it on a slipping node whose direction turned beyond what the slip law's tangent covers, for the
/// rest of the step (docs/theory/mortar.md §8).
void ResetSlipTrialFactors(ModelPart& rContact);

/// The trial tangential traction of a slave node that the stick/slip test reads: λ̄τ = k Pλ + max(κ, 1) ε P ũτ (ALM,
/// @p with_multiplier) or
/// κ ε P(ũτ + e) (penalty, e = TANGENT_SLIP the elastic weighted slip carried over from earlier steps).
Array3 TrialTangentialTraction(const Node& node, const ProcessInfo& process_info, bool with_multiplier);

/// The trial whose direction the ALM slip law imposes: k Pλ + c_t,j P ũτ with the node's own c_t,j =
/// SlipTrialFactor(node) ε. At a converged slip state kPλ ∥ Pũτ, so it points as the test's trial does.
Array3 SlipDirectionTrial(const Node& node, const ProcessInfo& process_info);

/// @brief λ̄n = ε η G; ACTIVE ⇔ λ̄n < 0, or the node was ACTIVE and its mean gap G/A opened by less than
///        @p release_gap (the largest displacement correction of the iterate; 0: no hold), which counts as a change
///        (docs/theory/active_set.md §2). @return the number of ACTIVE flips and held open nodes
std::size_t ComputePenaltyFrictionlessActiveSet(ModelPart& model_part, double release_gap = 0.0);
/// @brief λ̄n = k λ + ε g̃ (λ = LAGRANGE_MULTIPLIER_CONTACT_PRESSURE); on activation λ := λ̄n / k.
/// @return the number of ACTIVE flips
std::size_t ComputeALMFrictionlessActiveSet(ModelPart& model_part);
/// @brief λ̄n = k n·λ + ε g̃ (λ = VECTOR_LAGRANGE_MULTIPLIER); on activation λ := n λ̄n / k.
/// @return the number of ACTIVE flips
std::size_t ComputeALMFrictionlessComponentsActiveSet(ModelPart& model_part);
/// @brief Penalty frictional: λ̄n = ε g̃; active nodes: λ̄τ = κ ε P(ũτ + e), stick ⇔ |λ̄τ| ≤ −μ λ̄n, slip traction
///        −μ λ̄n λ̄τ/|λ̄τ|; inactive nodes: ũτ := 0, SLIP reset. The normal set is the frictionless one with
///        @p release_gap.
/// @param[in,out] model_part the contact model part (ProcessInfo: the factors); its SLAVE nodes' flags and tractions
/// @param[in] pure_slip every active node slips
/// @param[in] release_gap as in ComputePenaltyFrictionlessActiveSet (0: no hold)
/// @return {ACTIVE flips and held open nodes, SLIP flips} (slip flips are not counted in pure slip)
std::array<std::size_t, 2> ComputePenaltyFrictionalActiveSet(ModelPart& model_part, bool pure_slip = false,
                                                             double release_gap = 0.0);
/// @brief ALM frictional: λ̄n = k n·λ + ε g̃, λ̄τ = k Pλ + κ ε ũτ; on activation λ := n λ̄n/k + λ̄τ/k (λ̄τ dropped
///        when μ < machine ε); slip ⇔ μ < machine ε (a frictionless node cannot stick) or |λ̄τ| / (−μ λ̄n) >
///        1 − SLIP_THRESHOLD (slipping node) or > 1 (sticking node); slip traction −μ λ̄n λ̄τ/|λ̄τ|; inactive nodes:
///        ũτ := 0, SLIP reset.
/// @param[in,out] model_part the contact model part (ProcessInfo: the factors); its SLAVE nodes' flags and multipliers
/// @param[in] pure_slip every active node slips
/// @return {ACTIVE flips, SLIP flips}
std::array<std::size_t, 2> ComputeALMFrictionalActiveSet(ModelPart& model_part, bool pure_slip = false);

}  // namespace ActiveSetUtilities

}  // namespace contact_app
