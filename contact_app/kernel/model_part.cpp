// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/model_part.h"

#include <cmath>
#include <sstream>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/registry.h"
#include "contact_app/kernel/string_utilities.h"
#include "contact_app/kernel/variables.h"

namespace contact_app {

namespace {

/// Calls @p action on @p part and every ancestor up to the root.
template <class TAction>
void UpTheTree(ModelPart& part, TAction action) {
    ModelPart* current = &part;
    while (true) {
        action(*current);
        if (!current->IsSubModelPart()) break;
        current = &current->GetParentModelPart();
    }
}

}  // namespace

ModelPart::ModelPart(std::string name, std::size_t buffer_size, Model* model)
    : mName(std::move(name)),
      mModel(model),
      mProcessInfo(std::make_shared<ProcessInfo>()),
      mVariables(std::make_shared<VariablesList>()),
      mBufferSize(std::make_shared<std::size_t>(buffer_size)) {
    CONTACT_CHECK(!mName.empty() && mName.find('.') == std::string::npos, InputError, "invalid model part name \"",
                  mName, "\"\n  expected: a non-empty name without '.' (dots separate sub model parts)");
    CONTACT_CHECK(buffer_size >= 1, InputError, "model part ", mName, ": buffer size must be at least 1, got ",
                  buffer_size);
}

ModelPart::ModelPart(std::string name, ModelPart& parent)
    : mName(std::move(name)),
      mParent(&parent),
      mModel(parent.mModel),
      mProcessInfo(parent.mProcessInfo),
      mVariables(parent.mVariables),
      mBufferSize(parent.mBufferSize) {}

std::string ModelPart::FullName() const { return mParent ? mParent->FullName() + "." + mName : mName; }

ModelPart& ModelPart::GetRootModelPart() { return mParent ? mParent->GetRootModelPart() : *this; }
const ModelPart& ModelPart::GetRootModelPart() const { return mParent ? mParent->GetRootModelPart() : *this; }

// -- Sub model parts --

ModelPart& ModelPart::CreateSubModelPart(const std::string& name) {
    CONTACT_CHECK(!name.empty() && name.find('.') == std::string::npos, InputError, "invalid sub model part name \"",
                  name, "\" in ", FullName(), "\n  expected: a non-empty name without '.'");
    CONTACT_CHECK(!HasSubModelPart(name), InputError, "model part ", FullName(), " already has a sub model part \"",
                  name, "\"\n  fix: use GetSubModelPart to reach it, or choose another name");
    mSubModelParts.push_back(std::unique_ptr<ModelPart>(new ModelPart(name, *this)));
    return *mSubModelParts.back();
}

ModelPart& ModelPart::GetSubModelPart(const std::string& name) {
    const auto dot = name.find('.');
    const std::string head = name.substr(0, dot);
    for (auto& child : mSubModelParts) {
        if (child->Name() == head) return dot == std::string::npos ? *child : child->GetSubModelPart(name.substr(dot + 1));
    }
    const auto names = GetSubModelPartNames();
    std::string listing;
    for (const auto& child : names) listing += (listing.empty() ? "" : ", ") + child;
    CONTACT_THROW(InputError, "model part ", FullName(), " has no sub model part \"", head, "\"", DidYouMean(head, names),
                  "\n  existing: ", listing.empty() ? std::string("none") : listing);
}

bool ModelPart::HasSubModelPart(const std::string& name) const {
    const auto dot = name.find('.');
    const std::string head = name.substr(0, dot);
    for (const auto& child : mSubModelParts) {
        if (child->Name() == head) return dot == std::string::npos || child->HasSubModelPart(name.substr(dot + 1));
    }
    return false;
}

void ModelPart::RemoveSubModelPart(const std::string& name) {
    const auto found = std::find_if(mSubModelParts.begin(), mSubModelParts.end(),
                                    [&](const auto& child) { return child->Name() == name; });
    CONTACT_CHECK(found != mSubModelParts.end(), InputError, "model part ", FullName(),
                  " has no sub model part \"", name, "\" to remove");
    mSubModelParts.erase(found);
}

std::vector<std::string> ModelPart::GetSubModelPartNames() const {
    std::vector<std::string> names;
    for (const auto& child : mSubModelParts) names.push_back(child->Name());
    return names;
}

std::vector<ModelPart*> ModelPart::SubModelParts() const {
    std::vector<ModelPart*> parts;
    for (const auto& child : mSubModelParts) parts.push_back(child.get());
    return parts;
}

// -- Variables and buffer --

void ModelPart::AddNodalSolutionStepVariable(const VariableData& variable) {
    if (mVariables->Has(variable)) return;
    mVariables->Add(variable);
    for (const auto& node : GetRootModelPart().mNodes) node->ResizeSolutionStepData(*mBufferSize);
}

bool ModelPart::HasNodalSolutionStepVariable(const VariableData& variable) const { return mVariables->Has(variable); }

const VariablesList::Pointer& ModelPart::pGetNodalSolutionStepVariablesList() const { return mVariables; }

void ModelPart::SetBufferSize(std::size_t buffer_size) {
    CONTACT_CHECK(buffer_size >= 1, InputError, "model part ", FullName(), ": buffer size must be at least 1, got ",
                  buffer_size);
    *mBufferSize = buffer_size;
    for (const auto& node : GetRootModelPart().mNodes) node->ResizeSolutionStepData(buffer_size);
}

std::size_t ModelPart::GetBufferSize() const { return *mBufferSize; }

void ModelPart::CloneTimeStep(double new_time) {
    ProcessInfo& info = *mProcessInfo;
    const double old_time = info.GetValue(TIME);
    // Checked before the buffers move: a NaN TIME would otherwise run every later step silently.
    CONTACT_CHECK(std::isfinite(new_time), InputError, "CloneTimeStep(", new_time, ") on model part ", FullName(),
                  ": the new time is not finite\n  expected: a finite time",
                  "\n  fix:      check the time stepping that computes it (time_step, start_time, end_time)");
    CONTACT_CHECK(std::isfinite(new_time - old_time), InputError, "CloneTimeStep(", new_time, ") on model part ",
                  FullName(), ": the step from the current TIME ", old_time, " is not finite",
                  "\n  expected: a finite TIME and a finite step\n  fix:      check what set TIME");
    for (const auto& node : GetRootModelPart().mNodes) node->CloneSolutionStep();
    info.SetValue(TIME, new_time);
    info.SetValue(DELTA_TIME, new_time - old_time);
    info.SetValue(STEP, info.GetValue(STEP) + 1);
}

// -- Helpers --

void ModelPart::CheckNewId(const char* kind, bool taken, IndexType id) const {
    CONTACT_CHECK(id >= 1, InputError, kind, " id ", id, " in model part ", FullName(), " is invalid",
                  "\n  expected: ids start at 1");
    constexpr IndexType kMaxId = 9223372036854775807ULL;  // what the JSON layer and the outputs store
    CONTACT_CHECK(id <= kMaxId, InputError, kind, " id ", id, " in model part ", FullName(),
                  " is beyond the largest id ", kMaxId, "\n  expected: at most 2^63 - 1");
    CONTACT_CHECK(!taken, InputError, kind, " id ", id, " is already used in model part ",
                  GetRootModelPart().Name(), "\n  fix: ids must be unique per root model part");
}

template <class T>
void ModelPart::ThrowMissing(const char* kind, IndexType id) const {
    CONTACT_THROW(InputError, "model part ", FullName(), " has no ", kind, " with id ", id);
}

std::vector<Node::Pointer> ModelPart::NodesByIds(const std::vector<IndexType>& node_ids, const char* what,
                                                 IndexType id) const {
    const ModelPart& root = GetRootModelPart();
    std::vector<Node::Pointer> nodes;
    nodes.reserve(node_ids.size());
    for (const IndexType node_id : node_ids) {
        Node::Pointer node = root.mNodes.FindPointer(node_id);
        CONTACT_CHECK(node != nullptr, InputError, what, " ", id, " refers to node ", node_id,
                      ", which does not exist in model part ", root.Name());
        nodes.push_back(std::move(node));
    }
    return nodes;
}

// -- Nodes --

Node::Pointer ModelPart::CreateNewNode(IndexType id, double x, double y, double z) {
    ModelPart& root = GetRootModelPart();
    CheckNewId("node", root.mNodes.Contains(id), id);
    CONTACT_CHECK(std::isfinite(x) && std::isfinite(y) && std::isfinite(z), InputError, "node ", id, " of model part ",
                  FullName(), " has a non-finite coordinate (", x, ", ", y, ", ", z, ")",
                  "\n  expected: finite coordinates\n  fix:      check how the coordinates were computed");
    auto node = std::make_shared<Node>(id, x, y, z);
    node->SetSolutionStepVariablesList(mVariables, *mBufferSize);
    UpTheTree(*this, [&](ModelPart& part) { part.mNodes.Insert(node); });
    return node;
}

void ModelPart::AddNode(Node::Pointer node) {
    ModelPart& root = GetRootModelPart();
    if (Node* existing = root.mNodes.Find(node->Id())) {
        CONTACT_CHECK(existing == node.get(), InputError, "cannot add node ", node->Id(), " to model part ", FullName(),
                      ": the root already holds a different node with that id");
    } else if (node->pGetVariablesList() != mVariables) {
        CONTACT_CHECK(node->pGetVariablesList() == nullptr, InputError, "node ", node->Id(),
                      " belongs to another root model part and cannot join ", FullName());
        node->SetSolutionStepVariablesList(mVariables, *mBufferSize);
    }
    UpTheTree(*this, [&](ModelPart& part) { part.mNodes.Insert(node); });
}

void ModelPart::AddNodes(const std::vector<IndexType>& ids) {
    auto nodes = NodesByIds(ids, "sub model part", 0);
    UpTheTree(*this, [&](ModelPart& part) {
        if (&part != &GetRootModelPart()) part.mNodes.InsertMany(nodes);
    });
}

void ModelPart::AddNodesBulk(std::vector<Node::Pointer> nodes) {
    for (const auto& node : nodes)
        if (node->pGetVariablesList() != mVariables) node->SetSolutionStepVariablesList(mVariables, *mBufferSize);
    UpTheTree(*this, [&](ModelPart& part) {
        const auto clash = part.mNodes.InsertMany(nodes);
        CONTACT_CHECK(!clash, InputError, "node id ", clash.value_or(0), " is used twice in model part ", part.FullName(),
                      "\n  fix: node ids must be unique");
    });
}

Node::Pointer ModelPart::pGetNode(IndexType id) const {
    Node::Pointer node = mNodes.FindPointer(id);
    if (!node) ThrowMissing<Node>("node", id);
    return node;
}

void ModelPart::RemoveNode(IndexType id) {
    mNodes.Erase(id);
    for (auto& child : mSubModelParts) child->RemoveNode(id);
}

// -- Properties --

Properties::Pointer ModelPart::CreateNewProperties(IndexType id) {
    CONTACT_CHECK(!GetRootModelPart().mProperties.Contains(id), InputError, "properties ", id,
                  " already exist in model part ", GetRootModelPart().Name(),
                  "\n  fix: use GetProperties to reach them");
    auto properties = std::make_shared<Properties>(id);
    UpTheTree(*this, [&](ModelPart& part) { part.mProperties.Insert(properties); });
    return properties;
}

Properties::Pointer ModelPart::pGetProperties(IndexType id) {
    if (auto found = mProperties.FindPointer(id)) return found;
    if (auto at_root = GetRootModelPart().mProperties.FindPointer(id)) {
        AddProperties(at_root);
        return at_root;
    }
    return CreateNewProperties(id);
}

void ModelPart::AddProperties(Properties::Pointer properties) {
    UpTheTree(*this, [&](ModelPart& part) {
        CONTACT_CHECK(part.mProperties.Insert(properties), InputError, "model part ", part.FullName(),
                      " already holds different properties with id ", properties->Id());
    });
}

// -- Elements --

Element::Pointer ModelPart::CreateNewElement(const std::string& name, IndexType id,
                                             const std::vector<IndexType>& node_ids, Properties::Pointer properties) {
    const Element& prototype = Registry<Element>::Instance().Get(name);
    CheckNewId("element", GetRootModelPart().mElements.Contains(id), id);
    auto element = prototype.Create(id, NodesByIds(node_ids, "element", id), std::move(properties));
    UpTheTree(*this, [&](ModelPart& part) { part.mElements.Insert(element); });
    return element;
}

void ModelPart::AddElement(Element::Pointer element) {
    UpTheTree(*this, [&](ModelPart& part) {
        CONTACT_CHECK(part.mElements.Insert(element), InputError, "model part ", part.FullName(),
                      " already holds a different element with id ", element->Id());
    });
}

void ModelPart::AddElements(const std::vector<IndexType>& ids) {
    std::vector<Element::Pointer> elements;
    const ModelPart& root = GetRootModelPart();
    for (const IndexType id : ids) {
        auto element = root.mElements.FindPointer(id);
        CONTACT_CHECK(element != nullptr, InputError, "element ", id, " does not exist in model part ", root.Name(),
                      " and cannot be added to ", FullName());
        elements.push_back(std::move(element));
    }
    UpTheTree(*this, [&](ModelPart& part) { part.mElements.InsertMany(elements); });
}

void ModelPart::AddElementsBulk(std::vector<Element::Pointer> elements) {
    UpTheTree(*this, [&](ModelPart& part) {
        const auto clash = part.mElements.InsertMany(elements);
        CONTACT_CHECK(!clash, InputError, "element id ", clash.value_or(0), " is used twice in model part ",
                      part.FullName(), "\n  fix: element ids must be unique");
    });
}

Element::Pointer ModelPart::pGetElement(IndexType id) const {
    auto element = mElements.FindPointer(id);
    if (!element) ThrowMissing<Element>("element", id);
    return element;
}

void ModelPart::RemoveElement(IndexType id) {
    mElements.Erase(id);
    for (auto& child : mSubModelParts) child->RemoveElement(id);
}

// -- Conditions --

Condition::Pointer ModelPart::CreateNewCondition(const std::string& name, IndexType id,
                                                 const std::vector<IndexType>& node_ids,
                                                 Properties::Pointer properties) {
    const Condition& prototype = Registry<Condition>::Instance().Get(name);
    CheckNewId("condition", GetRootModelPart().mConditions.Contains(id), id);
    auto condition = prototype.Create(id, NodesByIds(node_ids, "condition", id), std::move(properties));
    UpTheTree(*this, [&](ModelPart& part) { part.mConditions.Insert(condition); });
    return condition;
}

void ModelPart::AddCondition(Condition::Pointer condition) {
    UpTheTree(*this, [&](ModelPart& part) {
        CONTACT_CHECK(part.mConditions.Insert(condition), InputError, "model part ", part.FullName(),
                      " already holds a different condition with id ", condition->Id());
    });
}

void ModelPart::AddConditions(const std::vector<IndexType>& ids) {
    std::vector<Condition::Pointer> conditions;
    const ModelPart& root = GetRootModelPart();
    for (const IndexType id : ids) {
        auto condition = root.mConditions.FindPointer(id);
        CONTACT_CHECK(condition != nullptr, InputError, "condition ", id, " does not exist in model part ", root.Name(),
                      " and cannot be added to ", FullName());
        conditions.push_back(std::move(condition));
    }
    UpTheTree(*this, [&](ModelPart& part) { part.mConditions.InsertMany(conditions); });
}

void ModelPart::AddConditionsBulk(std::vector<Condition::Pointer> conditions) {
    UpTheTree(*this, [&](ModelPart& part) {
        const auto clash = part.mConditions.InsertMany(conditions);
        CONTACT_CHECK(!clash, InputError, "condition id ", clash.value_or(0), " is used twice in model part ",
                      part.FullName(), "\n  fix: condition ids must be unique");
    });
}

Condition::Pointer ModelPart::pGetCondition(IndexType id) const {
    auto condition = mConditions.FindPointer(id);
    if (!condition) ThrowMissing<Condition>("condition", id);
    return condition;
}

void ModelPart::RemoveCondition(IndexType id) {
    mConditions.Erase(id);
    for (auto& child : mSubModelParts) child->RemoveCondition(id);
}

std::size_t ModelPart::RemoveConditionsFlagged(const Flags& flag) {
    for (auto& child : mSubModelParts) child->RemoveConditionsFlagged(flag);
    return mConditions.EraseIf([&](const Condition& condition) { return condition.Is(flag); });
}

// -- Constraints --

MasterSlaveConstraint::Pointer ModelPart::CreateNewMasterSlaveConstraint(const std::string& name, IndexType id,
                                                                         DofsVectorType master_dofs,
                                                                         DofsVectorType slave_dofs,
                                                                         const Matrix& relation,
                                                                         const Vector& constant) {
    const MasterSlaveConstraint& prototype = Registry<MasterSlaveConstraint>::Instance().Get(name);
    CheckNewId("constraint", GetRootModelPart().mConstraints.Contains(id), id);
    CONTACT_CHECK(relation.allFinite() && constant.allFinite(), InputError, "constraint ", id, " of model part ",
                  FullName(), " has a non-finite weight or constant",
                  "\n  expected: finite numbers in the relation matrix and the constant vector");
    auto constraint = prototype.Create(id, std::move(master_dofs), std::move(slave_dofs), relation, constant);
    UpTheTree(*this, [&](ModelPart& part) { part.mConstraints.Insert(constraint); });
    return constraint;
}

MasterSlaveConstraint::Pointer ModelPart::CreateNewMasterSlaveConstraint(
    const std::string& name, IndexType id, Node& master_node, const Variable<double>& master_variable,
    Node& slave_node, const Variable<double>& slave_variable, double weight, double constant) {
    Matrix relation(1, 1);
    relation(0, 0) = weight;
    Vector constant_vector(1);
    constant_vector[0] = constant;
    return CreateNewMasterSlaveConstraint(name, id, {&master_node.GetDof(master_variable)},
                                          {&slave_node.GetDof(slave_variable)}, relation, constant_vector);
}

void ModelPart::AddMasterSlaveConstraint(MasterSlaveConstraint::Pointer constraint) {
    UpTheTree(*this, [&](ModelPart& part) {
        CONTACT_CHECK(part.mConstraints.Insert(constraint), InputError, "model part ", part.FullName(),
                      " already holds a different constraint with id ", constraint->Id());
    });
}

void ModelPart::AddMasterSlaveConstraints(const std::vector<IndexType>& ids) {
    std::vector<MasterSlaveConstraint::Pointer> constraints;
    const ModelPart& root = GetRootModelPart();
    for (const IndexType id : ids) {
        auto constraint = root.mConstraints.FindPointer(id);
        CONTACT_CHECK(constraint != nullptr, InputError, "constraint ", id, " does not exist in model part ",
                      root.Name(), " and cannot be added to ", FullName());
        constraints.push_back(std::move(constraint));
    }
    UpTheTree(*this, [&](ModelPart& part) { part.mConstraints.InsertMany(constraints); });
}

MasterSlaveConstraint& ModelPart::GetMasterSlaveConstraint(IndexType id) const {
    MasterSlaveConstraint* constraint = mConstraints.Find(id);
    if (!constraint) ThrowMissing<MasterSlaveConstraint>("constraint", id);
    return *constraint;
}

void ModelPart::RemoveMasterSlaveConstraint(IndexType id) {
    mConstraints.Erase(id);
    for (auto& child : mSubModelParts) child->RemoveMasterSlaveConstraint(id);
}

// -- Geometries and tables --

void ModelPart::AddGeometry(IndexType id, Geometry::Pointer geometry) {
    UpTheTree(*this, [&](ModelPart& part) {
        auto [position, inserted] = part.mGeometries.emplace(id, geometry);
        CONTACT_CHECK(inserted || position->second == geometry, InputError, "model part ", part.FullName(),
                      " already holds a different geometry with id ", id);
    });
}

void ModelPart::AddGeometries(const std::vector<IndexType>& ids) {
    for (const IndexType id : ids) AddGeometry(id, GetRootModelPart().pGetGeometry(id));
}

Geometry::Pointer ModelPart::pGetGeometry(IndexType id) const {
    const auto found = mGeometries.find(id);
    if (found == mGeometries.end()) ThrowMissing<Geometry>("geometry", id);
    return found->second;
}

void ModelPart::AddTable(IndexType id, std::shared_ptr<Table> table) {
    UpTheTree(*this, [&](ModelPart& part) { part.mTables[id] = table; });
}

Table& ModelPart::GetTable(IndexType id) const { return *pGetTable(id); }

std::shared_ptr<Table> ModelPart::pGetTable(IndexType id) const {
    const auto found = mTables.find(id);
    if (found == mTables.end()) ThrowMissing<Table>("table", id);
    return found->second;
}

std::string ModelPart::Info(const std::string& indent) const {
    std::ostringstream out;
    out << indent << "ModelPart " << FullName() << ": " << NumberOfNodes() << " nodes, " << NumberOfElements()
        << " elements, " << NumberOfConditions() << " conditions, " << NumberOfMasterSlaveConstraints()
        << " constraints, " << NumberOfProperties() << " properties";
    if (NumberOfGeometries() > 0) out << ", " << NumberOfGeometries() << " geometries";
    if (NumberOfTables() > 0) out << ", " << NumberOfTables() << " tables";
    if (!IsSubModelPart()) out << " (buffer size " << GetBufferSize() << ")";
    out << "\n";
    for (const auto& child : mSubModelParts) out << child->Info(indent + "  ");
    return out.str();
}

}  // namespace contact_app
