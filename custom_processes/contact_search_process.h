// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "contact_app/kernel/model_part.h"
#include "custom_processes/contact_search_settings.h"
#include "custom_processes/oriented_bounding_box.h"
#include "custom_processes/search_tree.h"
#include "custom_processes/self_contact_utilities.h"

namespace contact_app {

class IndexMap;

/// The mortar contact search (Kratos AdvancedContactSearchProcess; `simple_search` = SimpleContactSearchProcess;
/// docs/theory/contact_search.md). Each step: nodal mean normals of `<main>.Contact[.ContactSub<id>]`; a kd-tree over
/// the master face centres; per slave face the candidates in a radius / box (+ OBB filter), checked (not itself,
/// opposite orientation, not yet paired, no reciprocal pair); INDEX_MAP of the slave face records master id →
/// pair condition id; pair conditions `<condition_name>Condition<d>D<n>N<final_string>` from Registry<Condition> go
/// to `<main>.ComputingContact[.ComputingContactSub<id>]`. Activation: NoCheck (all), DirectCheck (projection
/// within ACTIVE_CHECK_FACTOR·NODAL_H) or MappingCheck (NORMAL_GAP by projecting each slave node along its
/// nodal normal onto its masters — a direct projection instead of the reference's mortar mapper).
/// Pairs survive between steps while ACTIVE. Role: slave faces are those with SLAVE == !inverted.
/// Self contact (predefined_master_slave false): roles from a pre-search in adjacency order
/// (self_contact_utilities.h). octree_with_obb is served by the same kd-tree + OBB filter (no octree).
/// Details and deviations: docs/theory/contact_search.md.
class ContactSearchProcess {
public:
    /// Which multipliers the solver carries (reference TypeSolution), from the nodal variables.
    enum class TypeSolution { VectorLagrangeMultiplier, NormalContactStress, FrictionlessPenaltyMethod,
                              FrictionalPenaltyMethod, ScalarLagrangeMultiplier, Other };
    /// Wall-clock seconds of the last UpdateMortarConditions.
    struct Timings {
        double tree_build = 0.0;  ///< point list + kd-tree (+ OBBs)
        double queries = 0.0;     ///< candidate queries and checks of every slave face
        double total = 0.0;       ///< whole UpdateMortarConditions
        std::size_t slave_faces = 0, master_faces = 0, candidates = 0;
    };

    /// @param[in] main_model_part must contain the sub model part "Contact" (and "ContactSub<id_name>")
    /// @param[in] settings validated here
    /// @param[in] pair_properties properties of the created pair conditions (shared); null = the slave face's
    /// @param[in] resume adopt the pairs (with their INDEX_MAP entries, constraints and flags), the face flags and
    ///            NORMAL_GAP that a restart file restored; otherwise a fresh search erases leftover pairs
    /// @throws InputError if the contact part is missing, a setting is out of range, or NORMAL is not historical
    ContactSearchProcess(ModelPart& main_model_part, ContactSearchSettings settings,
                         Properties::Pointer pair_properties = nullptr, bool resume = false);
    virtual ~ContactSearchProcess() = default;
    ContactSearchProcess(const ContactSearchProcess&) = delete;
    ContactSearchProcess& operator=(const ContactSearchProcess&) = delete;

    /// ExecuteInitialize + ExecuteInitializeSolutionStep + ExecuteFinalizeSolutionStep.
    void Execute();
    /// CheckContactModelParts, CreatePointListMortar, InitializeMortarConditions.
    void ExecuteInitialize();
    /// ClearMortarConditions + UpdateMortarConditions.
    void ExecuteInitializeSolutionStep();
    /// ClearMortarConditions.
    void ExecuteFinalizeSolutionStep();

    /// A face already MARKER (claimed by another search) is replaced in this search's part by a clone with a
    /// new id; the others are marked MARKER.
    void CheckContactModelParts();
    /// The master faces (kd-tree points) of the current roles.
    void CreatePointListMortar();
    /// An empty INDEX_MAP on every face of the contact part that has none.
    void InitializeMortarConditions();
    /// ResetContactOperators, then zero the multipliers of the inactive slave nodes.
    void ClearMortarConditions();
    /// The search of the step: normals, candidates, pairs, gaps, active set (docs/theory/contact_search.md §1).
    void UpdateMortarConditions();
    /// Pair reuse: erase the pair conditions no longer ACTIVE (all of them when the main part is MODIFIED)
    /// and their INDEX_MAP entries; candidates without condition are dropped too.
    virtual void ResetContactOperators();
    /// Swaps the slave and master roles.
    void InvertSearch() { mSettings.inverted_search = !mSettings.inverted_search; }

    const ContactSearchSettings& Settings() const { return mSettings; }
    TypeSolution GetTypeSolution() const { return mTypeSolution; }
    const Timings& LastTimings() const { return mTimings; }
    /// Whether the check for slave nodes starting inside the master ran (it runs at the first search only). A
    /// restarted run sets what the saving run had, or its first search would check (and pair) again.
    bool PenetrationChecked() const { return mPenetrationChecked; }
    void SetPenetrationChecked(bool checked) { mPenetrationChecked = checked; }
    ModelPart& GetContactModelPart() { return *mpContactPart; }
    ModelPart& GetComputingModelPart() { return *mpComputingPart; }
    /// `<condition_name>Condition<d>D<n_slave>N<final_string>`.
    std::string PairConditionName(int dim, std::size_t slave_nodes) const;

protected:
    /// Hook after a pair condition was created, added, given NORMAL and ACTIVE and initialised (MPC adds its
    /// constraint here).
    virtual void OnPairCreated(Condition& pair);
    /// Hook for the pair conditions about to be erased (MPC erases their constraints).
    virtual void OnPairsErased(const std::vector<Condition*>& pairs);
    ModelPart& MainModelPart() { return mrMainModelPart; }

private:
    struct MasterFace {
        Condition* condition;
        std::shared_ptr<OrientedBoundingBox> box;  // only for the *_with_obb types
    };
    enum class CheckResult { Fail, AlreadyInTheMap, OK };

    bool IsSlaveRole(const Flags& entity) const { return entity.Is(SLAVE) == !mSettings.inverted_search; }
    bool UsesOBB() const;
    std::vector<Condition*> SlaveFaces() const;
    std::vector<Node*> SlaveNodes() const;
    void BuildTree(const std::vector<Condition*>& masters);
    void QueryCandidates(const Condition& slave, std::vector<std::size_t>& results) const;
    double OBBThickness() const;
    bool SearchesInBox() const;
    /// How far the search looks from a slave face: search_factor × (in_box*: face size; else: largest centre-node
    /// distance), also how far behind the face a penetrated master is found.
    double SearchReach(const Condition& slave) const;
    /// First search only: finds the slave nodes that start inside the master body; those within the reach are
    /// paired with the face they are behind (PairPenetratingNodes) and activated (ActivatePenetratingNodes), their
    /// faces' OBBs swept backwards; deeper ones throw InputError.
    void FindInitialPenetration();
    void PairPenetratingNodes();
    void ActivatePenetratingNodes();
    CheckResult CheckCondition(const Condition& slave, const Condition& master) const;
    void SearchPairs();
    void AddPotentialPairing(Condition& slave, Condition& master);
    void CreatePairConditions();
    Condition::Pointer AddPairing(Condition& slave, Condition& master);
    void AssignSelfContactRoles();
    void ApplySelfContactRoles(const std::vector<Condition*>& faces, const std::vector<SelfContactRole>& roles);
    void MoveByStepJump(double sign);
    void ComputeMappedGap();
    void CheckPairing();
    void ComputeWeightedReaction();
    void ComputeActiveInactiveNodes();
    void UpdatePairActivity();
    void SetActiveNode(Node& node) const;
    void SetInactiveNode(Node& node) const;
    void ZeroMultipliers(Node& node) const;
    void InitializeSlip(Node& node) const;
    double ActiveCheckFactor() const;

    ModelPart& mrMainModelPart;
    ContactSearchSettings mSettings;
    Properties::Pointer mpPairProperties;
    ModelPart* mpContactPart = nullptr;
    ModelPart* mpComputingPart = nullptr;
    TypeSolution mTypeSolution = TypeSolution::Other;
    std::vector<MasterFace> mMasters;
    SearchTree mTree;
    double mThickness = 1.0;
    double mMaxMasterRadius = 0.0;                       // largest centre-node distance of the master faces
    bool mPenetrationChecked = false;                    // PairPenetratingNodes ran (first search)
    std::vector<std::pair<Node*, double>> mPenetratingNodes;  // found by it, with their depth, to activate
    std::vector<std::pair<Condition*, Condition*>> mPenetrationPairs;  // (slave face, master it penetrates)
    std::unordered_map<const Condition*, double> mPenetratingFaces;  // slave faces with a penetrating node: depth
    std::vector<std::pair<Node*, Array3>> mStepJump;  // nodes moved for a dynamic search, and by how much
    std::vector<Dof*> mSymmetryMultipliers;            // fixed by ContactUtilities::FixSymmetryPlaneMultipliers
    Timings mTimings;
};

}  // namespace contact_app
