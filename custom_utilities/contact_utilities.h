// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <map>
#include <utility>
#include <vector>

#include "contact_app/kernel/geometries/geometry.h"
#include "contact_app/kernel/types.h"

namespace contact_app {

class Condition;
class Dof;
class ModelPart;
class Node;

/// Model-part level helpers of the contact workflow (Kratos ContactUtilities, docs/theory/contact_strategies.md §1):
/// nodal mesh sizes, the explicit refresh of the weighted gaps, the predicted step jump and activity checks.
/// NODAL_H is read from the historical database when the model part stores it, else from the node's
/// non-historical values (NodalH()). Differences from the reference: CalculateMinimalNodalH is a true minimum
/// ([BUG?] in the reference), and ComputeExplicitContributionConditions zeroes the weighted values first.
class ContactUtilities {
public:
    /// @brief NODAL_H of @p node: historical if stored, else the non-historical value (0 when absent).
    static double NodalH(const Node& node);
    /// @brief Q = AREA_WEIGHTED_PAIR_GAP / NODAL_AREA, the weighted gap the pairs' augmentation transmits to a slave
    ///        node (docs/theory/mortar.md §7); WEIGHTED_GAP where the node has no area.
    static double TransmittedWeightedGap(const Node& node);
    /// @brief η G with G = WEIGHTED_GAP and η = SQUARED_PAIR_AREA / NODAL_AREA² (Σ_c a_c² / A²): the gap the penalty
    ///        families push a slave node with, λ̄ = ε η G (docs/theory/mortar.md §7 "Nodal penalty"); G where the node
    ///        has no area.
    static double PenaltyWeightedGap(const Node& node);
    /// @brief η = SQUARED_PAIR_AREA / NODAL_AREA² = Σ_c a_c² / A², the share of the nodal weighted gap a penalty node is
    ///        pushed with (1 where the node has no area).
    static double PenaltyShare(const Node& node);
    /// @brief T = AREA_WEIGHTED_PAIR_SLIP / NODAL_AREA, the weighted slip the pairs' penalty stick rows transmit to a
    ///        slave node (docs/theory/mortar.md §7); WEIGHTED_SLIP where the node has no area.
    static Array3 TransmittedWeightedSlip(const Node& node);
    /// @brief Whether component @p c of the node's VECTOR_LAGRANGE_MULTIPLIER is a fixed DoF: held at a symmetry plane
    ///        (FixSymmetryPlaneMultipliers) or by the user, so it carries no traction (docs/theory/mortar.md §8).
    static bool IsMultiplierComponentHeld(const Node& node, int c);
    /// @brief Whether component @p c of the node's DISPLACEMENT is prescribed (a fixed DoF): the support, not the
    ///        contact, carries the force along it (a symmetry plane), and the node does not move along it.
    static bool IsDisplacementComponentPrescribed(const Node& node, int c);
    /// @brief Largest NODAL_H of the nodes of @p model_part (0 for an empty part).
    static double CalculateMaxNodalH(const ModelPart& model_part);
    /// @brief Arithmetic mean of NODAL_H over the nodes of @p model_part (0 for an empty part).
    static double CalculateMeanNodalH(const ModelPart& model_part);
    /// @brief Smallest NODAL_H of the nodes of @p model_part (0 for an empty part).
    static double CalculateMinimalNodalH(const ModelPart& model_part);
    /// @brief Max / min NODAL_H. @throws InputError if the minimum is not positive (run FindNodalHProcess)
    static double CalculateRelativeSizeMesh(const ModelPart& model_part);

    /// @brief Predicted step jump DELTA_COORDINATES (non-historical) = c_v Δt (v + v_old) + c_a Δt² a_old with
    ///        (c_v, c_a) = (0.25, 0.125) for half a step, (0.5, 0.5) for a full one; fixed DISPLACEMENT components
    ///        are zeroed.
    /// @param[in,out] model_part its nodes must store VELOCITY and ACCELERATION (buffer ≥ 2)
    /// @param[in] delta_time Δt; @param[in] half_step half or full jump
    /// @throws InputError if VELOCITY / ACCELERATION are not historical variables
    static void ComputeStepJump(ModelPart& model_part, double delta_time, bool half_step = true);
    /// @brief Geometry centre moved by Σ N_i(centre) DELTA_COORDINATES_i.
    static Array3 GetHalfJumpCenter(const Geometry& geometry);

    /// @brief The sub model part @p name of the root of @p model_part ("Contact", "ComputingContact"), else the
    ///        direct child of @p model_part of that name, else nullptr.
    static ModelPart* FindContactPart(ModelPart& model_part, const char* name);
    /// @brief True iff some node of @p model_part is SLAVE and ACTIVE.
    /// @throws ConvergenceError "CONTACT LOST" if none is and @p throw_error
    static bool CheckActivity(const ModelPart& model_part, bool throw_error = true);
    /// @brief True iff some node of @p model_part has a ROTATION_X/Y/Z DoF.
    static bool CheckModelPartHasRotationDoF(const ModelPart& model_part);
    /// @brief Removes (from @p model_part and below) the conditions that are pairs (geometry with geometry parts).
    static void CleanContactModelParts(ModelPart& model_part);
    /// @brief Refreshes the explicit nodal contact values: ResetExplicitNodalValues on the nodes of every condition
    ///        of @p model_part, then AddExplicitContribution of every condition with the root ProcessInfo.
    static void ComputeExplicitContributionConditions(ModelPart& model_part);
    /// @brief Before the pairs accumulate into @p node: WEIGHTED_GAP, WEIGHTED_SLIP (historical when stored, else
    ///        non-historical), NODAL_AREA, AREA_WEIGHTED_PAIR_GAP and SQUARED_PAIR_AREA := 0.
    static void ResetExplicitNodalValues(Node& node);
    /// @brief Fixes VECTOR_LAGRANGE_MULTIPLIER_c = 0 at the frictional slave nodes (WEIGHTED_SLIP stored) of
    ///        @p computing's pairs that lie on a symmetry plane c = const through the interface: the node is held in
    ///        DISPLACEMENT_c, its NORMAL lies in the plane (|n_c| ≤ 0.1 |n|), and the master nodes of its pairs on the
    ///        same plane are all held too (at least one exists). By symmetry the contact traction has
    ///        no c component there; left free, the stick rows of such nodes constrain (almost) only held DoFs and the
    ///        solve returned multipliers 10^4 times too large (docs/theory/mortar.md §8). First frees the DoFs of
    ///        @p fixed (the last call's result), so the set follows the pairs and the supports; DoFs the user fixed
    ///        are left alone.
    /// @return the DoFs fixed by this call
    static std::vector<Dof*> FixSymmetryPlaneMultipliers(ModelPart& computing, const std::vector<Dof*>& fixed);
    /// @brief A pair condition is ACTIVE iff one of its slave (geometry part 0) nodes is ACTIVE; conditions without
    ///        geometry parts use their own nodes.
    static void ActivateConditionWithActiveNodes(ModelPart& model_part);

    /// @brief The slave nodes that two or more of @p pairs hold (their own geometry, the slave face): node id →
    ///        (index into @p pairs, local index of the node in that pair), in the order of @p pairs. The nodal laws'
    ///        cross-pair tangent blocks live between these pairs (docs/theory/mortar.md §7).
    static std::map<IndexType, std::vector<std::pair<std::size_t, int>>> SharedSlaveNodes(
        const std::vector<const Condition*>& pairs);

    /// @brief Moves @p point by @p length along @p normal (point += n·L).
    static void ScaleNode(Array3& point, const Array3& normal, double length);
    /// @brief Euclidean distance between two points.
    static double DistancePoints(const Array3& a, const Array3& b);
};

}  // namespace contact_app
