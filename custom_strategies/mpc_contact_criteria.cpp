// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/mpc_contact_criteria.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "custom_utilities/contact_utilities.h"

namespace contact_app {
namespace {

/// Default of REACTION_CHECK_STIFFNESS_FACTOR when the ProcessInfo has none (the reference's C++ default).
constexpr double kDefaultReactionCheckFactor = 1.0e-12;
/// A gap counts as a penetration below −this × the node's length scale: a gap the constraint has just closed is
/// zero up to round-off, and its sign must not decide the contact status.
constexpr double kGapTolerance = 1.0e-10;
/// A slip of the step (WEIGHTED_SLIP / area) below this × the node's length scale is round-off: its direction means
/// nothing and does not change the stick/slip state.
constexpr double kSlipTolerance = 1.0e-12;
/// A slip direction (unit vector) that changed by more than this in an iteration has not converged (≈ 0.006°).
constexpr double kDirectionTolerance = 1.0e-4;

/// Largest YOUNG_MODULUS of the elements' properties (0 without one): the scale of the tension tolerance.
double YoungModulus(const ModelPart& rModelPart) {
    double young = 0.0;
    for (const auto& element : rModelPart.GetRootModelPart().Elements())
        if (element->pGetProperties() && element->GetProperties().Has(YOUNG_MODULUS))
            young = std::max(young, element->GetProperties().GetValue(YOUNG_MODULUS));
    return young;
}

/// The contact force on a slave node from its REACTION, without the components whose displacement is prescribed: there
/// the reaction also holds the support's force (on a symmetry plane, the whole tangential reaction of the plane's
/// direction), which the constraint does not exert and the Coulomb test must not read (as the ALM families leave a
/// held multiplier component out of their trial, docs/theory/active_set.md §4).
Array3 ContactForceOfReaction(const Node& node) {
    Array3 force = node.FastGetSolutionStepValue(REACTION);
    for (int c = 0; c < 3; ++c)
        if (ContactUtilities::IsDisplacementComponentPrescribed(node, c)) force[c] = 0.0;
    return force;
}

Array3 UnitNormal(const Node& node) {
    const Array3 n = node.FastGetSolutionStepValue(NORMAL);
    const double norm = n.norm();
    return norm > 0.0 ? Array3(n / norm) : n;
}

/// The contact traction on the slave node in the variables every mortar family writes (docs/theory/mortar.md §9):
/// AUGMENTED_NORMAL_CONTACT_PRESSURE = p (< 0 in compression), AUGMENTED_TANGENT_CONTACT_PRESSURE = the friction
/// force over the lumped area, so outputs and post-processing read one set of names whatever the family.
void SetTraction(Node& rNode, double pressure, const Array3& tangential) {
    rNode.SetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE, pressure);
    rNode.SetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE, tangential);
}

/// Every pair of "ComputingContact" is ACTIVE iff one of its slave nodes is; its constraint follows it.
void SyncPairsAndConstraints(ModelPart& computing) {
    ContactUtilities::ActivateConditionWithActiveNodes(computing);
    for (const auto& condition : computing.Conditions()) {
        if (!condition->Has(CONSTRAINT_POINTER)) continue;
        if (const auto constraint = condition->GetValue(CONSTRAINT_POINTER))
            constraint->Set(ACTIVE, condition->Is(ACTIVE));
    }
}

}  // namespace

void MPCContactCriteria::ComputeLumpedSlaveArea(ModelPart& rModelPart) {
    ModelPart* contact = ContactUtilities::FindContactPart(rModelPart, "Contact");
    if (contact == nullptr) return;
    for (const auto& node : contact->Nodes()) node->SetValue(NODAL_MAUX, 0.0);
    for (const auto& condition : contact->Conditions()) {
        if (!condition->Is(SLAVE)) continue;
        Geometry& face = condition->GetGeometry();
        const double share = std::abs(face.DomainSize()) / static_cast<double>(face.size());
        for (std::size_t i = 0; i < face.size(); ++i)
            face[i].SetValue(NODAL_MAUX, face[i].GetValue(NODAL_MAUX) + share);
    }
}

bool MPCContactCriteria::PreCriteria(ModelPart& rModelPart, DofsArrayType&, const SparseMatrixType&,
                                     const SystemVectorType&, const SystemVectorType&) {
    ModelPart* contact = ContactUtilities::FindContactPart(rModelPart, "Contact");
    if (contact == nullptr) return true;
    const ModelPart& root = rModelPart.GetRootModelPart();
    const bool store_previous = root.HasNodalSolutionStepVariable(WEIGHTED_GAP) && root.GetBufferSize() > 1;
    bool has_area = true;
    for (const auto& node : contact->Nodes()) {
        node->SetValue(CONTACT_FORCE, Array3(Array3::Zero()));
        if (store_previous)
            node->FastGetSolutionStepValue(WEIGHTED_GAP, 1) = node->FastGetSolutionStepValue(WEIGHTED_GAP);
        if (node->Is(SLAVE) && !(node->Has(NODAL_MAUX) && node->GetValue(NODAL_MAUX) > 0.0)) has_area = false;
    }
    if (!has_area) ComputeLumpedSlaveArea(rModelPart);
    if (ModelPart* computing = ContactUtilities::FindContactPart(rModelPart, "ComputingContact"))
        ContactUtilities::ComputeExplicitContributionConditions(*computing);
    return true;
}

bool MPCContactCriteria::PostCriteria(ModelPart& rModelPart, DofsArrayType&, const SparseMatrixType&,
                                      const SystemVectorType&, const SystemVectorType&, const BuilderAndSolver&) {
    mActiveFlips = mSlipFlips = mActiveNodes = mSlipNodes = 0;
    mMaxTurn = 0.0;
    ProcessInfo& info = rModelPart.GetProcessInfo();
    if (!(info.Has(NL_ITERATION_NUMBER) && info.GetValue(NL_ITERATION_NUMBER) > 0)) return true;
    ModelPart* contact = ContactUtilities::FindContactPart(rModelPart, "Contact");
    CONTACT_CHECK(contact != nullptr, InputError, "MPCContactCriteria: the model part ",
                  rModelPart.GetRootModelPart().FullName(), " has no \"Contact\" sub model part",
                  "\n  fix: add mpc_contact_process to processes.contact_process_list");
    ModelPart* computing = ContactUtilities::FindContactPart(rModelPart, "ComputingContact");
    if (computing != nullptr) ContactUtilities::ComputeExplicitContributionConditions(*computing);

    const double factor = info.Has(REACTION_CHECK_STIFFNESS_FACTOR) ? info.GetValue(REACTION_CHECK_STIFFNESS_FACTOR)
                                                                    : kDefaultReactionCheckFactor;
    const double young = YoungModulus(rModelPart);
    const double tolerance_pressure = -factor * young;
    const bool frictional = contact->Is(SLIP) || (computing != nullptr && computing->Is(SLIP));
    for (const auto& node : contact->Nodes()) {
        if (!node->Is(SLAVE)) continue;
        if (!(node->Has(NODAL_MAUX) && node->GetValue(NODAL_MAUX) > 0.0)) ComputeLumpedSlaveArea(rModelPart);
        const double lumped_area = node->GetValue(NODAL_MAUX);
        CONTACT_CHECK(lumped_area > 0.0, InputError, "MPCContactCriteria: slave node ", node->Id(), " of ",
                      contact->FullName(), " has a lumped area ", lumped_area,
                      "\n  expected: > 0 (the node must belong to a SLAVE condition of \"Contact\")",
                      "\n  fix: check the assume_master_slave setting of the contact process");
        const bool was_active = node->IsNotDefined(ACTIVE) || node->Is(ACTIVE);
        // Only a constrained (active) node carries a contact force in its reaction.
        const Array3 force = was_active ? ContactForceOfReaction(*node) : Array3(Array3::Zero());
        const Array3 n = UnitNormal(*node);
        const double normal_force = force.dot(n);
        const double pressure = normal_force / lumped_area;
        const double area =
            node->Has(NODAL_AREA) && node->GetValue(NODAL_AREA) > 0.0 ? node->GetValue(NODAL_AREA) : lumped_area;
        const double gap = node->FastGetSolutionStepValue(WEIGHTED_GAP) / area;
        const double nodal_h = ContactUtilities::NodalH(*node);
        const double length = nodal_h > 0.0 ? nodal_h : std::sqrt(lumped_area);
        // The active set on p̄ = p + (E/h) g̃/A, the ALM's augmented pressure with the penalty E/h: an inactive node
        // (p = 0) is activated by a penetration, an active one, whose gap the constraint keeps closed up to the drift
        // of the iterate since the last rebuild, is released by tension (a union of the two tests kept an edge node
        // active in tension over a 1e-8 drift, docs/theory/active_set.md §4). Without a Young's modulus, the gap alone.
        const bool penetrating = gap < -kGapTolerance * length;
        const bool active = young > 0.0 ? pressure + (penetrating ? young / length * gap : 0.0) < tolerance_pressure
                                        : pressure < tolerance_pressure || penetrating;
        if (active != was_active || node->IsNotDefined(ACTIVE)) {
            if (active != was_active) ++mActiveFlips;
            node->Set(ACTIVE, active);
        }
        const double weight =
            node->Has(NODAL_PAUX) && node->GetValue(NODAL_PAUX) > 0.0 ? node->GetValue(NODAL_PAUX) : 1.0;
        if (!active) {
            node->SetValue(CONTACT_FORCE, Array3(Array3::Zero()));
            SetTraction(*node, 0.0, Array3::Zero());
            if (frictional) node->Set(SLIP, false);
            continue;
        }
        ++mActiveNodes;
        node->SetValue(NORMAL_CONTACT_STRESS, pressure);
        if (!frictional) {
            node->SetValue(CONTACT_FORCE, Array3(normal_force * n / weight));
            SetTraction(*node, pressure, Array3::Zero());
            continue;
        }
        const Array3 tangential_force = force - normal_force * n;
        const double mu = node->Has(FRICTION_COEFFICIENT) ? node->GetValue(FRICTION_COEFFICIENT) : 0.0;
        const bool was_slip = was_active && node->Is(SLIP);
        // The slip of the step, master relative to slave (+WEIGHTED_SLIP): the friction on the slave follows it.
        Array3 slip = node->SolutionStepsDataHas(WEIGHTED_SLIP) ? node->FastGetSolutionStepValue(WEIGHTED_SLIP)
                                                                  : Array3(Array3::Zero());
        slip -= slip.dot(n) * n;
        const bool slip_measurable = slip.norm() > kSlipTolerance * area * length;
        const Array3 previous = node->GetValue(TANGENT_XI);
        bool slipping = false;
        Array3 direction = previous;
        if (!(mu > 0.0)) {
            slipping = true;  // frictionless (the reference's 0 ≤ 0 would stick a node without tangential force)
        } else if (!was_slip) {
            // Stick → slip when the stick force leaves the cone (B9 done right: two forces); the friction keeps
            // the stick force's direction.
            slipping = tangential_force.norm() > -mu * normal_force;
            if (slipping) direction = tangential_force / tangential_force.norm();
        } else if (slip_measurable) {
            // Slip → stick when the node moved against the friction it was given (the force overshot).
            slipping = slip.dot(previous) > 0.0;
            if (slipping) direction = slip / slip.norm();
        } else {
            slipping = true;  // no slip measured yet: keep the direction of the transition
        }
        if (was_active && was_slip != slipping) ++mSlipFlips;
        // A slip direction that still turns is not converged either (docs/theory/mortar.md §9).
        if (slipping && was_slip && previous.norm() > 0.0) {
            const double turn = (direction - previous).norm();
            mMaxTurn = std::max(mMaxTurn, turn);
            if (turn > kDirectionTolerance) ++mSlipFlips;
        }
        node->Set(SLIP, slipping);
        node->SetValue(TANGENT_XI, slipping ? direction : Array3(Array3::Zero()));
        if (slipping) ++mSlipNodes;
        const Array3 friction = slipping && mu > 0.0 ? Array3(-mu * normal_force * direction) : tangential_force;
        node->SetValue(CONTACT_FORCE, Array3((normal_force * n + friction) / weight));
        SetTraction(*node, pressure, Array3(friction / lumped_area));
        node->SetValue(TANGENTIAL_CONTACT_STRESS, slipping ? -mu * pressure : tangential_force.norm() / lumped_area);
    }
    if (computing != nullptr) SyncPairsAndConstraints(*computing);
    info.SetValue(ACTIVE_SET_CONVERGED, mActiveFlips == 0);
    if (frictional) info.SetValue(SLIP_SET_CONVERGED, mSlipFlips == 0);
    return mActiveFlips == 0 && mSlipFlips == 0;
}

std::string MPCContactCriteria::LastNorms() const {
    std::ostringstream out;
    out << "active " << mActiveNodes << " (" << mActiveFlips << " changed)";
    if (mSlipNodes > 0 || mSlipFlips > 0) {
        out << ", slip " << mSlipNodes << " (" << mSlipFlips << " changed";
        if (mMaxTurn > 0.0) out << ", turn " << std::scientific << std::setprecision(1) << mMaxTurn;
        out << ")";
    }
    return out.str();
}

}  // namespace contact_app
