// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/active_set_utilities.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/model_part.h"
#include "custom_utilities/contact_utilities.h"

namespace contact_app::ActiveSetUtilities {

namespace {

constexpr double kMachineEpsilon = std::numeric_limits<double>::epsilon();

/// The SLAVE nodes to update, or none when the set is frozen (simplified semi-smooth Newton after iteration 1).
std::vector<Node*> SlaveNodesToUpdate(ModelPart& model_part) {
    std::vector<Node*> nodes;
    const bool update = model_part.Is(INTERACTION) ||
                        model_part.GetProcessInfo().GetValue(NL_ITERATION_NUMBER) == 1;
    if (!update) return nodes;
    ModelPart& contact = model_part.HasSubModelPart("Contact") ? model_part.GetSubModelPart("Contact") : model_part;
    for (const auto& node : contact.Nodes())
        if (node->Is(SLAVE)) nodes.push_back(node.get());
    return nodes;
}

double Penalty(const Node& node, const ProcessInfo& process_info) {
    return node.Has(INITIAL_PENALTY) ? node.GetValue(INITIAL_PENALTY) : process_info.GetValue(INITIAL_PENALTY);
}

double ScaleFactor(const ProcessInfo& process_info, const char* function) {
    CONTACT_CHECK(process_info.Has(SCALE_FACTOR), InputError, function,
                  ": SCALE_FACTOR is not set in the ProcessInfo\n  fix: run ALMVariablesCalculationProcess or set",
                  " ProcessInfo[SCALE_FACTOR] before updating the active set");
    return process_info.GetValue(SCALE_FACTOR);
}

/// Historical value when stored (as the conditions write it), else the non-historical one.
template <class T>
T& NodalValue(Node& node, const Variable<T>& variable) {
    return node.SolutionStepsDataHas(variable) ? node.FastGetSolutionStepValue(variable)
                                               : node.GetOrCreateValue(variable);
}

/// Sets ACTIVE to @p active; returns 1 if it changed.
std::size_t UpdateActive(Node& node, bool active) {
    const bool changed = node.Is(ACTIVE) != active;
    node.Set(ACTIVE, active);
    return changed ? 1 : 0;
}

/// Sets SLIP to @p slip; returns 1 if it changed.
std::size_t UpdateSlip(Node& node, bool slip) {
    const bool changed = node.Is(SLIP) != slip;
    node.Set(SLIP, slip);
    return changed ? 1 : 0;
}

/// Whether some pair covers the node: the explicit pass gave it a positive overlap area (NODAL_AREA = Σ_c ∫N_j over
/// the pairs' overlaps; a node without the value has not been through a pass and counts as covered). A node that slid
/// off every master face has no contact constraint left; kept ACTIVE, its multiplier had no row and kept its last value
/// (a stale 1e15 on the sliding cylinders of the example collection).
bool Covered(const Node& node) { return !node.Has(NODAL_AREA) || node.GetValue(NODAL_AREA) > 0.0; }

/// v/|v|, or the zero vector for a zero v.
Array3 Direction(const Array3& v) {
    const double norm = v.norm();
    return norm > 0.0 ? Array3(v / norm) : Array3(Array3::Zero());
}

/// The mean gap G_j / A_j of a slave node (G_j where it has no NODAL_AREA): the length its weighted gap averages.
double MeanGap(Node& node) {
    const double gap = NodalValue(node, WEIGHTED_GAP);
    const double area = node.Has(NODAL_AREA) ? node.GetValue(NODAL_AREA) : 0.0;
    return area > 0.0 ? gap / area : gap;
}

/// Whether a penalty node is active after the update, and the changes it counts (docs/theory/active_set.md §2):
/// active iff λ̄ = ε η G < 0, except that an ACTIVE node whose mean gap opened by less than @p release_gap (the
/// largest displacement correction of the iterate) stays: its opening is below the motion of the iterate itself.
/// Such a held node is open, so it counts as a change and Newton cannot stop on it; once the corrections fall below
/// its opening it leaves.
struct PenaltyActivity {
    bool active;
    std::size_t changes;
};
PenaltyActivity UpdatePenaltyActive(Node& node, double augmented_normal, double release_gap) {
    const bool covered = Covered(node);
    if (augmented_normal < 0.0 && covered) return {true, UpdateActive(node, true)};
    if (covered && node.Is(ACTIVE) && MeanGap(node) < release_gap) return {true, 1};
    return {false, UpdateActive(node, false)};
}

}  // namespace

std::size_t ComputePenaltyFrictionlessActiveSet(ModelPart& model_part, double release_gap) {
    const ProcessInfo& process_info = model_part.GetProcessInfo();
    std::size_t flips = 0;
    for (Node* node : SlaveNodesToUpdate(model_part)) {
        // A penalty node is in contact while its nodal weighted gap penetrates: λ̄ = ε η G < 0 (docs/theory/mortar.md
        // §7 "Nodal penalty").
        const double augmented_normal = Penalty(*node, process_info) * ContactUtilities::PenaltyWeightedGap(*node);
        node->SetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE, augmented_normal);
        flips += UpdatePenaltyActive(*node, augmented_normal, release_gap).changes;
    }
    return flips;
}

std::size_t ComputeALMFrictionlessActiveSet(ModelPart& model_part) {
    const ProcessInfo& process_info = model_part.GetProcessInfo();
    const double k = ScaleFactor(process_info, "ComputeALMFrictionlessActiveSet");
    std::size_t flips = 0;
    for (Node* node : SlaveNodesToUpdate(model_part)) {
        double& lambda = NodalValue(*node, LAGRANGE_MULTIPLIER_CONTACT_PRESSURE);
        const double penalty = Penalty(*node, process_info);
        const double augmented_normal = k * lambda + penalty * NodalValue(*node, WEIGHTED_GAP);
        node->SetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE,
                       k * lambda + penalty * ContactUtilities::TransmittedWeightedGap(*node));
        const bool active = augmented_normal < 0.0 && Covered(*node);
        if (active && node->IsNot(ACTIVE)) lambda = augmented_normal / k;
        if (!Covered(*node)) lambda = 0.0;
        flips += UpdateActive(*node, active);
    }
    return flips;
}

std::size_t ComputeALMFrictionlessComponentsActiveSet(ModelPart& model_part) {
    const ProcessInfo& process_info = model_part.GetProcessInfo();
    const double k = ScaleFactor(process_info, "ComputeALMFrictionlessComponentsActiveSet");
    std::size_t flips = 0;
    for (Node* node : SlaveNodesToUpdate(model_part)) {
        Array3& lambda = NodalValue(*node, VECTOR_LAGRANGE_MULTIPLIER);
        const Array3 normal = NodalValue(*node, NORMAL);
        const double penalty = Penalty(*node, process_info);
        const double augmented_normal = k * normal.dot(lambda) + penalty * NodalValue(*node, WEIGHTED_GAP);
        node->SetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE,
                       k * normal.dot(lambda) + penalty * ContactUtilities::TransmittedWeightedGap(*node));
        const bool active = augmented_normal < 0.0 && Covered(*node);
        if (active && node->IsNot(ACTIVE)) lambda = normal * (augmented_normal / k);
        if (!Covered(*node)) lambda.setZero();
        flips += UpdateActive(*node, active);
    }
    return flips;
}

namespace {

/// Whether a slip node's direction turned since the build (TANGENT_XI, set before it) by more than
/// kSlipDirectionTolerance, weighted by its share of the largest friction bound @p largest_bound: Newton must not stop
/// while a direction still turns, but the direction of a node that carries (almost) no friction, e.g. at the edge of
/// a Hertzian contact where the pressure vanishes, is round-off and may turn freely (docs/theory/mortar.md §8).
bool Turned(const Node& node, const Array3& direction, double bound, double largest_bound) {
    if (!node.Has(TANGENT_XI) || direction.norm() == 0.0 || !(largest_bound > 0.0)) return false;
    const Array3& previous = node.GetValue(TANGENT_XI);
    return previous.norm() > 0.0 &&
           (previous / previous.norm() - direction).norm() * bound > kSlipDirectionTolerance * largest_bound;
}

/// Whether a slip node's trial direction @p direction points against the one the build slipped along (TANGENT_XI, set
/// before it): the slip force of the build overshot, so the iterate crossed the stick cone, which lies between the two
/// directions. The penalty set then tries stick (docs/theory/active_set.md §3).
bool Reversed(const Node& node, const Array3& direction) {
    return node.Has(TANGENT_XI) && node.GetValue(TANGENT_XI).dot(direction) < 0.0;
}

/// The slip trial factor every step starts from, SlipTrialFactor(κ) with κ = TANGENT_FACTOR of @p process_info.
double BaseSlipTrialFactor(const ProcessInfo& process_info) {
    return SlipTrialFactor(process_info.Has(TANGENT_FACTOR) ? process_info.GetValue(TANGENT_FACTOR) : 0.0);
}

/// Whether a slipping node's tangential multiplier points against its slip of the step (k Pλ·PŜ < 0 with Ŝ =
/// +WEIGHTED_SLIP, the master's motion relative to the slave, which the friction on the slave must follow): the
/// friction of the build pushed the slave along its own motion relative to the master. Such a state solves the
/// regularised slip law wherever c_t|PŜ| < μ|λ̄n| (the trial kPλ + c_t ε PŜ then keeps the multiplier's direction),
/// and the direction update 2-cycles around it (12 newly touching edge nodes of the Cattaneo–Mindlin 3D level 3, for
/// 30 iterations). The node sticks for the next update, as a reversing penalty node does (docs/theory/active_set.md
/// §3). Only a node whose factor f = SLIP_TRIAL_FACTOR was raised in the step counts (converging Newton paths pass
/// through such states at the base factor: the 3D press fit), and only a slip that weighs at least
/// kSlipDirectionTolerance of the bound @p bound in the trial, f ε|PŜ| with @p penalty = ε (a stick iterate may have
/// just zeroed it).
bool NotDissipative(const Node& node, const Array3& lambda, const Array3& normal, double bound, double penalty,
                    const ProcessInfo& process_info) {
    Array3 slip = node.FastGetSolutionStepValue(WEIGHTED_SLIP);
    slip -= normal.dot(slip) * normal;
    const double factor = SlipTrialFactor(node, process_info);
    if (!(factor > BaseSlipTrialFactor(process_info))) return false;
    if (!(factor * penalty * slip.norm() > kSlipDirectionTolerance * bound)) return false;
    const Array3 tangential = lambda - normal.dot(lambda) * normal;
    return tangential.dot(slip) < -1e-12 * tangential.norm() * slip.norm();
}

/// Raises a slipping node's SLIP_TRIAL_FACTOR f when the iteration turned its direction by more than the slip law's
/// linearisation covers: the trial k Pλ + f ε Pũτ resists a rotation θ only through f ε|Pũτ|, so its tangent holds
/// for θ ≲ θ_f = √(2 f ε|Pũτ| / μ|λ̄n|). A turn θ > θ_f (from the build's TANGENT_XI to @p direction) sets f so that
/// θ_f = kSlipTurnMargin θ, for the rest of the step (docs/theory/mortar.md §8). A converged slip state does not
/// depend on f.
void RaiseSlipTrialFactor(Node& node, const Array3& direction, double bound, double penalty) {
    if (!node.Has(TANGENT_XI) || !node.Has(SLIP_TRIAL_FACTOR) || !(bound > 0.0) || !(penalty > 0.0)) return;
    const Array3& previous = node.GetValue(TANGENT_XI);
    if (previous.norm() == 0.0 || direction.norm() == 0.0) return;
    const double cosine = std::clamp(previous.dot(direction) / (previous.norm() * direction.norm()), -1.0, 1.0);
    const double turn = std::acos(cosine);
    const Array3 normal = node.FastGetSolutionStepValue(NORMAL);
    Array3 slip = node.FastGetSolutionStepValue(WEIGHTED_SLIP);
    slip -= normal.dot(slip) * normal;
    for (int c = 0; c < 3; ++c)
        if (ContactUtilities::IsMultiplierComponentHeld(node, c)) slip[c] = 0.0;
    const double stiffness = penalty * slip.norm();  // ε|Pũτ|
    if (!(stiffness > 0.0)) return;
    const double factor = node.GetValue(SLIP_TRIAL_FACTOR);
    const double covered = std::sqrt(2.0 * factor * stiffness / bound);
    if (turn > covered) node.SetValue(SLIP_TRIAL_FACTOR, kSlipTurnMargin * kSlipTurnMargin * turn * turn * bound / (2.0 * stiffness));
}

/// A node leaving stick for slip: its multiplier's tangential part goes onto the Coulomb cone along the trial
/// direction, Pλ := (μ|λ̄n|/k) τ̂ (the return map of the trial; @p magnitude = μ|λ̄n|/k, @p direction = τ̂), the normal
/// part is kept. The stick iterate's Pλ may lie far outside the cone (3.6× on the frictional sliding cylinders);
/// left there, the slip law's linearisation, which resists a rotation only through c_t|Ŝ|, turns the excess into
/// large rotations over the next iterations (docs/theory/active_set.md §3). A node with a held multiplier component
/// (symmetry plane: a fixed DoF) keeps its values.
void ReturnToTheCone(const Node& node, Array3& lambda, double magnitude, const Array3& direction) {
    for (int c = 0; c < 3; ++c)
        if (ContactUtilities::IsMultiplierComponentHeld(node, c)) return;
    if (direction.norm() == 0.0 || !(magnitude > 0.0)) return;
    const Array3 normal = node.FastGetSolutionStepValue(NORMAL);
    lambda = normal.dot(lambda) * normal + magnitude * direction;
}

/// max over the slave nodes to update of μ |λ̄n|, with λ̄n as @p transmitted_normal computes it.
template <class TNormal>
double LargestFrictionBound(const std::vector<Node*>& nodes, TNormal&& transmitted_normal) {
    double largest = 0.0;
    for (Node* node : nodes) {
        const double normal = transmitted_normal(*node);
        if (normal < 0.0) largest = std::max(largest, -node->GetValue(FRICTION_COEFFICIENT) * normal);
    }
    return largest;
}

}  // namespace

double SlipTrialFactor(const Node& node, const ProcessInfo& process_info) {
    const double own = node.Has(SLIP_TRIAL_FACTOR) ? node.GetValue(SLIP_TRIAL_FACTOR) : 0.0;
    return own > 0.0 ? own : BaseSlipTrialFactor(process_info);
}

void ResetSlipTrialFactors(ModelPart& rContact) {
    const ProcessInfo& process_info = rContact.GetProcessInfo();
    const double base = BaseSlipTrialFactor(process_info);
    for (const auto& node : rContact.Nodes())
        if (node->Is(SLAVE)) node->SetValue(SLIP_TRIAL_FACTOR, base);
}

namespace {

/// k Pλ + f ε P ũτ (ALM, @p with_multiplier) or f ε P(T + e) (penalty): the trial tangential traction with the slip
/// factor @p factor (c_t/ε).
Array3 TangentialTrial(const Node& node, const ProcessInfo& process_info, bool with_multiplier, double factor) {
    const double penalty = Penalty(node, process_info);
    const Array3 normal = node.FastGetSolutionStepValue(NORMAL);
    const auto tangential = [&normal](const Array3& v) { return Array3(v - normal.dot(v) * normal); };
    // ALM: the nodal slip S its multiplier rows hold; penalty: the elastic slip of earlier steps plus the slip the
    // pairs' stick rows transmit, T = Σ_c ω^c s^c (docs/theory/mortar.md §7; S ≈ 2T on a matching mesh).
    Array3 slip = Array3::Zero();
    if (with_multiplier) {
        if (node.SolutionStepsDataHas(WEIGHTED_SLIP)) slip = node.FastGetSolutionStepValue(WEIGHTED_SLIP);
    } else {
        slip = ContactUtilities::TransmittedWeightedSlip(node) + node.GetValue(TANGENT_SLIP);
    }
    Array3 trial = factor * penalty * tangential(slip);
    if (with_multiplier) {
        trial += process_info.GetValue(SCALE_FACTOR) * tangential(node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER));
        // A held multiplier component carries no traction (a symmetry plane, docs/theory/mortar.md §8).
        for (int c = 0; c < 3; ++c)
            if (ContactUtilities::IsMultiplierComponentHeld(node, c)) trial[c] = 0.0;
    }
    return trial;
}

}  // namespace

Array3 TrialTangentialTraction(const Node& node, const ProcessInfo& process_info, bool with_multiplier) {
    const double tangent_factor = process_info.Has(TANGENT_FACTOR) ? process_info.GetValue(TANGENT_FACTOR) : 0.0;
    return TangentialTrial(node, process_info, with_multiplier,
                           with_multiplier ? SlipTrialFactor(tangent_factor) : tangent_factor);
}

Array3 SlipDirectionTrial(const Node& node, const ProcessInfo& process_info) {
    return TangentialTrial(node, process_info, true, SlipTrialFactor(node, process_info));
}

std::array<std::size_t, 2> ComputePenaltyFrictionalActiveSet(ModelPart& model_part, bool pure_slip,
                                                             double release_gap) {
    const ProcessInfo& process_info = model_part.GetProcessInfo();
    std::array<std::size_t, 2> flips{0, 0};
    const std::vector<Node*> nodes = SlaveNodesToUpdate(model_part);
    const double largest_bound = LargestFrictionBound(nodes, [&](Node& node) {
        return Penalty(node, process_info) * ContactUtilities::PenaltyWeightedGap(node);
    });
    for (Node* node : nodes) {
        const double penalty = Penalty(*node, process_info);
        const double transmitted_normal = penalty * ContactUtilities::PenaltyWeightedGap(*node);
        node->SetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE, transmitted_normal);
        const PenaltyActivity activity = UpdatePenaltyActive(*node, transmitted_normal, release_gap);
        const bool active = activity.active;
        flips[0] += activity.changes;
        if (!active) {  // the deactivation is the counted change; the stick/slip state is just reset
            NodalValue(*node, WEIGHTED_SLIP).setZero();
            node->SetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE, Array3(Array3::Zero()));
            node->Set(SLIP, pure_slip);
            continue;
        }
        const double mu = node->GetValue(FRICTION_COEFFICIENT);
        const Array3 trial = TrialTangentialTraction(*node, process_info, false);
        const bool was_slip = node->Is(SLIP);
        const bool slip = pure_slip || (trial.norm() > -mu * transmitted_normal &&
                                        !(was_slip && Reversed(*node, Direction(trial))));
        // Slip traction along the trial, as the stick one (the reference flips its sign: [BUG?] B10).
        node->SetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE,
                       slip ? Array3(-mu * transmitted_normal * Direction(trial)) : trial);
        const std::size_t changed = UpdateSlip(*node, slip);
        if (!pure_slip) flips[1] += changed;
        if (slip && was_slip && Turned(*node, Direction(trial), -mu * transmitted_normal, largest_bound)) ++flips[1];
    }
    return flips;
}

std::array<std::size_t, 2> ComputeALMFrictionalActiveSet(ModelPart& model_part, bool pure_slip) {
    const ProcessInfo& process_info = model_part.GetProcessInfo();
    const double k = ScaleFactor(process_info, "ComputeALMFrictionalActiveSet");
    const double slip_threshold = process_info.GetValue(SLIP_THRESHOLD);
    // In 2D a direction is a sign: it flips, it does not turn.
    const bool directions_turn = !process_info.Has(DOMAIN_SIZE) || process_info.GetValue(DOMAIN_SIZE) != 2;
    std::array<std::size_t, 2> flips{0, 0};
    const std::vector<Node*> nodes = SlaveNodesToUpdate(model_part);
    const double largest_bound = LargestFrictionBound(nodes, [&](Node& node) {
        const Array3 normal = NodalValue(node, NORMAL);
        return k * normal.dot(NodalValue(node, VECTOR_LAGRANGE_MULTIPLIER)) +
               Penalty(node, process_info) * ContactUtilities::TransmittedWeightedGap(node);
    });
    for (Node* node : nodes) {
        const double penalty = Penalty(*node, process_info);
        Array3& lambda = NodalValue(*node, VECTOR_LAGRANGE_MULTIPLIER);
        const Array3 normal = NodalValue(*node, NORMAL);
        const double augmented_normal = k * normal.dot(lambda) + penalty * NodalValue(*node, WEIGHTED_GAP);
        // The normal traction the pairs transmit bounds the friction (docs/theory/mortar.md §7).
        const double transmitted_normal =
            k * normal.dot(lambda) + penalty * ContactUtilities::TransmittedWeightedGap(*node);
        node->SetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE, transmitted_normal);
        const Array3 trial = TrialTangentialTraction(*node, process_info, true);
        const bool active = augmented_normal < 0.0 && Covered(*node);
        if (!active) {  // the deactivation is the counted change; the stick/slip state is just reset
            if (!Covered(*node)) lambda.setZero();
            NodalValue(*node, WEIGHTED_SLIP).setZero();
            node->SetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE, Array3(Array3::Zero()));
            flips[0] += UpdateActive(*node, false);
            node->Set(SLIP, pure_slip);
            continue;
        }
        const double mu = node->GetValue(FRICTION_COEFFICIENT);
        if (node->IsNot(ACTIVE))
            lambda = normal * (augmented_normal / k) + (mu < kMachineEpsilon ? Array3(Array3::Zero()) : Array3(trial / k));
        flips[0] += UpdateActive(*node, true);
        // Coulomb test on the trial traction (the semi-smooth Newton of the slip law the conditions use), with
        // hysteresis. A frictionless node slips (the test would be 0/0 and flip between states).
        const bool was_slip = node->Is(SLIP);
        const double threshold = was_slip ? 1.0 - slip_threshold : 1.0;
        // A slipping node whose friction fed its slip instead of resisting it overshot the cone: stick for the next update.
        const bool slip = pure_slip || mu < kMachineEpsilon ||
                          (trial.norm() > -mu * transmitted_normal * threshold &&
                           !(was_slip && NotDissipative(*node, lambda, normal, -mu * transmitted_normal, penalty,
                                                        process_info)));
        // The direction weighs the slip by the node's own c_t (SLIP_TRIAL_FACTOR, the one the build used).
        const Array3 direction = Direction(SlipDirectionTrial(*node, process_info));
        node->SetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE,
                       slip ? Array3(-mu * transmitted_normal * direction) : trial);
        const std::size_t changed = UpdateSlip(*node, slip);
        if (!pure_slip) flips[1] += changed;
        if (slip && !was_slip && mu >= kMachineEpsilon) ReturnToTheCone(*node, lambda, -mu * transmitted_normal / k, direction);
        if (slip && was_slip && mu >= kMachineEpsilon) {
            if (Turned(*node, direction, -mu * transmitted_normal, largest_bound)) ++flips[1];
            if (directions_turn) RaiseSlipTrialFactor(*node, direction, -mu * transmitted_normal, penalty);
        }
    }
    return flips;
}

}  // namespace contact_app::ActiveSetUtilities
