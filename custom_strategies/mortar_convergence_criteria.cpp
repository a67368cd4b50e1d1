// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/mortar_convergence_criteria.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "custom_conditions/paired_condition.h"
#include "custom_processes/aalm_adapt_penalty_value_process.h"
#include "custom_utilities/active_set_utilities.h"
#include "custom_utilities/contact_utilities.h"
#include "custom_utilities/mortar_normals.h"

namespace contact_app {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

/// A unit vector orthogonal to n (the reference's fallback tangent: in 2D (n_y, −n_x, 0)).
Array3 OrthogonalUnit(const Array3& n) {
    if (std::abs(n[2]) < kEps) {  // plane normals: rotate clockwise in the x–y plane
        const Array3 t(n[1], -n[0], 0.0);
        return t.norm() > kEps ? Array3(t / t.norm()) : Array3(1.0, 0.0, 0.0);
    }
    const Array3 helper = std::abs(n[0]) < 0.9 ? Array3(1.0, 0.0, 0.0) : Array3(0.0, 1.0, 0.0);
    const Array3 t = helper - helper.dot(n) * n;
    return t / t.norm();
}

const char* FamilyName(BaseMortarConvergenceCriteria::Family family) {
    using F = BaseMortarConvergenceCriteria::Family;
    switch (family) {
        case F::ALM_FRICTIONLESS:
            return "ALMFrictionlessMortarConvergenceCriteria";
        case F::ALM_FRICTIONLESS_COMPONENTS:
            return "ALMFrictionlessComponentsMortarConvergenceCriteria";
        case F::ALM_FRICTIONAL:
            return "ALMFrictionalMortarConvergenceCriteria";
        case F::PENALTY_FRICTIONLESS:
            return "PenaltyFrictionlessMortarConvergenceCriteria";
        case F::PENALTY_FRICTIONAL:
            return "PenaltyFrictionalMortarConvergenceCriteria";
        default:
            return "MeshTyingMortarConvergenceCriteria";
    }
}

/// max |Δu| of the last correction: a penalty node that opened by less is held (docs/theory/active_set.md §2).
double LargestCorrection(const SystemVectorType& rDx) {
    double largest = 0.0;
    for (std::size_t i = 0; i < static_cast<std::size_t>(rDx.size()); ++i) largest = std::max(largest, std::abs(rDx[i]));
    return largest;
}

}  // namespace

void UpdateContactNormals(ModelPart& rModelPart) {
    ModelPart* contact = ContactUtilities::FindContactPart(rModelPart, "Contact");
    if (contact == nullptr) return;
    ComputeNodesMeanNormalModelPart(*contact, true);
    ModelPart* computing = ContactUtilities::FindContactPart(rModelPart, "ComputingContact");
    if (computing == nullptr) return;
    for (const auto& condition : computing->Conditions()) {
        auto* pair = dynamic_cast<PairedCondition*>(condition.get());
        if (pair == nullptr || !pair->HasPairedGeometry()) continue;
        pair->SetValue(NORMAL, pair->GetParentGeometry().UnitNormal(Array3::Zero()));
        pair->SetPairedNormal(pair->GetPairedGeometry().UnitNormal(Array3::Zero()));
    }
}

BaseMortarConvergenceCriteria::BaseMortarConvergenceCriteria(Family family, bool pure_slip)
    : mFamily(family), mPureSlip(pure_slip) {}

void BaseMortarConvergenceCriteria::UpdateNormalsAndTangents(ModelPart& rModelPart) const {
    if (mFamily == Family::MESH_TYING) return;
    if (ContactUtilities::FindContactPart(rModelPart, "Contact") == nullptr) return;
    UpdateContactNormals(rModelPart);
    // The pairs' weighted gaps and slips, and the nodal sums the residuals read, follow the new normals.
    if (ModelPart* computing = ContactUtilities::FindContactPart(rModelPart, "ComputingContact"))
        ContactUtilities::ComputeExplicitContributionConditions(*computing);
    UpdateTangents(rModelPart);
}

void BaseMortarConvergenceCriteria::UpdateTangents(ModelPart& rModelPart) const {
    ModelPart* contact = ContactUtilities::FindContactPart(rModelPart, "Contact");
    if (!IsFrictional() || contact == nullptr) return;
    // The slip direction of the trial traction (ActiveSetUtilities::TrialTangentialTraction); the conditions compute
    // it themselves and use TANGENT_XI only where it vanishes, the set update compares it to detect a turning slip.
    const bool with_multiplier = mFamily == Family::ALM_FRICTIONAL &&
                                 rModelPart.GetRootModelPart().HasNodalSolutionStepVariable(VECTOR_LAGRANGE_MULTIPLIER);
    const ProcessInfo& info = rModelPart.GetProcessInfo();
    for (const auto& node : contact->Nodes()) {
        Array3 n = node->FastGetSolutionStepValue(NORMAL);
        if (n.norm() < kEps) continue;
        n.normalize();
        Array3 direction = Array3::Zero();
        if (node->Is(ACTIVE) && node->Is(SLAVE))
            direction = with_multiplier ? ActiveSetUtilities::SlipDirectionTrial(*node, info)
                                        : ActiveSetUtilities::TrialTangentialTraction(*node, info, false);
        node->SetValue(TANGENT_XI, direction.norm() > kEps * (1.0 + direction.norm())
                                       ? Array3(direction / direction.norm())
                                       : OrthogonalUnit(n));
    }
}

void BaseMortarConvergenceCriteria::InitializeSolutionStep(ModelPart& rModelPart, DofsArrayType&,
                                                           const SparseMatrixType&, const SystemVectorType&,
                                                           const SystemVectorType&, const BuilderAndSolver&) {
    // Each step starts from the slip law's own c_t (docs/theory/mortar.md §8).
    if (mFamily == Family::ALM_FRICTIONAL)
        if (ModelPart* contact = ContactUtilities::FindContactPart(rModelPart, "Contact"))
            ActiveSetUtilities::ResetSlipTrialFactors(*contact);
    UpdateNormalsAndTangents(rModelPart);
    ProcessInfo& info = rModelPart.GetProcessInfo();
    info.SetValue(ACTIVE_SET_CONVERGED, true);
    if (IsFrictional()) info.SetValue(SLIP_SET_CONVERGED, true);
}

bool BaseMortarConvergenceCriteria::PreCriteria(ModelPart& rModelPart, DofsArrayType&, const SparseMatrixType&,
                                                const SystemVectorType&, const SystemVectorType&) {
    const ProcessInfo& info = rModelPart.GetProcessInfo();
    const int normal_variation = info.Has(CONSIDER_NORMAL_VARIATION) ? info.GetValue(CONSIDER_NORMAL_VARIATION) : 0;
    // Normals move inside the step only with normal variation (docs/theory/contact_strategies.md §1); the slip
    // directions follow
    // every iteration. Moving the normals of a stiff penalty interface each iteration kept its Newton from converging.
    if (normal_variation != 0)
        UpdateNormalsAndTangents(rModelPart);
    else
        UpdateTangents(rModelPart);
    if (info.Has(ADAPT_PENALTY) && info.GetValue(ADAPT_PENALTY))
        if (ModelPart* contact = ContactUtilities::FindContactPart(rModelPart, "Contact"))
            AALMAdaptPenaltyValueProcess(*contact).Execute();
    return true;
}

void BaseMortarConvergenceCriteria::CountSets(ModelPart& rModelPart) {
    mActiveNodes = mSlipNodes = 0;
    ModelPart* contact = ContactUtilities::FindContactPart(rModelPart, "Contact");
    if (contact == nullptr) return;
    for (const auto& node : contact->Nodes()) {
        if (!node->Is(SLAVE) || !node->Is(ACTIVE)) continue;
        ++mActiveNodes;
        if (node->Is(SLIP)) ++mSlipNodes;
    }
}

bool BaseMortarConvergenceCriteria::PostCriteria(ModelPart& rModelPart, DofsArrayType&, const SparseMatrixType&,
                                                 const SystemVectorType& rDx, const SystemVectorType&,
                                                 const BuilderAndSolver&) {
    mActiveFlips = mSlipFlips = 0;
    ProcessInfo& info = rModelPart.GetProcessInfo();
    if (mFamily == Family::MESH_TYING) return true;
    ModelPart& root = rModelPart.GetRootModelPart();
    ModelPart* contact = ContactUtilities::FindContactPart(rModelPart, "Contact");
    CONTACT_CHECK(contact != nullptr, InputError, FamilyName(mFamily), ": the model part ", root.FullName(),
                  " has no \"Contact\" sub model part\n  fix: add a contact process (alm_contact_process, ...) to the",
                  " processes of the analysis");
    // The weighted gaps and slips of this configuration were computed by the contact strategy after the update
    // (ResidualBasedNewtonRaphsonContactStrategy::AfterSolutionUpdate), before the residual the criteria read.

    // The set utilities look for "Contact" under the model part they get and honour its INTERACTION flag.
    ModelPart& owner = contact->GetParentModelPart();
    switch (mFamily) {
        case Family::ALM_FRICTIONLESS:
            mActiveFlips = ActiveSetUtilities::ComputeALMFrictionlessActiveSet(owner);
            break;
        case Family::ALM_FRICTIONLESS_COMPONENTS:
            mActiveFlips = ActiveSetUtilities::ComputeALMFrictionlessComponentsActiveSet(owner);
            break;
        case Family::PENALTY_FRICTIONLESS:
            mActiveFlips = ActiveSetUtilities::ComputePenaltyFrictionlessActiveSet(owner, LargestCorrection(rDx));
            break;
        case Family::ALM_FRICTIONAL: {
            const auto flips = ActiveSetUtilities::ComputeALMFrictionalActiveSet(owner, mPureSlip);
            mActiveFlips = flips[0];
            mSlipFlips = flips[1];
            break;
        }
        case Family::PENALTY_FRICTIONAL: {
            const auto flips =
                ActiveSetUtilities::ComputePenaltyFrictionalActiveSet(owner, mPureSlip, LargestCorrection(rDx));
            mActiveFlips = flips[0];
            mSlipFlips = flips[1];
            break;
        }
        default:
            break;
    }
    CountSets(rModelPart);
    if (mFamily == Family::ALM_FRICTIONAL) CountNonDissipative(*contact);
    info.SetValue(ACTIVE_SET_CONVERGED, mActiveFlips == 0);
    if (IsFrictional()) info.SetValue(SLIP_SET_CONVERGED, mSlipFlips == 0);
    return mActiveFlips == 0 && mSlipFlips == 0;
}

void BaseMortarConvergenceCriteria::CountNonDissipative(const ModelPart& rContact) {
    mNonDissipativeNodes = 0;
    for (const auto& node : rContact.Nodes()) {
        if (!node->Is(SLAVE) || !node->Is(ACTIVE) || !node->Is(SLIP)) continue;
        const Array3& traction = node->GetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE);
        const Array3& slip = node->FastGetSolutionStepValue(WEIGHTED_SLIP);
        // The friction on the slave follows the master's relative motion (+WEIGHTED_SLIP): λτ·ũτ ≥ 0.
        if (traction.dot(slip) < -1e-12 * traction.norm() * slip.norm()) ++mNonDissipativeNodes;
    }
}

void BaseMortarConvergenceCriteria::FinalizeSolutionStep(ModelPart& rModelPart, DofsArrayType&,
                                                         const SparseMatrixType&, const SystemVectorType&,
                                                         const SystemVectorType&) {
    if (mFamily != Family::PENALTY_FRICTIONAL) return;
    // Penalty friction carries its elastic (stick) slip to the next step: e = τ/(κε) of the converged traction.
    ModelPart* contact = ContactUtilities::FindContactPart(rModelPart, "Contact");
    if (contact == nullptr) return;
    const ProcessInfo& info = rModelPart.GetProcessInfo();
    const double tangent_factor = info.Has(TANGENT_FACTOR) ? info.GetValue(TANGENT_FACTOR) : 0.0;
    for (const auto& node : contact->Nodes()) {
        if (!node->Is(SLAVE)) continue;
        const double stiffness = tangent_factor * (node->Has(INITIAL_PENALTY) ? node->GetValue(INITIAL_PENALTY)
                                                                              : info.GetValue(INITIAL_PENALTY));
        const bool carries = node->Is(ACTIVE) && stiffness > 0.0;
        node->SetValue(TANGENT_SLIP, carries ? Array3(node->GetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE) / stiffness)
                                             : Array3(Array3::Zero()));
    }
}

std::string BaseMortarConvergenceCriteria::LastNorms() const {
    std::ostringstream out;
    out << "active " << mActiveNodes << " (" << mActiveFlips << " changed)";
    if (IsFrictional()) out << ", slip " << mSlipNodes << " (" << mSlipFlips << " changed)";
    if (mNonDissipativeNodes > 0) out << ", " << mNonDissipativeNodes << " slip node(s) not dissipative";
    return out.str();
}

std::string BaseMortarConvergenceCriteria::Info() const {
    return FamilyName(mFamily);
}

}  // namespace contact_app
