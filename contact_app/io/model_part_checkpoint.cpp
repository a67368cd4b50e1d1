// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/io/model_part_checkpoint.h"

#include <cstring>
#include <map>
#include <set>
#include <typeindex>
#include <unordered_map>
#include <vector>

#include "contact_app/io/checkpoint_stream.h"
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
using detail::CheckpointWriter;

namespace {

constexpr char kMagic[9] = "\x89" "CAREST\n";
// Pointer variables that refer to a master-slave constraint are stored as an index in the constraint table.
const char* const kConstraintPointerVariables[] = {"MASTER_SLAVE_CONSTRAINT", "CONSTRAINT_POINTER"};

bool IsConstraintPointer(const std::string& name) {
    for (const char* candidate : kConstraintPointerVariables)
        if (name == candidate) return true;
    return false;
}

// -- Registered names from instances: the registry maps names to prototypes, the checkpoint needs the reverse. --

std::string GeometryKey(const Geometry& geometry) {
    return geometry.NumberOfGeometryParts() == 2 ? geometry.GetGeometryPart(0).Name() : geometry.Name();
}

template <class T>
std::string RegisteredEntityName(const T& entity) {
    static std::map<std::pair<std::type_index, std::string>, std::string> names;
    static std::size_t registered = 0;
    auto& registry = Registry<T>::Instance();
    const auto all = registry.Names();
    if (all.size() != registered) {
        names.clear();
        for (const auto& name : all) {
            const T& prototype = registry.Get(name);
            names.emplace(std::make_pair(std::type_index(typeid(prototype)), GeometryKey(prototype.GetGeometry())), name);
        }
        registered = all.size();
    }
    const auto found = names.find({std::type_index(typeid(entity)), GeometryKey(entity.GetGeometry())});
    CONTACT_CHECK(found != names.end(), ConfigurationError, "checkpoint: ", entity.Info(),
                  " is of a class that is not registered under any name, so it cannot be re-created on load",
                  "\n  fix: register the class (contact_app.registered_elements()/registered_conditions())");
    return found->second;
}

template <class T>
std::string RegisteredTypeName(const T& object, const char* kind) {
    auto& registry = Registry<T>::Instance();
    for (const auto& name : registry.Names())
        if (typeid(registry.Get(name)) == typeid(object)) return name;
    CONTACT_THROW(ConfigurationError, "checkpoint: a ", kind, " of an unregistered class cannot be stored",
                  "\n  fix: register the class in its registry");
}

// -- Saving --

class Saver {
public:
    explicit Saver(const ModelPart& root) : mRoot(root) {}

    std::string Payload() {
        const ProcessInfo& info = mRoot.GetProcessInfo();
        mOut.Section("HEAD");
        mOut.PutString(mRoot.Name());
        mOut.Put(info.GetValue(TIME));
        mOut.Put(static_cast<std::int64_t>(info.GetValue(STEP)));
        mOut.PutSize(mRoot.GetBufferSize());
        CollectConstraints();
        WriteVariables();
        mOut.Section("PINF");
        mOut.PutFlags(info);
        WriteData(info.Data(), "the ProcessInfo");
        WriteProperties();
        WriteNodes();
        WriteGeometries();
        WriteEntities(mRoot.Elements(), "ELEM");
        WriteEntities(mRoot.Conditions(), "COND");
        WriteConstraints();
        mOut.Section("PART");
        WritePart(mRoot);
        mOut.Section("END!");
        return std::move(mOut.Buffer());
    }

private:
    void CollectConstraints() {
        for (const auto& constraint : mRoot.MasterSlaveConstraints()) AddConstraint(constraint, true);
        // Constraints only reachable through pointer values (contact MPC) are stored as well.
        auto scan = [&](const DataValueContainer& data) {
            for (const auto& [variable, value] : data.Data())
                if (IsConstraintPointer(variable->Name()))
                    if (auto pointer = std::get_if<std::shared_ptr<void>>(&value); pointer && *pointer)
                        AddConstraint(std::static_pointer_cast<MasterSlaveConstraint>(*pointer), false);
        };
        for (const auto& node : mRoot.Nodes()) scan(node->Data());
        for (const auto& element : mRoot.Elements()) scan(element->Data());
        for (const auto& condition : mRoot.Conditions()) scan(condition->Data());
    }

    void AddConstraint(const MasterSlaveConstraint::Pointer& constraint, bool in_root) {
        if (mConstraintIndex.emplace(constraint.get(), mConstraints.size()).second)
            mConstraints.emplace_back(constraint, in_root);
    }

    void WriteVariables() {
        mOut.Section("VARS");
        const auto& list = mRoot.pGetNodalSolutionStepVariablesList();
        mVariables = list ? list->Variables() : std::vector<const VariableData*>{};
        mOut.PutSize(mVariables.size());
        for (const VariableData* variable : mVariables) mOut.PutString(variable->Name());
    }

    void WriteData(const DataValueContainer& data, const std::string& owner) {
        mOut.PutSize(data.Size());
        for (const auto& [key, value] : data.Data()) {
            const auto* variable = key;  // a structured binding cannot be captured before C++20 (clang)
            mOut.PutString(variable->Name());
            mOut.Put(static_cast<std::uint8_t>(value.index()));
            std::visit([&](const auto& v) { WriteValue(*variable, v, owner); }, value);
        }
    }

    void WriteValue(const VariableData&, bool v, const std::string&) { mOut.Put(static_cast<std::uint8_t>(v)); }
    void WriteValue(const VariableData&, int v, const std::string&) { mOut.Put(static_cast<std::int64_t>(v)); }
    void WriteValue(const VariableData&, double v, const std::string&) { mOut.Put(v); }
    void WriteValue(const VariableData&, const Array3& v, const std::string&) { mOut.PutArray3(v); }
    void WriteValue(const VariableData&, const Vector& v, const std::string&) { mOut.PutVector(v); }
    void WriteValue(const VariableData&, const Matrix& v, const std::string&) { mOut.PutMatrix(v); }
    void WriteValue(const VariableData&, const std::string& v, const std::string&) { mOut.PutString(v); }
    void WriteValue(const VariableData& variable, const std::shared_ptr<void>& v, const std::string& owner) {
        if (!v) {
            mOut.Put(std::uint8_t{0});
        } else if (IsConstraintPointer(variable.Name())) {
            mOut.Put(std::uint8_t{2});
            mOut.PutSize(mConstraintIndex.at(v.get()));
        } else if (variable.Name() == "CONSTITUTIVE_LAW") {
            mOut.Put(std::uint8_t{3});
            mOut.PutString(RegisteredTypeName(*std::static_pointer_cast<ConstitutiveLaw>(v), "constitutive law"));
        } else {
            const RestartPointerCodec* codec = FindRestartPointerCodec(variable.Name());
            CONTACT_CHECK(codec != nullptr, ConfigurationError, "checkpoint: ", owner, " holds the pointer variable ",
                          variable.Name(), ", which checkpoints cannot store (no codec registered)",
                          "\n  fix: remove the value before saving, or register a RestartPointerCodec for it");
            mOut.Put(std::uint8_t{1});
            mOut.PutString(codec->save(v));
        }
    }

    void WriteProperties() {
        mOut.Section("PROP");
        const auto& registry = VariableRegistry::Instance();
        mOut.PutSize(mRoot.NumberOfProperties());
        for (const auto& properties : mRoot.PropertiesArray()) {
            mOut.PutSize(properties->Id());
            WriteData(properties->Data(), "properties " + std::to_string(properties->Id()));
            // Properties list no table keys: scan the double variables (only when there are tables).
            std::vector<std::pair<const VariableData*, const VariableData*>> tables;
            if (properties->NumberOfTables() > 0) {
                std::vector<const VariableData*> scalars;
                for (std::size_t key = 0; key < registry.Size(); ++key) {
                    const VariableData& variable = registry.ByKey(key);
                    if (variable.Type() == VariableType::Double || variable.Type() == VariableType::Component)
                        scalars.push_back(&variable);
                }
                for (const VariableData* input : scalars)
                    for (const VariableData* output : scalars)
                        if (properties->HasTable(*input, *output)) tables.emplace_back(input, output);
            }
            mOut.PutSize(tables.size());
            for (const auto& [input, output] : tables) {
                mOut.PutString(input->Name());
                mOut.PutString(output->Name());
                WriteTable(properties->GetTable(*input, *output));
            }
        }
    }

    void WriteTable(const Table& table) {
        mOut.PutString(table.InputVariable());
        mOut.PutString(table.OutputVariable());
        mOut.PutSize(table.Size());
        for (const auto& [x, y] : table.Data()) {
            mOut.Put(x);
            mOut.Put(y);
        }
    }

    void WriteNodes() {
        mOut.Section("NODE");
        const std::size_t buffer = mRoot.GetBufferSize();
        mOut.PutSize(mRoot.NumberOfNodes());
        for (const auto& node : mRoot.Nodes()) {
            mOut.PutSize(node->Id());
            mOut.PutArray3(node->InitialCoordinates());
            mOut.PutArray3(node->Coordinates());
            mOut.PutFlags(*node);
            WriteData(node->Data(), "node " + std::to_string(node->Id()));
            for (std::size_t step = 0; step < buffer; ++step) {
                for (const VariableData* variable : mVariables) {
                    if (variable->Type() == VariableType::Array)
                        mOut.PutArray3(node->FastGetSolutionStepValue(static_cast<const Variable<Array3>&>(*variable), step));
                    else
                        mOut.Put(node->FastGetSolutionStepValue(static_cast<const Variable<double>&>(*variable), step));
                }
            }
            mOut.PutSize(node->GetDofs().size());
            for (const auto& dof : node->GetDofs()) {
                mOut.PutString(dof->GetVariable().Name());
                mOut.PutString(dof->HasReaction() ? dof->GetReaction().Name() : std::string());
                mOut.Put(static_cast<std::uint8_t>(dof->IsFixed()));
                mOut.PutSize(dof->EquationId());
            }
        }
    }

    std::size_t GeometryIndex(const Geometry::Pointer& geometry) {
        const auto found = mGeometryIndex.find(geometry.get());
        if (found != mGeometryIndex.end()) return found->second;
        // Parts first, so that the reader always finds them already built.
        if (geometry->NumberOfGeometryParts() == 2) {
            GeometryIndex(geometry->pGetGeometryPart(0));
            GeometryIndex(geometry->pGetGeometryPart(1));
        }
        mGeometryIndex.emplace(geometry.get(), mGeometries.size());
        mGeometries.push_back(geometry);
        return mGeometries.size() - 1;
    }

    void WriteGeometries() {
        for (const auto& [id, geometry] : mRoot.Geometries()) GeometryIndex(geometry);
        for (const auto& element : mRoot.Elements()) GeometryIndex(element->pGetGeometry());
        for (const auto& condition : mRoot.Conditions()) GeometryIndex(condition->pGetGeometry());
        mOut.Section("GEOM");
        mOut.PutSize(mGeometries.size());
        for (const auto& geometry : mGeometries) {
            if (geometry->NumberOfGeometryParts() == 2) {
                mOut.PutString("CouplingGeometry");
                mOut.PutSize(mGeometryIndex.at(geometry->pGetGeometryPart(0).get()));
                mOut.PutSize(mGeometryIndex.at(geometry->pGetGeometryPart(1).get()));
                continue;
            }
            mOut.PutString(geometry->Name());
            mOut.PutSize(geometry->PointsNumber());
            for (const auto& point : geometry->Points()) mOut.PutSize(point->Id());
        }
    }

    template <class TContainer>
    void WriteEntities(const TContainer& entities, const char (&marker)[5]) {
        mOut.Section(marker);
        mOut.PutSize(entities.size());
        for (const auto& entity : entities) {
            mOut.PutString(RegisteredEntityName(*entity));
            mOut.PutSize(mGeometryIndex.at(entity->pGetGeometry().get()));
            const auto& properties = entity->pGetProperties();
            mOut.Put(static_cast<std::uint8_t>(properties != nullptr));
            mOut.PutSize(properties ? properties->Id() : 0);
            WriteData(entity->Data(), entity->Info());
            Serializer state;
            entity->Save(state);
            mOut.PutString(state.Data());
        }
    }

    void WriteConstraints() {
        mOut.Section("CNST");
        mOut.PutSize(mConstraints.size());
        ProcessInfo& info = const_cast<ModelPart&>(mRoot).GetProcessInfo();
        for (const auto& [constraint, in_root] : mConstraints) {
            mOut.PutString(RegisteredTypeName(*constraint, "master-slave constraint"));
            mOut.PutSize(constraint->Id());
            mOut.Put(static_cast<std::uint8_t>(in_root));
            mOut.PutFlags(*constraint);
            WriteData(constraint->Data(), constraint->Info());
            for (const DofsVectorType* dofs : {&constraint->GetSlaveDofsVector(), &constraint->GetMasterDofsVector()}) {
                mOut.PutSize(dofs->size());
                for (const Dof* dof : *dofs) {
                    mOut.PutSize(dof->Id());
                    mOut.PutString(dof->GetVariable().Name());
                }
            }
            Matrix relation;
            Vector constant;
            constraint->CalculateLocalSystem(relation, constant, info);
            mOut.PutMatrix(relation);
            mOut.PutVector(constant);
            // The test relation W of a slipping MPC node (Coulomb force) outlives the step: BLOCKED pairs keep it.
            Matrix test;
            mOut.PutMatrix(constraint->CalculateTestRelation(test, info) ? test : Matrix(0, 0));
        }
    }

    void WritePart(const ModelPart& part) {
        mOut.PutString(part.Name());
        mOut.PutFlags(part);
        WriteData(part.Data(), "model part " + part.FullName());
        auto ids = [&](const auto& container) {
            mOut.PutSize(container.size());
            for (const auto& entity : container) mOut.PutSize(entity->Id());
        };
        ids(part.Nodes());
        ids(part.Elements());
        ids(part.Conditions());
        ids(part.MasterSlaveConstraints());
        ids(part.PropertiesArray());
        mOut.PutSize(part.Geometries().size());
        for (const auto& [id, geometry] : part.Geometries()) {
            mOut.PutSize(id);
            mOut.PutSize(GeometryIndex(geometry));
        }
        WritePartTables(part);
        mOut.PutSize(part.NumberOfSubModelParts());
        for (const ModelPart* child : part.SubModelParts()) WritePart(*child);
    }

    void WritePartTables(const ModelPart& part) {
        // Model parts list no table ids: look for them among the small ids mdpa files use.
        std::vector<IndexType> ids;
        for (IndexType id = 0; ids.size() < part.NumberOfTables() && id < 1000000; ++id)
            if (part.HasTable(id)) ids.push_back(id);
        CONTACT_CHECK(ids.size() == part.NumberOfTables(), ConfigurationError, "checkpoint: model part ",
                      part.FullName(), " has a table with an id of 10^6 or more, which checkpoints cannot store",
                      "\n  fix: number the mdpa tables below 10^6");
        mOut.PutSize(ids.size());
        for (const IndexType id : ids) {
            mOut.PutSize(id);
            WriteTable(part.GetTable(id));
        }
    }

    const ModelPart& mRoot;
    CheckpointWriter mOut;
    std::vector<const VariableData*> mVariables;
    std::vector<Geometry::Pointer> mGeometries;
    std::unordered_map<const Geometry*, std::size_t> mGeometryIndex;
    std::vector<std::pair<MasterSlaveConstraint::Pointer, bool>> mConstraints;
    std::unordered_map<const void*, std::size_t> mConstraintIndex;
};

}  // namespace

std::uint64_t ModelPartCheckpoint::Hash(const char* data, std::size_t size) {
    constexpr std::uint64_t k1 = 0x9E3779B97F4A7C15ull, k2 = 0xC2B2AE3D27D4EB4Full;
    auto mix = [&](std::uint64_t h, std::uint64_t word) {
        h ^= word * k1;
        h = (h << 31) | (h >> 33);
        return h * k2;
    };
    std::uint64_t h = 0x27D4EB2F165667C5ull ^ size;
    std::size_t i = 0;
    for (; i + 8 <= size; i += 8) {
        std::uint64_t word;
        std::memcpy(&word, data + i, 8);
        h = mix(h, word);
    }
    std::uint64_t tail = 0;
    std::memcpy(&tail, data + i, size - i);
    h = mix(h, tail ^ (static_cast<std::uint64_t>(size - i) << 56));
    h ^= h >> 33;
    h *= 0xFF51AFD7ED558CCDull;
    h ^= h >> 33;
    h *= 0xC4CEB9FE1A85EC53ull;
    return h ^ (h >> 33);
}

std::string ModelPartCheckpoint::Save(const ModelPart& model_part) {
    const std::string payload = Saver(model_part.GetRootModelPart()).Payload();
    std::string bytes(kMagic, 8);
    detail::CheckpointWriter header;
    header.Put(kFormatVersion);
    header.Put(static_cast<std::uint32_t>(kHeaderSize));
    header.Put(static_cast<std::uint64_t>(payload.size()));
    header.Put(Hash(payload.data(), payload.size()));
    bytes += header.Buffer();
    bytes += payload;
    return bytes;
}

ModelPartCheckpoint::Summary ModelPartCheckpoint::Inspect(const std::string& bytes, const std::string& source) {
    auto refuse = [&](const std::string& what, const std::string& fix) {
        CONTACT_THROW(InputError, "restart file \"", source, "\": ", what, "\n  fix: ", fix);
    };
    if (bytes.size() < kHeaderSize)
        refuse("only " + std::to_string(bytes.size()) + " bytes, shorter than the 32-byte header (truncated)",
               "load an intact checkpoint: the file was cut while written or copied");
    if (std::memcmp(bytes.data(), kMagic, 8) != 0)
        refuse("not a contact_app checkpoint (the file does not start with the checkpoint magic)",
               "give a .rest file written by contact_app (Kratos' own restart files cannot be read)");
    Summary summary;
    std::memcpy(&summary.version, bytes.data() + 8, 4);
    std::uint32_t header_size = 0;
    std::memcpy(&header_size, bytes.data() + 12, 4);
    std::memcpy(&summary.payload_size, bytes.data() + 16, 8);
    std::memcpy(&summary.checksum, bytes.data() + 24, 8);
    if (summary.version != kFormatVersion || header_size != kHeaderSize)
        refuse("format version " + std::to_string(summary.version) + ", this contact_app reads version " +
                   std::to_string(kFormatVersion),
               "load it with the contact_app version that wrote it, or run again from the mesh");
    const std::size_t actual = bytes.size() - kHeaderSize;
    if (summary.payload_size != actual)
        refuse("the header announces " + std::to_string(summary.payload_size) + " payload bytes but the file holds " +
                   std::to_string(actual) + (actual < summary.payload_size ? " (truncated)" : " (extra bytes)"),
               "load an intact checkpoint: the file was cut or appended to after it was written");
    const std::uint64_t hash = Hash(bytes.data() + kHeaderSize, actual);
    if (hash != summary.checksum)
        refuse("the payload hash does not match the header (the file is corrupt)",
               "load an intact checkpoint (an earlier one of the same run), or run again from the mesh");
    CheckpointReader in(bytes, kHeaderSize, source);
    in.Section("HEAD");
    summary.model_part_name = in.GetString();
    summary.time = in.Get<double>();
    summary.step = in.Get<std::int64_t>();
    return summary;
}

}  // namespace contact_app
