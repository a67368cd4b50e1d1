// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "contact_app/kernel/condition.h"
#include "contact_app/kernel/element.h"
#include "contact_app/kernel/entity_container.h"
#include "contact_app/kernel/master_slave_constraint.h"
#include "contact_app/kernel/node.h"
#include "contact_app/kernel/process_info.h"
#include "contact_app/kernel/properties.h"
#include "contact_app/kernel/table.h"

namespace contact_app {

class Model;

/// A named set of nodes, elements, conditions, constraints and properties (Kratos ModelPart).
///
/// The root model part owns the entities, the historical-variable layout, the buffer size and
/// the ProcessInfo. A sub model part holds a subset of its parent's entities (shared pointers)
/// and shares the root's layout and ProcessInfo. Anything added to a sub model part is added
/// to all its ancestors. Ids are unique per root.
class ModelPart : public Flags, public DataValueHolder {
public:
    using NodesContainerType = EntityContainer<Node>;
    using ElementsContainerType = EntityContainer<Element>;
    using ConditionsContainerType = EntityContainer<Condition>;
    using MasterSlaveConstraintContainerType = EntityContainer<MasterSlaveConstraint>;
    using PropertiesContainerType = EntityContainer<Properties>;

    /// A root model part. Prefer Model::CreateModelPart.
    ModelPart(std::string name, std::size_t buffer_size, Model* model = nullptr);
    ModelPart(const ModelPart&) = delete;
    ModelPart& operator=(const ModelPart&) = delete;

    const std::string& Name() const { return mName; }
    /// Dotted path from the root, e.g. "Structure.Contact_Part".
    std::string FullName() const;
    bool IsSubModelPart() const { return mParent != nullptr; }
    ModelPart& GetParentModelPart() { return mParent ? *mParent : *this; }
    ModelPart& GetRootModelPart();
    const ModelPart& GetRootModelPart() const;
    /// The owning model (nullptr for a stand-alone model part).
    Model* GetModel() const { return mModel; }

    // -- Sub model parts --
    /// @throws InputError if the name is empty, contains '.', or exists.
    ModelPart& CreateSubModelPart(const std::string& name);
    /// @param name a direct child name or a dotted path "A.B" below this part.
    /// @throws InputError listing the existing sub model parts.
    ModelPart& GetSubModelPart(const std::string& name);
    bool HasSubModelPart(const std::string& name) const;
    void RemoveSubModelPart(const std::string& name);
    std::vector<std::string> GetSubModelPartNames() const;
    std::size_t NumberOfSubModelParts() const { return mSubModelParts.size(); }
    std::vector<ModelPart*> SubModelParts() const;

    // -- Historical variables and buffer (stored at the root) --
    /// Declares a historical variable; existing nodes grow their storage (values kept).
    void AddNodalSolutionStepVariable(const VariableData& variable);
    bool HasNodalSolutionStepVariable(const VariableData& variable) const;
    const VariablesList::Pointer& pGetNodalSolutionStepVariablesList() const;
    void SetBufferSize(std::size_t buffer_size);
    std::size_t GetBufferSize() const;
    /// Shifts every node's buffer by one step and sets TIME = @p new_time, DELTA_TIME = new - old, STEP += 1.
    void CloneTimeStep(double new_time);

    // -- Nodes --
    /// @throws InputError if the id is 0 or taken by another node of the root.
    Node::Pointer CreateNewNode(IndexType id, double x, double y, double z);
    /// Adds an existing node of the same root (or a free node, which joins the root).
    void AddNode(Node::Pointer node);
    /// Adds root nodes by id. @throws InputError naming the first missing id.
    void AddNodes(const std::vector<IndexType>& ids);
    /// Bulk insertion used by readers: one sort per level. @throws InputError on a clashing id.
    void AddNodesBulk(std::vector<Node::Pointer> nodes);
    bool HasNode(IndexType id) const { return mNodes.Contains(id); }
    /// @throws InputError naming the model part.
    Node& GetNode(IndexType id) const { return *pGetNode(id); }
    Node::Pointer pGetNode(IndexType id) const;
    /// Removes the node from this part and all its sub model parts.
    void RemoveNode(IndexType id);
    /// Removes the node from the whole hierarchy (from the root down).
    void RemoveNodeFromAllLevels(IndexType id) { GetRootModelPart().RemoveNode(id); }
    std::size_t NumberOfNodes() const { return mNodes.size(); }
    const NodesContainerType& Nodes() const { return mNodes; }

    // -- Properties --
    Properties::Pointer CreateNewProperties(IndexType id);
    /// The properties with @p id, created (at the root and here) if missing, as Kratos does.
    Properties::Pointer pGetProperties(IndexType id);
    Properties& GetProperties(IndexType id) { return *pGetProperties(id); }
    bool HasProperties(IndexType id) const { return mProperties.Contains(id); }
    void AddProperties(Properties::Pointer properties);
    std::size_t NumberOfProperties() const { return mProperties.size(); }
    const PropertiesContainerType& PropertiesArray() const { return mProperties; }

    // -- Elements and conditions --
    /// Creates a registered element on root nodes @p node_ids.
    /// @throws InputError for an unknown name (with suggestions), a missing node, a wrong node count, a taken id.
    Element::Pointer CreateNewElement(const std::string& name, IndexType id, const std::vector<IndexType>& node_ids,
                                      Properties::Pointer properties);
    void AddElement(Element::Pointer element);
    void AddElements(const std::vector<IndexType>& ids);
    void AddElementsBulk(std::vector<Element::Pointer> elements);
    bool HasElement(IndexType id) const { return mElements.Contains(id); }
    Element& GetElement(IndexType id) const { return *pGetElement(id); }
    Element::Pointer pGetElement(IndexType id) const;
    void RemoveElement(IndexType id);
    std::size_t NumberOfElements() const { return mElements.size(); }
    const ElementsContainerType& Elements() const { return mElements; }

    Condition::Pointer CreateNewCondition(const std::string& name, IndexType id, const std::vector<IndexType>& node_ids,
                                          Properties::Pointer properties);
    void AddCondition(Condition::Pointer condition);
    void AddConditions(const std::vector<IndexType>& ids);
    void AddConditionsBulk(std::vector<Condition::Pointer> conditions);
    bool HasCondition(IndexType id) const { return mConditions.Contains(id); }
    Condition& GetCondition(IndexType id) const { return *pGetCondition(id); }
    Condition::Pointer pGetCondition(IndexType id) const;
    void RemoveCondition(IndexType id);
    /// Removes (here and below) every condition with @p flag set; returns how many left this part.
    std::size_t RemoveConditionsFlagged(const Flags& flag);
    std::size_t NumberOfConditions() const { return mConditions.size(); }
    const ConditionsContainerType& Conditions() const { return mConditions; }

    // -- Master-slave constraints --
    /// Creates a registered constraint from DoF lists, relation (slaves × masters) and constant.
    MasterSlaveConstraint::Pointer CreateNewMasterSlaveConstraint(const std::string& name, IndexType id,
                                                                  DofsVectorType master_dofs, DofsVectorType slave_dofs,
                                                                  const Matrix& relation, const Vector& constant);
    /// Kratos shortcut: slave = weight · master + constant for one DoF pair.
    MasterSlaveConstraint::Pointer CreateNewMasterSlaveConstraint(const std::string& name, IndexType id,
                                                                  Node& master_node, const Variable<double>& master_variable,
                                                                  Node& slave_node, const Variable<double>& slave_variable,
                                                                  double weight, double constant);
    void AddMasterSlaveConstraint(MasterSlaveConstraint::Pointer constraint);
    void AddMasterSlaveConstraints(const std::vector<IndexType>& ids);
    bool HasMasterSlaveConstraint(IndexType id) const { return mConstraints.Contains(id); }
    MasterSlaveConstraint& GetMasterSlaveConstraint(IndexType id) const;
    void RemoveMasterSlaveConstraint(IndexType id);
    std::size_t NumberOfMasterSlaveConstraints() const { return mConstraints.size(); }
    const MasterSlaveConstraintContainerType& MasterSlaveConstraints() const { return mConstraints; }

    // -- Geometries (geometry-only entities of "Begin Geometries" blocks) --
    void AddGeometry(IndexType id, Geometry::Pointer geometry);
    void AddGeometries(const std::vector<IndexType>& ids);
    bool HasGeometry(IndexType id) const { return mGeometries.count(id) != 0; }
    Geometry::Pointer pGetGeometry(IndexType id) const;
    std::size_t NumberOfGeometries() const { return mGeometries.size(); }
    const std::map<IndexType, Geometry::Pointer>& Geometries() const { return mGeometries; }

    // -- Tables --
    void AddTable(IndexType id, std::shared_ptr<Table> table);
    bool HasTable(IndexType id) const { return mTables.count(id) != 0; }
    Table& GetTable(IndexType id) const;
    std::shared_ptr<Table> pGetTable(IndexType id) const;
    std::size_t NumberOfTables() const { return mTables.size(); }

    // -- Data --
    ProcessInfo& GetProcessInfo() { return *mProcessInfo; }
    const ProcessInfo& GetProcessInfo() const { return *mProcessInfo; }
    const ProcessInfo::Pointer& pGetProcessInfo() const { return mProcessInfo; }
    // Model-part values (Begin ModelPartData / SubModelPartData) come from DataValueHolder.

    /// Multi-line summary: counts per container and the sub model part tree.
    std::string Info(const std::string& indent = "") const;

private:
    ModelPart(std::string name, ModelPart& parent);
    template <class T>
    [[noreturn]] void ThrowMissing(const char* kind, IndexType id) const;
    std::vector<Node::Pointer> NodesByIds(const std::vector<IndexType>& node_ids, const char* what, IndexType id) const;
    void CheckNewId(const char* kind, bool taken, IndexType id) const;

    std::string mName;
    ModelPart* mParent = nullptr;
    Model* mModel = nullptr;
    std::vector<std::unique_ptr<ModelPart>> mSubModelParts;
    NodesContainerType mNodes;
    ElementsContainerType mElements;
    ConditionsContainerType mConditions;
    MasterSlaveConstraintContainerType mConstraints;
    PropertiesContainerType mProperties;
    std::map<IndexType, Geometry::Pointer> mGeometries;
    std::map<IndexType, std::shared_ptr<Table>> mTables;
    // Shared with the whole hierarchy (set by the root).
    ProcessInfo::Pointer mProcessInfo;
    VariablesList::Pointer mVariables;
    std::shared_ptr<std::size_t> mBufferSize;
};

}  // namespace contact_app
