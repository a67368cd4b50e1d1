// SPDX-License-Identifier: BSD-3-Clause
// ModelPartCheckpoint::Load: decode and check everything (pass 1, nothing of the target touched), then insert
// (pass 2, which cannot fail once pass 1 passed and the target was found empty).
#include <map>
#include <memory>
#include <vector>

#include "contact_app/io/checkpoint_stream.h"
#include "contact_app/io/model_part_checkpoint.h"
#include "contact_app/kernel/constitutive_law.h"
#include "contact_app/kernel/geometries/coupling_geometry.h"
#include "contact_app/kernel/geometries/geometry_factory.h"
#include "contact_app/kernel/model_part.h"
#include "contact_app/kernel/registry.h"
#include "contact_app/kernel/restart_pointer_codecs.h"
#include "contact_app/kernel/serializer.h"
#include "contact_app/kernel/variable_registry.h"
#include "contact_app/kernel/variables.h"

namespace contact_app {

using detail::CheckpointReader;

namespace {

struct DofRecord {
    const Variable<double>* variable;
    const Variable<double>* reaction;
    bool fixed;
    std::size_t equation_id;
};

struct NodeRecord {
    Node::Pointer node;
    std::vector<double> history;  // step-major, variables in the saved order
    std::vector<DofRecord> dofs;
};

struct ConstraintRecord {
    std::string name;
    IndexType id = 0;
    bool in_root = false;
    Flags flags;
    DataValueContainer data;
    std::vector<std::pair<IndexType, const Variable<double>*>> slaves, masters;
    Matrix relation;
    Vector constant;
    Matrix test_relation;  ///< empty: W = T
    MasterSlaveConstraint::Pointer created;
};

struct PartRecord {
    std::string name;
    Flags flags;
    DataValueContainer data;
    std::vector<IndexType> nodes, elements, conditions, constraints, properties;
    std::vector<std::pair<IndexType, std::size_t>> geometries;
    std::vector<std::pair<IndexType, std::shared_ptr<Table>>> tables;
    std::vector<std::unique_ptr<PartRecord>> children;
};

struct PendingConstraintPointer {
    DataValueContainer* container;
    const VariableData* variable;
    std::size_t index;
};

class Loader {
public:
    Loader(const std::string& bytes, const std::string& source)
        : mIn(bytes, ModelPartCheckpoint::kHeaderSize, source) {}

    void Decode() {
        mIn.Section("HEAD");
        mName = mIn.GetString();
        mIn.Get<double>();
        mIn.Get<std::int64_t>();
        mBufferSize = mIn.GetCount(0);
        if (mBufferSize == 0) mIn.Fail("a buffer size of 0");
        ReadVariables();
        mIn.Section("PINF");
        mInfoFlags = mIn.GetFlags();
        ReadData(mInfoData);
        ReadProperties();
        ReadNodes();
        ReadGeometries();
        ReadEntities(mElements, "ELEM");
        ReadEntities(mConditions, "COND");
        ReadConstraints();
        mIn.Section("PART");
        ReadPart(mRootPart);
        mIn.Section("END!");
        if (!mIn.AtEnd()) mIn.Fail("data after the end marker");
        if (mRootPart.name != mName) mIn.Fail("the model part tree is named \"" + mRootPart.name + "\", not \"" + mName + "\"");
        for (const auto& pending : mPending)
            if (pending.index >= mConstraints.size()) mIn.Fail("a constraint pointer to a missing constraint");
    }

    const std::string& Name() const { return mName; }

    void Insert(ModelPart& root) {
        for (const VariableData* variable : mVariables) root.AddNodalSolutionStepVariable(*variable);
        root.SetBufferSize(mBufferSize);
        static_cast<Flags&>(root.GetProcessInfo()) = mInfoFlags;
        root.GetProcessInfo().Data() = mInfoData;
        for (auto& pending : mPending)
            if (pending.container == &mInfoData) pending.container = &root.GetProcessInfo().Data();
        for (const auto& [id, properties] : mProperties) root.AddProperties(properties);
        InsertNodes(root);
        std::vector<Element::Pointer> elements;
        for (const auto& [id, element] : mElements) elements.push_back(element);
        root.AddElementsBulk(std::move(elements));
        std::vector<Condition::Pointer> conditions;
        for (const auto& [id, condition] : mConditions) conditions.push_back(condition);
        root.AddConditionsBulk(std::move(conditions));
        for (auto& record : mConstraints) {
            record.created = CreateConstraint(record);
            if (record.in_root) root.AddMasterSlaveConstraint(record.created);
        }
        FillPart(root, mRootPart);
        for (const auto& pending : mPending) {
            const auto& variable =
                VariableRegistry::Instance().GetTyped<MasterSlaveConstraint::Pointer>(pending.variable->Name());
            pending.container->SetValue(variable, mConstraints[pending.index].created);
        }
    }

private:
    const VariableData& GetVariable(const std::string& name) {
        if (!VariableRegistry::Instance().Has(name)) mIn.Fail("the variable " + name + " is not registered here");
        return VariableRegistry::Instance().Get(name);
    }

    const Variable<double>& GetDoubleVariable(const std::string& name) {
        const VariableData& variable = GetVariable(name);
        if (variable.Type() != VariableType::Double && variable.Type() != VariableType::Component)
            mIn.Fail("the DoF variable " + name + " is not a double variable");
        return static_cast<const Variable<double>&>(variable);
    }

    void ReadVariables() {
        mIn.Section("VARS");
        const std::size_t count = mIn.GetCount(8);
        for (std::size_t i = 0; i < count; ++i) {
            const VariableData& variable = GetVariable(mIn.GetString());
            if (variable.HistoricalSize() == 0) mIn.Fail("the historical variable " + variable.Name() + " has a kind that cannot be stored historically");
            mVariables.push_back(&variable);
            mHistorySize += variable.HistoricalSize();
        }
    }

    template <class T>
    void SetTyped(DataValueContainer& data, const VariableData& variable, VariableType expected, const T& value) {
        if (variable.Type() != expected) mIn.Fail("the value of " + variable.Name() + " has another kind than the variable");
        data.SetValue(static_cast<const Variable<T>&>(variable), value);
    }

    void ReadData(DataValueContainer& data) {
        const std::size_t count = mIn.GetCount(9);
        for (std::size_t i = 0; i < count; ++i) {
            const VariableData& variable = GetVariable(mIn.GetString());
            switch (mIn.Get<std::uint8_t>()) {
                case 0: SetTyped(data, variable, VariableType::Bool, mIn.Get<std::uint8_t>() != 0); break;
                case 1: SetTyped(data, variable, VariableType::Integer, static_cast<int>(mIn.Get<std::int64_t>())); break;
                case 2: SetTyped(data, variable, VariableType::Double, mIn.Get<double>()); break;
                case 3: SetTyped(data, variable, VariableType::Array, mIn.GetArray3()); break;
                case 4: SetTyped(data, variable, VariableType::Vector, mIn.GetVector()); break;
                case 5: SetTyped(data, variable, VariableType::Matrix, mIn.GetMatrix()); break;
                case 6: SetTyped(data, variable, VariableType::String, mIn.GetString()); break;
                case 7: ReadPointer(data, variable); break;
                default: mIn.Fail("an unknown value kind for " + variable.Name());
            }
        }
    }

    void ReadPointer(DataValueContainer& data, const VariableData& variable) {
        if (variable.Type() != VariableType::Pointer) mIn.Fail(variable.Name() + " is not a pointer variable");
        switch (mIn.Get<std::uint8_t>()) {
            case 0: break;  // a null pointer reads as absent
            case 1: {
                const std::string bytes = mIn.GetString();
                const RestartPointerCodec* codec = FindRestartPointerCodec(variable.Name());
                if (codec == nullptr) mIn.Fail("no codec is registered for the pointer variable " + variable.Name());
                codec->load(data, bytes);
                break;
            }
            case 2: mPending.push_back({&data, &variable, mIn.GetCount(0)}); break;
            case 3: {
                const std::string name = mIn.GetString();
                if (!Registry<ConstitutiveLaw>::Instance().Has(name)) mIn.Fail("unknown constitutive law " + name);
                data.SetValue(CONSTITUTIVE_LAW, Registry<ConstitutiveLaw>::Instance().Get(name).Clone());
                break;
            }
            default: mIn.Fail("an unknown pointer kind for " + variable.Name());
        }
    }

    std::shared_ptr<Table> ReadTable() {
        const std::string input = mIn.GetString();
        const std::string output = mIn.GetString();
        auto table = std::make_shared<Table>(input, output);
        const std::size_t rows = mIn.GetCount(16);
        for (std::size_t row = 0; row < rows; ++row) {
            const double x = mIn.Get<double>();
            table->PushBack(x, mIn.Get<double>());
        }
        return table;
    }

    void ReadProperties() {
        mIn.Section("PROP");
        const std::size_t count = mIn.GetCount(24);
        for (std::size_t i = 0; i < count; ++i) {
            auto properties = std::make_shared<Properties>(mIn.GetCount(0));
            ReadData(properties->Data());
            const std::size_t tables = mIn.GetCount(16);
            for (std::size_t t = 0; t < tables; ++t) {
                const VariableData& input = GetVariable(mIn.GetString());
                const VariableData& output = GetVariable(mIn.GetString());
                properties->SetTable(input, output, *ReadTable());
            }
            if (!mProperties.emplace(properties->Id(), properties).second)
                mIn.Fail("properties " + std::to_string(properties->Id()) + " stored twice");
        }
    }

    void ReadNodes() {
        mIn.Section("NODE");
        const std::size_t count = mIn.GetCount(64);
        for (std::size_t i = 0; i < count; ++i) {
            const IndexType id = mIn.GetCount(0);
            const Array3 initial = mIn.GetArray3();
            const Array3 current = mIn.GetArray3();
            NodeRecord record{std::make_shared<Node>(id, current[0], current[1], current[2]), {}, {}};
            record.node->InitialCoordinates() = initial;
            static_cast<Flags&>(*record.node) = mIn.GetFlags();
            ReadData(record.node->Data());
            record.history.resize(mBufferSize * mHistorySize);
            mIn.GetDoubles(record.history.data(), record.history.size());
            const std::size_t dofs = mIn.GetCount(25);
            for (std::size_t d = 0; d < dofs; ++d) {
                const Variable<double>& variable = GetDoubleVariable(mIn.GetString());
                const std::string reaction = mIn.GetString();
                DofRecord dof{&variable, reaction.empty() ? nullptr : &GetDoubleVariable(reaction), false, 0};
                if (!HasHistorical(variable)) mIn.Fail("node " + std::to_string(id) + " has a DoF of " + variable.Name() + ", which is not historical");
                dof.fixed = mIn.Get<std::uint8_t>() != 0;
                dof.equation_id = mIn.GetCount(0);
                record.dofs.push_back(dof);
            }
            if (!mNodes.emplace(id, std::move(record)).second) mIn.Fail("node " + std::to_string(id) + " stored twice");
        }
    }

    bool HasHistorical(const VariableData& variable) const {
        const VariableData& source = variable.IsComponent() ? *variable.SourceVariable() : variable;
        for (const VariableData* stored : mVariables)
            if (*stored == source) return true;
        return false;
    }

    Node::Pointer GetNode(IndexType id) {
        const auto found = mNodes.find(id);
        if (found == mNodes.end()) mIn.Fail("a reference to node " + std::to_string(id) + ", which is not stored");
        return found->second.node;
    }

    void ReadGeometries() {
        mIn.Section("GEOM");
        const std::size_t count = mIn.GetCount(16);
        for (std::size_t i = 0; i < count; ++i) {
            const std::string name = mIn.GetString();
            if (name == "CouplingGeometry") {
                const std::size_t slave = mIn.GetCount(0), master = mIn.GetCount(0);
                if (slave >= mGeometries.size() || master >= mGeometries.size()) mIn.Fail("a coupling geometry with a missing part");
                mGeometries.push_back(std::make_shared<CouplingGeometry>(mGeometries[slave], mGeometries[master]));
                continue;
            }
            const std::size_t points = mIn.GetCount(8);
            Geometry::PointsArrayType nodes;
            for (std::size_t p = 0; p < points; ++p) nodes.push_back(GetNode(mIn.GetCount(0)));
            mGeometries.push_back(CreateGeometry(name, std::move(nodes)));
        }
    }

    template <class T>
    void ReadEntities(std::map<IndexType, std::shared_ptr<T>>& entities, const char (&marker)[5]) {
        mIn.Section(marker);
        const std::size_t count = mIn.GetCount(32);
        auto& registry = Registry<T>::Instance();
        for (std::size_t i = 0; i < count; ++i) {
            const std::string name = mIn.GetString();
            if (!registry.Has(name)) mIn.Fail("the " + std::string(marker) + " type \"" + name + "\" is not registered here");
            const std::size_t geometry = mIn.GetCount(0);
            if (geometry >= mGeometries.size()) mIn.Fail("an entity on a missing geometry");
            const bool has_properties = mIn.Get<std::uint8_t>() != 0;
            const IndexType properties_id = mIn.GetCount(0);
            Properties::Pointer properties;
            if (has_properties) {
                const auto found = mProperties.find(properties_id);
                if (found == mProperties.end()) mIn.Fail("a reference to properties " + std::to_string(properties_id) + ", which are not stored");
                properties = found->second;
            }
            auto entity = registry.Get(name).Create(0, mGeometries[geometry], properties);
            ReadData(entity->Data());
            Serializer state(mIn.GetString());
            entity->Load(state);
            if (!state.AtEnd()) mIn.Fail("the state of " + entity->Info() + " is longer than its class reads");
            if (!entities.emplace(entity->Id(), entity).second) mIn.Fail(entity->Info() + " stored twice");
        }
    }

    void ReadConstraints() {
        mIn.Section("CNST");
        const std::size_t count = mIn.GetCount(40);
        mConstraints.resize(count);  // never resized again: mPending points into the records
        for (auto& record : mConstraints) {
            record.name = mIn.GetString();
            if (!Registry<MasterSlaveConstraint>::Instance().Has(record.name)) mIn.Fail("the constraint type \"" + record.name + "\" is not registered here");
            record.id = mIn.GetCount(0);
            record.in_root = mIn.Get<std::uint8_t>() != 0;
            record.flags = mIn.GetFlags();
            ReadData(record.data);
            for (auto* dofs : {&record.slaves, &record.masters}) {
                const std::size_t size = mIn.GetCount(16);
                for (std::size_t d = 0; d < size; ++d) {
                    const IndexType node = mIn.GetCount(0);
                    const Variable<double>& variable = GetDoubleVariable(mIn.GetString());
                    GetNode(node);
                    bool found = false;
                    for (const DofRecord& dof : mNodes.at(node).dofs) found = found || dof.variable == &variable;
                    if (!found) mIn.Fail("constraint " + std::to_string(record.id) + " uses a DoF node " + std::to_string(node) + " does not have");
                    dofs->emplace_back(node, &variable);
                }
            }
            record.relation = mIn.GetMatrix();
            record.constant = mIn.GetVector();
            record.test_relation = mIn.GetMatrix();
            if (record.test_relation.size() > 0 && (record.test_relation.rows() != record.relation.rows() ||
                                                    record.test_relation.cols() != record.relation.cols()))
                mIn.Fail("constraint " + std::to_string(record.id) + " has a test relation of another shape than T");
        }
    }

    template <class TMap>
    void CheckIds(const std::vector<IndexType>& ids, const TMap& stored, const char* kind) {
        for (const IndexType id : ids)
            if (stored.count(id) == 0) mIn.Fail(std::string("a model part lists ") + kind + " " + std::to_string(id) + ", which is not stored");
    }

    void ReadPart(PartRecord& part) {
        part.name = mIn.GetString();
        part.flags = mIn.GetFlags();
        ReadData(part.data);
        auto ids = [&](std::vector<IndexType>& out) {
            out.resize(mIn.GetCount(8));
            for (auto& id : out) id = mIn.GetCount(0);
        };
        ids(part.nodes);
        ids(part.elements);
        ids(part.conditions);
        ids(part.constraints);
        ids(part.properties);
        CheckIds(part.nodes, mNodes, "node");
        CheckIds(part.elements, mElements, "element");
        CheckIds(part.conditions, mConditions, "condition");
        CheckIds(part.properties, mProperties, "properties");
        for (const IndexType id : part.constraints) {
            bool found = false;
            for (const auto& record : mConstraints) found = found || (record.in_root && record.id == id);
            if (!found) mIn.Fail("a model part lists constraint " + std::to_string(id) + ", which is not stored");
        }
        part.geometries.resize(mIn.GetCount(16));
        for (auto& [id, index] : part.geometries) {
            id = mIn.GetCount(0);
            index = mIn.GetCount(0);
            if (index >= mGeometries.size()) mIn.Fail("a model part lists a missing geometry");
        }
        part.tables.resize(mIn.GetCount(24));
        for (auto& [id, table] : part.tables) {
            id = mIn.GetCount(0);
            table = ReadTable();
        }
        const std::size_t children = mIn.GetCount(8);
        for (std::size_t i = 0; i < children; ++i) {
            part.children.push_back(std::make_unique<PartRecord>());
            ReadPart(*part.children.back());
        }
    }

    void InsertNodes(ModelPart& root) {
        std::vector<Node::Pointer> nodes;
        nodes.reserve(mNodes.size());
        for (const auto& [id, record] : mNodes) nodes.push_back(record.node);
        root.AddNodesBulk(std::move(nodes));
        for (auto& [id, record] : mNodes) {
            Node& node = *record.node;
            const double* value = record.history.data();
            for (std::size_t step = 0; step < mBufferSize; ++step) {
                for (const VariableData* variable : mVariables) {
                    if (variable->Type() == VariableType::Array) {
                        node.FastGetSolutionStepValue(static_cast<const Variable<Array3>&>(*variable), step) =
                            Array3(value[0], value[1], value[2]);
                        value += 3;
                    } else {
                        node.FastGetSolutionStepValue(static_cast<const Variable<double>&>(*variable), step) = *value++;
                    }
                }
            }
            for (const DofRecord& record_dof : record.dofs) {
                Dof& dof = node.AddDof(*record_dof.variable, record_dof.reaction);
                if (record_dof.fixed) dof.FixDof();
                else dof.FreeDof();
                dof.SetEquationId(record_dof.equation_id);
            }
        }
    }

    MasterSlaveConstraint::Pointer CreateConstraint(ConstraintRecord& record) {
        auto dofs = [&](const auto& list) {
            DofsVectorType result;
            for (const auto& [node, variable] : list) result.push_back(mNodes.at(node).node->pGetDof(*variable));
            return result;
        };
        const auto& prototype = Registry<MasterSlaveConstraint>::Instance().Get(record.name);
        auto constraint = prototype.Create(record.id, dofs(record.masters), dofs(record.slaves), record.relation, record.constant);
        if (record.test_relation.size() > 0) constraint->SetTestRelation(record.test_relation, ProcessInfo());
        static_cast<Flags&>(*constraint) = record.flags;
        constraint->Data() = record.data;
        // Pending pointers recorded against the record's container now live in the constraint's.
        for (auto& pending : mPending)
            if (pending.container == &record.data) pending.container = &constraint->Data();
        return constraint;
    }

    void FillPart(ModelPart& part, const PartRecord& record) {
        static_cast<Flags&>(part) = record.flags;
        part.Data() = record.data;
        for (auto& pending : mPending)
            if (pending.container == &record.data) pending.container = &part.Data();
        if (part.IsSubModelPart()) {
            part.AddNodes(record.nodes);
            part.AddElements(record.elements);
            part.AddConditions(record.conditions);
            part.AddMasterSlaveConstraints(record.constraints);
            for (const IndexType id : record.properties) part.AddProperties(mProperties.at(id));
        }
        for (const auto& [id, index] : record.geometries) part.AddGeometry(id, mGeometries[index]);
        for (const auto& [id, table] : record.tables) part.AddTable(id, table);
        for (const auto& child : record.children) FillPart(part.CreateSubModelPart(child->name), *child);
    }

    CheckpointReader mIn;
    std::string mName;
    std::size_t mBufferSize = 1;
    std::vector<const VariableData*> mVariables;
    std::size_t mHistorySize = 0;
    Flags mInfoFlags;
    DataValueContainer mInfoData;
    std::map<IndexType, Properties::Pointer> mProperties;
    std::map<IndexType, NodeRecord> mNodes;
    std::vector<Geometry::Pointer> mGeometries;
    std::map<IndexType, Element::Pointer> mElements;
    std::map<IndexType, Condition::Pointer> mConditions;
    std::vector<ConstraintRecord> mConstraints;
    PartRecord mRootPart;
    std::vector<PendingConstraintPointer> mPending;
};

}  // namespace

void ModelPartCheckpoint::Load(ModelPart& model_part, const std::string& bytes, const std::string& source) {
    const Summary summary = Inspect(bytes, source);
    CONTACT_CHECK(!model_part.IsSubModelPart(), InputError, "restart file \"", source, "\": cannot be loaded into ",
                  model_part.FullName(), ", a sub model part\n  fix: load it into the root model part \"",
                  summary.model_part_name, "\"");
    CONTACT_CHECK(model_part.Name() == summary.model_part_name, InputError, "restart file \"", source,
                  "\" holds the model part \"", summary.model_part_name, "\", not \"", model_part.Name(),
                  "\"\n  fix: load it into a model part of that name (solver_settings.model_part_name), or pick the "
                  "checkpoint of this model part");
    const bool empty = model_part.NumberOfNodes() == 0 && model_part.NumberOfElements() == 0 &&
                       model_part.NumberOfConditions() == 0 && model_part.NumberOfMasterSlaveConstraints() == 0 &&
                       model_part.NumberOfSubModelParts() == 0 && model_part.NumberOfProperties() == 0 &&
                       model_part.NumberOfGeometries() == 0 && model_part.NumberOfTables() == 0;
    CONTACT_CHECK(empty, InputError, "restart file \"", source, "\": model part ", model_part.Name(),
                  " is not empty (", model_part.NumberOfNodes(), " nodes, ", model_part.NumberOfSubModelParts(),
                  " sub model parts)\n  fix: load a checkpoint into a freshly created model part (a new Model)");
    Loader loader(bytes, source);
    loader.Decode();
    loader.Insert(model_part);
}

}  // namespace contact_app
