// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/contact_search_process.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <unordered_map>

#include <Eigen/Geometry>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/registry.h"
#include "custom_conditions/paired_condition.h"
#include "custom_processes/penetration_check.h"
#include "custom_processes/self_contact_utilities.h"
#include "custom_utilities/contact_utilities.h"
#include "custom_utilities/index_map.h"
#include "custom_utilities/mortar_normals.h"

namespace contact_app {
namespace {

using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point since) { return std::chrono::duration<double>(Clock::now() - since).count(); }

/// NODAL_H, historical when the node stores it (FindNodalHProcess), else the non-historical value.
double NodalH(const Node& node) {
    return node.SolutionStepsDataHas(NODAL_H) ? node.FastGetSolutionStepValue(NODAL_H) : node.GetValue(NODAL_H);
}

/// The face's INDEX_MAP, created (empty) if missing.
IndexMap& IndexMapOf(Condition& face) {
    auto map = face.GetValue(INDEX_MAP);
    if (!map) {
        map = std::make_shared<IndexMap>();
        face.SetValue(INDEX_MAP, map);
    }
    return *map;
}

bool IsPair(const Condition& condition) { return condition.GetGeometry().NumberOfGeometryParts() > 0; }

bool ShareANode(const Geometry& a, const Geometry& b) {
    for (std::size_t i = 0; i < a.PointsNumber(); ++i)
        for (std::size_t j = 0; j < b.PointsNumber(); ++j)
            if (&a[i] == &b[j]) return true;
    return false;
}

/// The node's NORMAL, or @p fallback when it is zero.
Array3 NodeNormal(const Node& node, const Array3& fallback) {
    const Array3& normal = node.FastGetSolutionStepValue(NORMAL);
    return normal.squaredNorm() > 0.0 ? normal : fallback;
}

}  // namespace

ContactSearchProcess::ContactSearchProcess(ModelPart& main_model_part, ContactSearchSettings settings,
                                           Properties::Pointer pair_properties, bool resume)
    : mrMainModelPart(main_model_part), mSettings(std::move(settings)), mpPairProperties(std::move(pair_properties)) {
    mSettings.Validate();
    CONTACT_CHECK(!mSettings.predict_correct_lagrange_multiplier, ConfigurationError,
                  "contact search: predict_correct_lagrange_multiplier = true is not implemented",
                  "\n  where:    search_parameters › predict_correct_lagrange_multiplier",
                  "\n  expected: false (the reference's Python driver does not pass it to the search either)");
    CONTACT_CHECK(mrMainModelPart.HasSubModelPart("Contact"), InputError, "contact search: model part \"",
                  mrMainModelPart.FullName(), "\" has no sub model part \"Contact\"",
                  "\n  fix: create it with the interface conditions (the contact process does it)");
    mpContactPart = &mrMainModelPart.GetSubModelPart("Contact");
    if (!mSettings.id_name.empty()) {
        const std::string sub = "ContactSub" + mSettings.id_name;
        CONTACT_CHECK(mpContactPart->HasSubModelPart(sub), InputError, "contact search (id_name \"",
                      mSettings.id_name, "\"): model part \"", mpContactPart->FullName(), "\" has no sub model part \"",
                      sub, "\"\n  fix: set id_name to the pair key whose ContactSub<key> exists, or \"\"");
        mpContactPart = &mpContactPart->GetSubModelPart(sub);
    }
    CONTACT_CHECK(mrMainModelPart.GetRootModelPart().HasNodalSolutionStepVariable(NORMAL), InputError,
                  "contact search: NORMAL is not a historical variable of \"", mrMainModelPart.GetRootModelPart().Name(),
                  "\"\n  fix: AddNodalSolutionStepVariable(NORMAL) before reading the mesh");
    if (!mrMainModelPart.HasSubModelPart("ComputingContact")) mrMainModelPart.CreateSubModelPart("ComputingContact");
    mpComputingPart = &mrMainModelPart.GetSubModelPart("ComputingContact");
    if (!mSettings.id_name.empty()) {
        const std::string sub = "ComputingContactSub" + mSettings.id_name;
        if (!mpComputingPart->HasSubModelPart(sub)) mpComputingPart->CreateSubModelPart(sub);
        mpComputingPart = &mpComputingPart->GetSubModelPart(sub);
    }
    const ModelPart& root = mrMainModelPart.GetRootModelPart();
    if (root.HasNodalSolutionStepVariable(VECTOR_LAGRANGE_MULTIPLIER))
        mTypeSolution = TypeSolution::VectorLagrangeMultiplier;
    else if (root.HasNodalSolutionStepVariable(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE))
        mTypeSolution = TypeSolution::NormalContactStress;
    else if (root.HasNodalSolutionStepVariable(WEIGHTED_GAP))
        mTypeSolution = mrMainModelPart.Is(SLIP) ? TypeSolution::FrictionalPenaltyMethod
                                                 : TypeSolution::FrictionlessPenaltyMethod;
    else if (root.HasNodalSolutionStepVariable(SCALAR_LAGRANGE_MULTIPLIER))
        mTypeSolution = TypeSolution::ScalarLagrangeMultiplier;
    // Restarted: the pairs are the saving run's, which the next search reuses like the continuous run would (an
    // MPC pair holds its constraint, recreating it would leave the old one in the model part).
    if (resume) return;

    // A fresh search owns no pairs: erase leftovers of a previous search object on the same part.
    for (const auto& pair : mpComputingPart->Conditions()) pair->Set(TO_ERASE, true);
    mrMainModelPart.GetRootModelPart().RemoveConditionsFlagged(TO_ERASE);


    if (mSettings.check_gap == CheckGap::MappingCheck)
        for (const auto& node : mpContactPart->Nodes()) node->SetValue(NORMAL_GAP, 0.0);
    for (const auto& face : mpContactPart->Conditions()) face->Set(ACTIVE, false);
}

std::string ContactSearchProcess::PairConditionName(int dim, std::size_t slave_nodes) const {
    return mSettings.condition_name + "Condition" + std::to_string(dim) + "D" + std::to_string(slave_nodes) + "N" +
           mSettings.final_string;
}

// -- Phases --

void ContactSearchProcess::Execute() {
    ExecuteInitialize();
    ExecuteInitializeSolutionStep();
    ExecuteFinalizeSolutionStep();
}

void ContactSearchProcess::ExecuteInitialize() {
    CheckContactModelParts();
    CreatePointListMortar();
    InitializeMortarConditions();
}

void ContactSearchProcess::ExecuteInitializeSolutionStep() {
    ClearMortarConditions();
    UpdateMortarConditions();
}

void ContactSearchProcess::ExecuteFinalizeSolutionStep() { ClearMortarConditions(); }

void ContactSearchProcess::CheckContactModelParts() {
    ModelPart& root = mrMainModelPart.GetRootModelPart();
    std::vector<Condition::Pointer> claimed;
    for (const auto& face : mpContactPart->Conditions()) {
        if (face->Is(MARKER)) claimed.push_back(face);
        else face->Set(MARKER, true);
    }
    for (const auto& face : claimed) {
        // Another search owns this face: this search works on its own copy (same geometry and properties).
        auto copy = face->Create(root.Conditions().MaxId() + 1, face->pGetGeometry(), face->pGetProperties());
        static_cast<Flags&>(*copy) = static_cast<const Flags&>(*face);
        copy->SetValue(NORMAL, face->GetValue(NORMAL));
        mpContactPart->RemoveCondition(face->Id());
        mpContactPart->AddCondition(copy);
    }
}

void ContactSearchProcess::CreatePointListMortar() {
    std::vector<Condition*> masters;
    for (const auto& face : mpContactPart->Conditions())
        if (!IsPair(*face) && !IsSlaveRole(*face)) masters.push_back(face.get());
    BuildTree(masters);
}

void ContactSearchProcess::InitializeMortarConditions() {
    for (const auto& face : mpContactPart->Conditions())
        if (!face->GetValue(INDEX_MAP)) face->SetValue(INDEX_MAP, std::make_shared<IndexMap>());
}

void ContactSearchProcess::ClearMortarConditions() {
    ResetContactOperators();
    for (const auto& node : mpContactPart->Nodes())
        if (IsSlaveRole(*node) && node->IsNot(ACTIVE)) ZeroMultipliers(*node);
}

void ContactSearchProcess::ResetContactOperators() {
    // Pairs without an active slave node (in the set the last step converged to) are the ones to erase.
    UpdatePairActivity();
    ModelPart& root = mrMainModelPart.GetRootModelPart();
    std::vector<Condition*> erased;
    if (mrMainModelPart.Is(MODIFIED)) {
        for (const auto& face : mpContactPart->Conditions())
            if (auto map = face->GetValue(INDEX_MAP)) map->clear();
        for (const auto& pair : mpComputingPart->Conditions()) erased.push_back(pair.get());
    } else {
        for (const auto& face : mpContactPart->Conditions()) {
            auto map = face->GetValue(INDEX_MAP);
            if (!map) continue;
            std::vector<IndexType> gone;
            for (const auto& [master_id, pair_id] : *map) {
                Condition* pair = pair_id == 0 ? nullptr : root.Conditions().Find(pair_id);
                if (pair != nullptr && pair->Is(ACTIVE)) continue;
                gone.push_back(master_id);
                if (pair != nullptr) erased.push_back(pair);
            }
            for (const IndexType id : gone) map->RemoveId(id);
        }
    }
    if (erased.empty()) return;
    OnPairsErased(erased);
    for (Condition* pair : erased) pair->Set(TO_ERASE, true);
    root.RemoveConditionsFlagged(TO_ERASE);
}

void ContactSearchProcess::OnPairCreated(Condition&) {}
void ContactSearchProcess::OnPairsErased(const std::vector<Condition*>&) {}

void ContactSearchProcess::UpdateMortarConditions() {
    const auto start = Clock::now();
    mTimings = Timings{};
    MoveByStepJump(+1.0);
    ComputeNodesMeanNormalModelPart(*mpContactPart, true);
    if (mpComputingPart->NumberOfConditions() > 0) ClearMortarConditions();
    if (!mSettings.predefined_master_slave) AssignSelfContactRoles();
    auto phase = Clock::now();
    CreatePointListMortar();
    mTimings.tree_build = Seconds(phase);
    phase = Clock::now();
    if (!mPenetrationChecked) FindInitialPenetration();
    mPenetrationChecked = true;
    SearchPairs();
    PairPenetratingNodes();
    mTimings.queries = Seconds(phase);
    if (mSettings.check_gap == CheckGap::MappingCheck) {
        CheckPairing();
    } else {
        if (!mStepJump.empty()) {
            MoveByStepJump(-1.0);
            ComputeNodesMeanNormalModelPart(*mpContactPart, true);
        }
        CreatePairConditions();
        ComputeWeightedReaction();
    }
    ActivatePenetratingNodes();
    // Every pair the search keeps is assembled during the step: the active set changes inside the Newton loop, and
    // a pair switched off here would miss the contribution of a slave node that becomes active later.
    for (const auto& pair : mpComputingPart->Conditions()) pair->Set(ACTIVE, true);
    mTimings.total = Seconds(start);
}

// -- Broad and narrow phase --

bool ContactSearchProcess::UsesOBB() const {
    return mSettings.type_search == SearchTreeType::InRadiusWithOBB ||
           mSettings.type_search == SearchTreeType::InBoxWithOBB ||
           mSettings.type_search == SearchTreeType::OctreeWithOBB;
}

double ContactSearchProcess::OBBThickness() const {
    double max_h = 0.0;
    for (const auto& node : mpContactPart->Nodes()) max_h = std::max(max_h, NodalH(*node));
    return mSettings.bounding_box_factor * (max_h > 0.0 ? max_h : 1.0);
}

void ContactSearchProcess::BuildTree(const std::vector<Condition*>& masters) {
    mMasters.clear();
    mMasters.reserve(masters.size());
    std::vector<Array3> centres;
    centres.reserve(masters.size());
    const bool obb = UsesOBB();
    if (obb) mThickness = OBBThickness();
    mMaxMasterRadius = 0.0;
    for (Condition* face : masters) {
        centres.push_back(face->GetGeometry().Center());
        for (std::size_t i = 0; i < face->GetGeometry().PointsNumber(); ++i)
            mMaxMasterRadius = std::max(mMaxMasterRadius, (face->GetGeometry()[i].Coordinates() - centres.back()).norm());
        mMasters.push_back({face, obb ? std::make_shared<OrientedBoundingBox>(face->GetGeometry(), mThickness) : nullptr});
    }
    mTree.Build(centres, mSettings.bucket_size);
    mTimings.master_faces = masters.size();
}

bool ContactSearchProcess::SearchesInBox() const {
    return mSettings.type_search == SearchTreeType::InBox || mSettings.type_search == SearchTreeType::InBoxWithOBB;
}

double ContactSearchProcess::SearchReach(const Condition& slave) const {
    const Geometry& face = slave.GetGeometry();
    if (SearchesInBox()) return mSettings.search_factor * (face.LocalSpaceDimension() == 1 ? face.Length() : std::sqrt(face.Area()));
    double radius = 0.0;
    const Array3 centre = face.Center();
    for (std::size_t i = 0; i < face.PointsNumber(); ++i) radius = std::max(radius, (face[i].Coordinates() - centre).norm());
    return mSettings.search_factor * radius;
}

void ContactSearchProcess::QueryCandidates(const Condition& slave, std::vector<std::size_t>& results) const {
    const Geometry& face = slave.GetGeometry();
    const double length = SearchReach(slave);
    if (SearchesInBox()) {
        // The face's box swept by ±L along the nodal normals, L = search_factor × face size (2D length,
        // 3D √area): masters in front (open gap) and behind (penetration) are found.
        const Array3 fallback = slave.GetValue(NORMAL);
        Array3 lo = Array3::Constant(std::numeric_limits<double>::max()), hi = -lo;
        for (std::size_t i = 0; i < face.PointsNumber(); ++i) {
            const Array3& x = face[i].Coordinates();
            const Array3 shift = length * NodeNormal(face[i], fallback);
            lo = lo.cwiseMin(x - shift).cwiseMin(x + shift);
            hi = hi.cwiseMax(x - shift).cwiseMax(x + shift);
        }
        mTree.SearchInBox(lo, hi, results, mSettings.allocation_size);
        return;
    }
    // A face starting inside the master body looks that much further: the masters it overlaps lie behind it.
    const auto penetrating = mPenetratingFaces.find(&slave);
    const double depth = penetrating == mPenetratingFaces.end() ? 0.0 : penetrating->second;
    mTree.SearchInRadius(face.Center(), length + depth, results, mSettings.allocation_size);
}

ContactSearchProcess::CheckResult ContactSearchProcess::CheckCondition(const Condition& slave,
                                                                       const Condition& master) const {
    if (slave.Id() == master.Id()) return CheckResult::Fail;
    // Faces of the same orientation cannot face each other.
    if ((slave.GetValue(NORMAL) - master.GetValue(NORMAL)).norm() < 1e-16 + mSettings.normal_orientation_threshold)
        return CheckResult::Fail;
    // Self contact: neighbours of the same surface are never a pair.
    if (!mSettings.predefined_master_slave && ShareANode(slave.GetGeometry(), master.GetGeometry()))
        return CheckResult::Fail;
    const auto slave_map = slave.GetValue(INDEX_MAP);
    if (slave_map && slave_map->Has(master.Id())) return CheckResult::AlreadyInTheMap;
    if (!mSettings.predefined_master_slave || IsSlaveRole(master)) {
        const auto master_map = master.GetValue(INDEX_MAP);
        if (master_map && master_map->Has(slave.Id())) return CheckResult::Fail;  // no reciprocal pair
    }
    return CheckResult::OK;
}

std::vector<Condition*> ContactSearchProcess::SlaveFaces() const {
    std::vector<Condition*> faces;
    for (const auto& face : mpContactPart->Conditions())
        if (!IsPair(*face) && IsSlaveRole(*face)) faces.push_back(face.get());
    return faces;
}

std::vector<Node*> ContactSearchProcess::SlaveNodes() const {
    std::vector<Node*> nodes;
    for (Condition* face : SlaveFaces())
        for (std::size_t i = 0; i < face->GetGeometry().PointsNumber(); ++i) nodes.push_back(&face->GetGeometry()[i]);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    return nodes;
}

void ContactSearchProcess::SearchPairs() {
    std::vector<std::size_t> found;
    const bool obb = UsesOBB();
    const auto slaves = SlaveFaces();
    mTimings.slave_faces = slaves.size();
    for (Condition* slave : slaves) {
        IndexMap& map = IndexMapOf(*slave);
        QueryCandidates(*slave, found);
        mTimings.candidates += found.size();
        std::optional<OrientedBoundingBox> slave_box;
        for (const std::size_t index : found) {
            Condition& master = *mMasters[index].condition;
            if (obb) {
                if (!slave_box) {
                    // A face starting inside the master body is swept behind itself by the search reach, like the
                    // in_box sweep, so that the masters it penetrates pass the filter.
                    slave_box.emplace(slave->GetGeometry(), mThickness);
                    if (mPenetratingFaces.count(slave)) slave_box->ExtendAlong(-slave->GetValue(NORMAL), SearchReach(*slave));
                }
                if (!slave_box->HasIntersection(*mMasters[index].box)) continue;
            }
            if (CheckCondition(*slave, master) != CheckResult::OK) continue;
            if (mSettings.check_gap == CheckGap::MappingCheck) map.AddId(master.Id());
            else AddPotentialPairing(*slave, master);
        }
    }
}

// -- Initial penetration (docs/theory/contact_search.md) --

void ContactSearchProcess::FindInitialPenetration() {
    // Surface components (faces joined through shared nodes): a face of the node's own body never contains it.
    std::unordered_map<const Node*, const Node*> parent;
    const auto find = [&](const Node* node) {
        auto it = parent.find(node);
        while (it != parent.end() && it->second != node) {
            node = it->second;
            it = parent.find(node);
        }
        return node;
    };
    for (const auto& face : mpContactPart->Conditions()) {
        if (IsPair(*face)) continue;
        const Geometry& geometry = face->GetGeometry();
        for (std::size_t i = 0; i < geometry.PointsNumber(); ++i) parent.emplace(&geometry[i], &geometry[i]);
        for (std::size_t i = 1; i < geometry.PointsNumber(); ++i) parent[find(&geometry[i])] = find(&geometry[0]);
    }
    std::unordered_map<const Node*, std::vector<Condition*>> faces_of;
    for (Condition* face : SlaveFaces())
        for (std::size_t i = 0; i < face->GetGeometry().PointsNumber(); ++i)
            faces_of[&face->GetGeometry()[i]].push_back(face);
    std::vector<Node*> nodes = SlaveNodes();
    std::sort(nodes.begin(), nodes.end(), [](const Node* a, const Node* b) { return a->Id() < b->Id(); });
    std::vector<Condition*> masters;
    for (const MasterFace& master : mMasters) masters.push_back(master.condition);
    const auto penetrating =
        FindPenetratingNodes(nodes, masters, mTree, mMaxMasterRadius, [&](const Node& node, const Condition& master) {
            return find(&node) == find(&master.GetGeometry()[0]);
        });
    const double factor = ActiveCheckFactor();
    std::vector<PenetratingNode> too_deep;
    double needed_factor = 0.0, deepest = 0.0;
    for (const PenetratingNode& hit : penetrating) {
        if (hit.depth <= factor * NodalH(*hit.node)) continue;  // within what the activation rules already take
        double reach = 0.0;
        for (const Condition* face : faces_of[hit.node]) reach = std::max(reach, SearchReach(*face));
        if (hit.depth > reach) {
            too_deep.push_back(hit);
            needed_factor = std::max(needed_factor, mSettings.search_factor * hit.depth / reach);
            deepest = std::max(deepest, hit.depth);
            continue;
        }
        for (Condition* face : faces_of[hit.node]) {
            double& deepest_of_face = mPenetratingFaces[face];
            deepest_of_face = std::max(deepest_of_face, hit.depth);
            mPenetrationPairs.emplace_back(face, hit.master);
        }
        mPenetratingNodes.emplace_back(hit.node, hit.depth);
    }
    if (too_deep.empty()) return;
    std::ostringstream list;
    for (std::size_t k = 0; k < std::min<std::size_t>(too_deep.size(), 5); ++k)
        list << (k ? ", " : "") << "node " << too_deep[k].node->Id() << " at depth " << too_deep[k].depth << " behind master condition "
             << too_deep[k].master->Id();
    if (too_deep.size() > 5) list << ", ...";
    CONTACT_THROW(InputError, "contact search: ", too_deep.size(), " slave node(s) of \"", mpContactPart->FullName(),
                  "\" start behind the master surface (inside the master body), deeper than the search reaches (", list.str(),
                  "; deepest ", deepest, ")\n  where:    search_parameters › search_factor = ", mSettings.search_factor,
                  " (", SearchesInBox() ? "the box sweep" : "the search radius",
                  " is search_factor × the slave face size)\n  expected: an initial penetration the search reaches, or "
                  "none\n  fix:      move the slave body out of the master (check the mesh coordinates), or raise "
                  "search_factor to at least ",
                  std::ceil(needed_factor * 1.05 * 10.0 - 1e-9) / 10.0, " so that these nodes are paired and pushed out");
}

void ContactSearchProcess::PairPenetratingNodes() {
    // The master each penetrating node is behind, whether or not the candidate query reached its centre.
    for (const auto& [slave, master] : mPenetrationPairs)
        if (CheckCondition(*slave, *master) == CheckResult::OK) IndexMapOf(*slave).AddId(master->Id());
    mPenetrationPairs.clear();
    mPenetratingFaces.clear();
}

void ContactSearchProcess::ActivatePenetratingNodes() {
    for (auto& [node, depth] : mPenetratingNodes) {
        SetActiveNode(*node);
        if (mSettings.check_gap == CheckGap::MappingCheck && node->GetValue(NORMAL_GAP) > -depth)
            node->SetValue(NORMAL_GAP, -depth);
    }
    mPenetratingNodes.clear();
}

// -- Pairs --

void ContactSearchProcess::AddPotentialPairing(Condition& slave, Condition& master) {
    Geometry& face = slave.GetGeometry();
    bool any = false;
    if (mSettings.check_gap == CheckGap::NoCheck) {
        for (std::size_t i = 0; i < face.PointsNumber(); ++i) SetActiveNode(face[i]);
        any = true;
    } else {  // DirectCheck
        const double factor = ActiveCheckFactor();
        const Array3 master_normal = master.GetValue(NORMAL);
        for (std::size_t i = 0; i < face.PointsNumber(); ++i) {
            Node& node = face[i];
            if (node.Is(ACTIVE)) {
                any = true;
                continue;
            }
            // Signed distance along the normal, open gap positive; a penetration deeper than NODAL_H is taken
            // for a face on the far side of the body, not for contact.
            const double h = NodalH(node), threshold = h * factor;
            const auto along_normal = ProjectAlong(node.Coordinates(), NodeNormal(node, slave.GetValue(NORMAL)), master);
            const auto along_master = ProjectAlong(node.Coordinates(), -master_normal, master);
            const auto close = [&](const std::optional<double>& t) { return t && *t <= threshold && *t >= -h; };
            if (close(along_normal) || close(along_master)) {
                SetActiveNode(node);
                any = true;
            }
        }
    }
    if (any) IndexMapOf(slave).AddId(master.Id());
}

void ContactSearchProcess::CreatePairConditions() {
    if (mSettings.condition_name.empty()) return;
    const ModelPart& root = mrMainModelPart.GetRootModelPart();
    for (Condition* slave : SlaveFaces()) {
        IndexMap& map = IndexMapOf(*slave);
        std::vector<IndexType> pending;
        for (const auto& [master_id, pair_id] : map)
            if (pair_id == 0) pending.push_back(master_id);
        for (const IndexType master_id : pending) {
            Condition* master = root.Conditions().Find(master_id);
            CONTACT_CHECK(master != nullptr, InternalError, "contact search: master condition ", master_id,
                          " of the INDEX_MAP of condition ", slave->Id(), " is not in ", root.Name());
            map.SetNewEntityId(master_id, AddPairing(*slave, *master)->Id());
        }
    }
    mSymmetryMultipliers = ContactUtilities::FixSymmetryPlaneMultipliers(*mpComputingPart, mSymmetryMultipliers);
}

Condition::Pointer ContactSearchProcess::AddPairing(Condition& slave, Condition& master) {
    const std::string name = PairConditionName(slave.GetGeometry().WorkingSpaceDimension(), slave.GetGeometry().PointsNumber());
    const auto* prototype = dynamic_cast<const PairedCondition*>(&Registry<Condition>::Instance().Get(name));
    CONTACT_CHECK(prototype != nullptr, InputError, "contact search: condition \"", name,
                  "\" is not a paired (contact) condition\n  where:    condition_name \"", mSettings.condition_name,
                  "\", final_string \"", mSettings.final_string,
                  "\"\n  fix:      use a contact condition stem such as \"ALMFrictionlessMortarContact\"");
    ModelPart& root = mrMainModelPart.GetRootModelPart();
    auto properties = mpPairProperties ? mpPairProperties : slave.pGetProperties();
    auto pair = prototype->Create(root.Conditions().MaxId() + 1, slave.pGetGeometry(), properties, master.pGetGeometry());
    mpComputingPart->AddCondition(pair);
    pair->SetValue(NORMAL, slave.GetValue(NORMAL));
    pair->Set(ACTIVE, true);
    pair->Initialize(root.GetProcessInfo());
    OnPairCreated(*pair);
    return pair;
}

void ContactSearchProcess::AssignSelfContactRoles() {
    // Every face may take either role: a pre-search over all faces (custom_processes/self_contact_utilities.h)
    // decides them; the real search then runs on the flags.
    std::vector<Condition*> faces;
    for (const auto& face : mpContactPart->Conditions())
        if (!IsPair(*face)) faces.push_back(face.get());
    BuildTree(faces);  // mMasters[i].condition == faces[i]
    std::vector<std::size_t> found;
    const auto candidates = [&](std::size_t i, std::vector<std::size_t>& result) {
        result.clear();
        QueryCandidates(*faces[i], found);
        std::optional<OrientedBoundingBox> box;
        for (const std::size_t j : found) {
            if ((faces[i]->GetValue(NORMAL) - faces[j]->GetValue(NORMAL)).norm() <
                1e-16 + mSettings.normal_orientation_threshold)
                continue;
            if (mMasters[j].box) {
                if (!box) box.emplace(faces[i]->GetGeometry(), mThickness);
                if (!box->HasIntersection(*mMasters[j].box)) continue;
            }
            result.push_back(j);
        }
    };
    ApplySelfContactRoles(faces, ComputeSelfContactRoles(faces, candidates));
}

void ContactSearchProcess::ApplySelfContactRoles(const std::vector<Condition*>& faces,
                                                 const std::vector<SelfContactRole>& roles) {
    const Flags slave_flag = mSettings.inverted_search ? MASTER : SLAVE;
    const Flags master_flag = mSettings.inverted_search ? SLAVE : MASTER;
    for (const auto& node : mpContactPart->Nodes()) {
        node->Set(slave_flag, false);
        node->Set(master_flag, true);
    }
    std::vector<Condition*> orphan_pairs;
    const ModelPart& root = mrMainModelPart.GetRootModelPart();
    for (std::size_t i = 0; i < faces.size(); ++i) {
        Condition& face = *faces[i];
        const bool slave = roles[i] == SelfContactRole::Slave;
        face.Set(slave_flag, slave);
        face.Set(master_flag, !slave);
        if (slave) {
            for (std::size_t k = 0; k < face.GetGeometry().PointsNumber(); ++k) {
                face.GetGeometry()[k].Set(slave_flag, true);
                face.GetGeometry()[k].Set(master_flag, false);
            }
        } else if (auto map = face.GetValue(INDEX_MAP)) {  // a former slave: drop its pairs
            for (const auto& [master_id, pair_id] : *map)
                if (Condition* pair = pair_id == 0 ? nullptr : root.Conditions().Find(pair_id)) orphan_pairs.push_back(pair);
            map->clear();
        }
    }
    if (orphan_pairs.empty()) return;
    OnPairsErased(orphan_pairs);
    for (Condition* pair : orphan_pairs) pair->Set(TO_ERASE, true);
    mrMainModelPart.GetRootModelPart().RemoveConditionsFlagged(TO_ERASE);
}

// -- Gaps and active set --

void ContactSearchProcess::MoveByStepJump(double sign) {
    if (sign < 0.0) {
        for (auto& [node, jump] : mStepJump) node->Coordinates() -= jump;
        mStepJump.clear();
        return;
    }
    mStepJump.clear();
    const ModelPart& root = mrMainModelPart.GetRootModelPart();
    if (!mSettings.dynamic_search || !root.HasNodalSolutionStepVariable(VELOCITY)) return;
    const double dt = root.GetProcessInfo().GetValue(DELTA_TIME);
    const bool with_acceleration = root.HasNodalSolutionStepVariable(ACCELERATION);
    for (const auto& node : mpContactPart->Nodes()) {
        Array3 jump = dt * node->FastGetSolutionStepValue(VELOCITY);
        if (with_acceleration) jump += 0.5 * dt * dt * node->FastGetSolutionStepValue(ACCELERATION);
        node->Coordinates() += jump;
        mStepJump.emplace_back(node.get(), jump);
    }
}

void ContactSearchProcess::ComputeMappedGap() {
    // NORMAL_GAP_i = t with x_i + t·n_i on a paired master face (the smallest |t|), open gap positive —
    // (x_i − x̂_i)·(−n_i) of the reference with x̂_i the projection; 1e12 where no master is hit.
    const ModelPart& root = mrMainModelPart.GetRootModelPart();
    for (Node* node : SlaveNodes()) node->SetValue(NORMAL_GAP, 1e12);
    for (Condition* slave : SlaveFaces()) {
        const auto map = slave->GetValue(INDEX_MAP);
        if (!map || map->empty()) continue;
        Geometry& face = slave->GetGeometry();
        for (std::size_t i = 0; i < face.PointsNumber(); ++i) {
            Node& node = face[i];
            const Array3 normal = NodeNormal(node, slave->GetValue(NORMAL));
            double gap = node.GetValue(NORMAL_GAP);
            for (const auto& [master_id, pair_id] : *map) {
                const Condition* master = root.Conditions().Find(master_id);
                if (master == nullptr) continue;
                const auto t = ProjectAlong(node.Coordinates(), normal, *master);
                if (t && std::abs(*t) < std::abs(gap)) gap = *t;
            }
            node.SetValue(NORMAL_GAP, gap);
        }
    }
}

void ContactSearchProcess::CheckPairing() {
    // DISTANCE_THRESHOLD = max(mean NODAL_H of the slave nodes, of the master nodes).
    const auto mean_h = [](const std::vector<Node*>& nodes) {
        double sum = 0.0;
        for (const Node* node : nodes) sum += NodalH(*node);
        return nodes.empty() ? 0.0 : sum / static_cast<double>(nodes.size());
    };
    std::vector<Node*> master_nodes;
    for (const auto& face : mpContactPart->Conditions())
        if (!IsPair(*face) && !IsSlaveRole(*face))
            for (std::size_t i = 0; i < face->GetGeometry().PointsNumber(); ++i)
                master_nodes.push_back(&face->GetGeometry()[i]);
    std::sort(master_nodes.begin(), master_nodes.end());
    master_nodes.erase(std::unique(master_nodes.begin(), master_nodes.end()), master_nodes.end());
    mrMainModelPart.GetProcessInfo().SetValue(DISTANCE_THRESHOLD, std::max(mean_h(SlaveNodes()), mean_h(master_nodes)));

    ComputeMappedGap();
    if (!mStepJump.empty()) {
        MoveByStepJump(-1.0);
        ComputeNodesMeanNormalModelPart(*mpContactPart, true);
    }
    CreatePairConditions();
    ComputeWeightedReaction();
    ComputeActiveInactiveNodes();
}

void ContactSearchProcess::ComputeWeightedReaction() {
    for (const auto& node : mpContactPart->Nodes()) ContactUtilities::ResetExplicitNodalValues(*node);
    const ProcessInfo& process_info = mrMainModelPart.GetProcessInfo();
    for (const auto& pair : mpComputingPart->Conditions()) pair->AddExplicitContribution(process_info);
}

double ContactSearchProcess::ActiveCheckFactor() const {
    const ProcessInfo& process_info = mrMainModelPart.GetProcessInfo();
    return process_info.Has(ACTIVE_CHECK_FACTOR) ? process_info.GetValue(ACTIVE_CHECK_FACTOR) : 0.01;
}

void ContactSearchProcess::ComputeActiveInactiveNodes() {
    const double base = mrMainModelPart.GetProcessInfo().GetValue(DISTANCE_THRESHOLD) * ActiveCheckFactor();
    const bool weighted_gap = mrMainModelPart.GetRootModelPart().HasNodalSolutionStepVariable(WEIGHTED_GAP);
    for (Node* node : SlaveNodes()) {
        const double gap = node->GetValue(NORMAL_GAP);
        bool active = gap < base;
        if (!active && !mSettings.simple_search && weighted_gap) {
            const double wg = node->FastGetSolutionStepValue(WEIGHTED_GAP);
            double limit = base;
            if (mSettings.static_check_movement && mSettings.consider_gap_threshold &&
                wg - node->FastGetSolutionStepValue(WEIGHTED_GAP, 1) > -1e-3 * std::abs(wg))
                limit = std::max(limit, 2e-4);
            const double area = node->GetValue(NODAL_AREA);
            active = node->Is(ACTIVE) && area > 0.0 && wg / area < limit;
        }
        if (active) SetActiveNode(*node);
        else SetInactiveNode(*node);
    }
}

void ContactSearchProcess::UpdatePairActivity() {
    // A pair survives the next clear while one of its slave nodes is in the active set (ResetContactOperators erases
    // the rest; the search recreates them if they are candidates again).
    for (const auto& pair : mpComputingPart->Conditions()) {
        const auto* paired = dynamic_cast<const PairedCondition*>(pair.get());
        if (paired == nullptr) continue;
        const Geometry& face = paired->GetParentGeometry();
        bool active = false;
        for (std::size_t i = 0; i < face.PointsNumber(); ++i) active = active || face[i].Is(ACTIVE);
        pair->Set(ACTIVE, active);
    }
}

void ContactSearchProcess::SetActiveNode(Node& node) const {
    if (node.IsNot(ACTIVE)) InitializeSlip(node);
    node.Set(ACTIVE, true);
    node.Set(MARKER, true);
}

void ContactSearchProcess::SetInactiveNode(Node& node) const {
    if (node.Is(MARKER)) return;  // activated by another search of this step
    node.Set(ACTIVE, false);
    ZeroMultipliers(node);
    node.SetValue(NORMAL_GAP, 0.0);
}

void ContactSearchProcess::ZeroMultipliers(Node& node) const {
    switch (mTypeSolution) {
        case TypeSolution::VectorLagrangeMultiplier:
            node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = Array3::Zero();
            break;
        case TypeSolution::NormalContactStress:
            node.FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) = 0.0;
            break;
        case TypeSolution::ScalarLagrangeMultiplier:
            node.FastGetSolutionStepValue(SCALAR_LAGRANGE_MULTIPLIER) = 0.0;
            break;
        default:
            break;
    }
}

void ContactSearchProcess::InitializeSlip(Node& node) const {
    double mu = 0.0;
    if (node.SolutionStepsDataHas(FRICTION_COEFFICIENT)) mu = node.FastGetSolutionStepValue(FRICTION_COEFFICIENT);
    else if (node.Has(FRICTION_COEFFICIENT)) mu = node.GetValue(FRICTION_COEFFICIENT);
    else if (mpPairProperties && mpPairProperties->Has(FRICTION_COEFFICIENT)) mu = mpPairProperties->GetValue(FRICTION_COEFFICIENT);
    if (mu < 1e-12 || mSettings.pure_slip) {
        node.Set(SLIP, true);
        return;
    }
    // Frictional vector multipliers: a node still carrying a multiplier keeps its stick/slip state.
    if (mTypeSolution == TypeSolution::VectorLagrangeMultiplier &&
        node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER).norm() > 1e-12)
        return;
    if (node.IsNotDefined(SLIP)) node.Set(SLIP, false);
}

}  // namespace contact_app
