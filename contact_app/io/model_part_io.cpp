// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/io/model_part_io.h"

#include <fstream>
#include <type_traits>
#include <unordered_map>

#include "contact_app/io/mdpa_line_reader.h"
#include "contact_app/io/mdpa_values.h"
#include "contact_app/kernel/constitutive_law.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/face_checks.h"
#include "contact_app/kernel/geometries/geometry_factory.h"
#include "contact_app/kernel/registry.h"
#include "contact_app/kernel/string_utilities.h"
#include "contact_app/kernel/variable_registry.h"
#include "contact_app/kernel/variables.h"

namespace contact_app {

namespace {

const std::vector<std::string> kTopLevelBlocks = {
    "ModelPartData", "Properties", "Table", "Nodes", "Geometries", "Elements", "Conditions", "Constraints",
    "NodalData", "ElementalData", "ConditionalData", "SubModelPart"};
const std::vector<std::string> kSubModelPartBlocks = {
    "SubModelPartData", "SubModelPartTables", "SubModelPartProperties", "SubModelPartNodes",
    "SubModelPartElements", "SubModelPartConditions", "SubModelPartGeometries", "SubModelPartConstraints",
    "SubModelPart"};

/// Reads one file into a root model part; one method per block kind.
class MdpaParser {
public:
    MdpaParser(const std::string& file_name, ModelPart& root) : mReader(file_name), mRoot(root) {}

    void Parse() {
        while (mReader.Next()) {
            const auto& tokens = mReader.Tokens();
            Expect(tokens[0] == "Begin" && tokens.size() >= 2, "expected \"Begin <Block>\", found ", Joined());
            const std::string kind = tokens[1];
            const std::vector<std::string> args(tokens.begin() + 2, tokens.end());
            const std::size_t begin_line = mReader.LineNumber();
            if (kind == "ModelPartData") ReadData(mRoot.Data(), kind);
            else if (kind == "Properties") ReadProperties(args);
            else if (kind == "Table") ReadTable(args);
            else if (kind == "Nodes") ReadNodes();
            else if (kind == "Geometries") ReadGeometries(args);
            else if (kind == "Elements") ReadElements(args);
            else if (kind == "Conditions") ReadConditions(args);
            else if (kind == "Constraints") ReadConstraints(args);
            else if (kind == "NodalData") ReadNodalData(args);
            else if (kind == "ElementalData") ReadEntityData(args, kind, mRoot.Elements());
            else if (kind == "ConditionalData") ReadEntityData(args, kind, mRoot.Conditions());
            else if (kind == "SubModelPart") ReadSubModelPart(mRoot, args);
            else if (kind == "Mesh")
                Fail("legacy \"Mesh\" blocks are not supported\n  fix: describe the subset as a SubModelPart block");
            else
                Fail("unknown block ", mdpa::Quoted("Begin " + kind), "\n  expected: one of ", QuotedList(kTopLevelBlocks),
                     DidYouMean(kind, kTopLevelBlocks));
            (void)begin_line;
        }
        if (mDegenerate.condition) {
            const std::size_t more = mDegenerateCount - 1;
            const std::string others = more == 0   ? ""
                                       : more == 1 ? " (1 more condition of the mesh is degenerate)"
                                                   : " (" + std::to_string(more) + " more conditions of the mesh are degenerate)";
            ThrowDegenerateFace(*mDegenerate.condition, mRoot, mDegenerate.reason + others,
                                mReader.FileName() + ":" + std::to_string(mDegenerate.line) + ": ");
        }
    }

private:
    template <class... TArgs>
    [[noreturn]] void Fail(const TArgs&... message) const {
        throw InputError(mReader.Where() + detail::Concat(message...));
    }
    template <class... TArgs>
    void Expect(bool condition, const TArgs&... message) const {
        if (!condition) Fail(message...);
    }
    /// The current line's words, quoted briefly for a message.
    std::string Joined() const {
        std::string text;
        for (const auto& token : mReader.Tokens()) text += (text.empty() ? "" : " ") + token;
        return mdpa::Quoted(text);
    }
    /// Runs @p action, prefixing any InputError it raises with the current file and line.
    template <class TAction>
    void AtLine(TAction action) const {
        try {
            action();
        } catch (const InputError& error) {
            const std::string what = error.what();
            if (what.rfind(mReader.FileName() + ":", 0) == 0) throw;
            throw InputError(mReader.Where() + what);
        }
    }

    /// A block being read: its kind and the line of its "Begin".
    struct Block {
        std::string kind;
        std::size_t opened;
    };
    Block Open(const std::string& kind) const { return {kind, mReader.LineNumber()}; }

    /// Advances to the next body line of @p block; returns false on its "End <kind>" (checked).
    bool NextBodyLine(const Block& block) {
        const std::string& kind = block.kind;
        const std::size_t opened = block.opened;
        if (!mReader.Next())
            throw InputError(mReader.FileName() + ":" + std::to_string(mReader.LineNumber()) +
                             ": the file ends inside the \"" + kind + "\" block opened at line " +
                             std::to_string(opened) + "\n  expected: \"End " + kind + "\"");
        const auto& tokens = mReader.Tokens();
        if (tokens[0] == "End") {
            Expect(tokens.size() >= 2 && tokens[1] == kind, "expected \"End ", kind, "\", found ", Joined());
            return false;
        }
        return true;
    }

    const VariableData& LookupVariable(const std::string& name) const {
        const VariableData* variable = nullptr;
        AtLine([&] { variable = &VariableRegistry::Instance().Get(name); });
        return *variable;
    }

    /// `VAR value` lines into a data container (ModelPartData, Properties, SubModelPartData).
    void ReadData(DataValueContainer& data, const std::string& kind) {
        const Block block = Open(kind);
        while (NextBodyLine(block)) {
            const auto& tokens = mReader.Tokens();
            if (tokens[0] == "Begin") Fail("a \"Begin ", tokens.size() > 1 ? tokens[1] : "", "\" block cannot be nested in ", kind);
            Expect(tokens.size() >= 2, "variable ", mdpa::Quoted(tokens[0]), " has no value\n  expected: VARIABLE_NAME value");
            const VariableData& variable = LookupVariable(tokens[0]);
            std::string value = tokens[1];
            for (std::size_t i = 2; i < tokens.size(); ++i) value += " " + tokens[i];
            if (variable.Name() == CONSTITUTIVE_LAW.Name()) {
                AtLine([&] {
                    const auto law = Registry<ConstitutiveLaw>::Instance().Get(value).Clone();
                    data.SetValue(CONSTITUTIVE_LAW, law);
                });
                continue;
            }
            Expect(variable.Type() == VariableType::String || tokens.size() == 2, "variable ", mdpa::Quoted(tokens[0]),
                   " expects one value, found ", tokens.size() - 1, " words");
            AtLine([&] { mdpa::SetParsedValue(data, variable, value); });
        }
    }

    void ReadProperties(const std::vector<std::string>& args) {
        Expect(args.size() == 1, "\"Begin Properties\" needs one property id, found ", args.size(), " words");
        IndexType id = 0;
        AtLine([&] { id = mdpa::ParseId(args[0], "property id"); });
        auto properties = mRoot.pGetProperties(id);
        const Block block = Open("Properties");
        while (NextBodyLine(block)) {
            const auto& tokens = mReader.Tokens();
            if (tokens[0] == "Begin") {
                Expect(tokens.size() == 4 && tokens[1] == "Table", "only \"Begin Table <input_variable> <output_variable>\" may be nested in Properties");
                const std::string input = tokens[2], output = tokens[3];
                const VariableData& input_variable = LookupVariable(input);
                const VariableData& output_variable = LookupVariable(output);
                properties->SetTable(input_variable, output_variable, ReadTableRows(input, output));
                continue;
            }
            // Reuse the data reader for this single line.
            Expect(tokens.size() >= 2, "variable ", mdpa::Quoted(tokens[0]), " has no value\n  expected: VARIABLE_NAME value");
            const VariableData& variable = LookupVariable(tokens[0]);
            if (variable.Name() == CONSTITUTIVE_LAW.Name()) {
                AtLine([&] { properties->SetValue(CONSTITUTIVE_LAW, Registry<ConstitutiveLaw>::Instance().Get(tokens[1]).Clone()); });
                continue;
            }
            Expect(variable.Type() == VariableType::String || tokens.size() == 2, "variable ", mdpa::Quoted(tokens[0]),
                   " expects one value, found ", tokens.size() - 1, " words");
            AtLine([&] { mdpa::SetParsedValue(properties->Data(), variable, tokens[1]); });
        }
    }

    Table ReadTableRows(const std::string& input, const std::string& output) {
        Table table(input, output);
        const Block block = Open("Table");
        while (NextBodyLine(block)) {
            const auto& tokens = mReader.Tokens();
            Expect(tokens.size() == 2, "a table row needs two numbers (x y), found ", tokens.size(), " words");
            AtLine([&] { table.PushBack(mdpa::ParseDouble(tokens[0], "table x"), mdpa::ParseDouble(tokens[1], "table y")); });
        }
        return table;
    }

    void ReadTable(const std::vector<std::string>& args) {
        Expect(args.size() == 3, "\"Begin Table\" needs <id> <input_variable> <output_variable>, found ", args.size(), " words");
        IndexType id = 0;
        AtLine([&] { id = mdpa::ParseId(args[0], "table id"); });
        LookupVariable(args[1]);
        LookupVariable(args[2]);
        mRoot.AddTable(id, std::make_shared<Table>(ReadTableRows(args[1], args[2])));
    }

    void ReadNodes() {
        std::vector<Node::Pointer> nodes;
        const Block block = Open("Nodes");
        while (NextBodyLine(block)) {
            const auto& tokens = mReader.Tokens();
            Expect(tokens.size() == 4, "a node line needs 4 values (id x y z), found ", tokens.size());
            AtLine([&] {
                const IndexType id = mdpa::ParseId(tokens[0], "node id");
                CONTACT_CHECK(id >= 1, InputError, "node id 0 is invalid\n  expected: ids start at 1");
                const auto [position, inserted] = mNodeLines.emplace(id, mReader.LineNumber());
                CONTACT_CHECK(inserted, InputError, "node ", id, " is defined twice (first at line ", position->second, ")");
                nodes.push_back(std::make_shared<Node>(id, mdpa::ParseDouble(tokens[1], "coordinate x"),
                                                       mdpa::ParseDouble(tokens[2], "coordinate y"),
                                                       mdpa::ParseDouble(tokens[3], "coordinate z")));
            });
        }
        mRoot.AddNodesBulk(std::move(nodes));
    }

    static void CheckNotZero(IndexType id, const char* what) {
        CONTACT_CHECK(id >= 1, InputError, what, " id 0 is invalid\n  expected: ids start at 1");
    }

    std::vector<Node::Pointer> NodesOf(std::size_t first, const char* what, IndexType id) const {
        const auto& tokens = mReader.Tokens();
        std::vector<Node::Pointer> nodes;
        for (std::size_t i = first; i < tokens.size(); ++i) {
            const IndexType node_id = mdpa::ParseId(tokens[i], "node id");
            auto node = mRoot.Nodes().FindPointer(node_id);
            CONTACT_CHECK(node != nullptr, InputError, what, " ", id, " uses node ", node_id,
                          ", which is not defined\n  fix: define it in a Nodes block before this block");
            nodes.push_back(std::move(node));
        }
        return nodes;
    }

    void ReadGeometries(const std::vector<std::string>& args) {
        Expect(args.size() == 1, "\"Begin Geometries\" needs a geometry name (e.g. Triangle2D3)");
        const std::string name = args[0];
        const Block block = Open("Geometries");
        while (NextBodyLine(block)) {
            AtLine([&] {
                const IndexType id = mdpa::ParseId(mReader.Tokens()[0], "geometry id");
                CheckNotZero(id, "geometry");
                CONTACT_CHECK(!mRoot.HasGeometry(id), InputError, "geometry ", id, " is defined twice");
                mRoot.AddGeometry(id, CreateGeometry(name, NodesOf(1, "geometry", id)));
            });
        }
    }

    /// Elements and Conditions blocks: `id property_id node_ids...`.
    template <class TEntity>
    void ReadEntities(const std::vector<std::string>& args, const std::string& kind, const char* what) {
        Expect(args.size() == 1, "\"Begin ", kind, "\" needs one registered ", what, " name, found ", args.size(), " words");
        const TEntity* prototype = nullptr;
        AtLine([&] { prototype = &Registry<TEntity>::Instance().Get(args[0]); });
        const std::size_t nodes_needed = prototype->GetGeometry().PointsNumber();
        std::vector<typename TEntity::Pointer> entities;
        const Block block = Open(kind);
        while (NextBodyLine(block)) {
            const auto& tokens = mReader.Tokens();
            AtLine([&] {
                const IndexType id = mdpa::ParseId(tokens[0], (std::string(what) + " id").c_str());
                CheckNotZero(id, what);
                CONTACT_CHECK(tokens.size() == nodes_needed + 2, InputError, what, " ", id, " (", args[0], ") needs ",
                              nodes_needed, " node ids after its id and property id, found ",
                              tokens.size() < 2 ? 0 : tokens.size() - 2);
                const IndexType property_id = mdpa::ParseId(tokens[1], "property id");
                entities.push_back(prototype->Create(id, NodesOf(2, what, id), mRoot.pGetProperties(property_id)));
                if constexpr (std::is_same_v<TEntity, Condition>) RecordIfDegenerate(entities.back());
            });
        }
        AtLine([&] { AddBulk(std::move(entities)); });
    }
    void AddBulk(std::vector<Element::Pointer> elements) {
        for (const auto& element : elements)
            CONTACT_CHECK(!mRoot.HasElement(element->Id()), InputError, "element ", element->Id(), " is defined twice");
        mRoot.AddElementsBulk(std::move(elements));
    }
    void AddBulk(std::vector<Condition::Pointer> conditions) {
        for (const auto& condition : conditions)
            CONTACT_CHECK(!mRoot.HasCondition(condition->Id()), InputError, "condition ", condition->Id(), " is defined twice");
        mRoot.AddConditionsBulk(std::move(conditions));
    }
    /// Degenerate faces are reported after the whole file is read, when the model parts that hold
    /// them are known; the first one is kept with its line.
    void RecordIfDegenerate(const Condition::Pointer& condition) {
        std::string reason = DegenerateFaceReason(condition->GetGeometry());
        if (reason.empty()) return;
        if (mDegenerateCount++ == 0) mDegenerate = {condition, mReader.LineNumber(), std::move(reason)};
    }
    void ReadElements(const std::vector<std::string>& args) { ReadEntities<Element>(args, "Elements", "element"); }
    void ReadConditions(const std::vector<std::string>& args) { ReadEntities<Condition>(args, "Conditions", "condition"); }

    /// `Begin Constraints <Name> <VAR> [<MASTER_VAR>]`, rows `id constant [weights] slave_id master_ids...`.
    void ReadConstraints(const std::vector<std::string>& args) {
        Expect(args.size() == 2 || args.size() == 3,
               "\"Begin Constraints\" needs <ConstraintName> <SLAVE_VARIABLE> [<MASTER_VARIABLE>]");
        const auto& registry = VariableRegistry::Instance();
        const Variable<double>* slave_variable = nullptr;
        const Variable<double>* master_variable = nullptr;
        AtLine([&] {
            Registry<MasterSlaveConstraint>::Instance().Get(args[0]);
            slave_variable = &registry.GetTyped<double>(args[1]);
            master_variable = args.size() == 3 ? &registry.GetTyped<double>(args[2]) : slave_variable;
        });
        const Block block = Open("Constraints");
        while (NextBodyLine(block)) {
            const auto& tokens = mReader.Tokens();
            AtLine([&] {
                CONTACT_CHECK(tokens.size() >= 5, InputError, "a constraint line needs: id constant [weights] slave_node master_nodes...");
                const IndexType id = mdpa::ParseId(tokens[0], "constraint id");
                Vector constant(1);
                constant[0] = mdpa::ParseDouble(tokens[1], "constraint constant");
                const Vector weights = mdpa::ParseVector(tokens[2]);
                const auto count = static_cast<std::size_t>(weights.size());
                CONTACT_CHECK(tokens.size() == 4 + count, InputError, "constraint ", id, " has ", count,
                              " weights, so it needs 1 slave and ", count, " master node ids, found ", tokens.size() - 3);
                const auto nodes = NodesOf(3, "constraint", id);
                DofsVectorType master_dofs;
                for (std::size_t i = 1; i < nodes.size(); ++i) master_dofs.push_back(&nodes[i]->AddDof(*master_variable));
                DofsVectorType slave_dofs{&nodes[0]->AddDof(*slave_variable)};
                mRoot.CreateNewMasterSlaveConstraint(args[0], id, master_dofs, slave_dofs, weights.transpose(), constant);
            });
        }
    }

    void ReadNodalData(const std::vector<std::string>& args) {
        Expect(args.size() == 1, "\"Begin NodalData\" needs one variable or flag name");
        const std::string& name = args[0];
        const bool is_flag = !VariableRegistry::Instance().Has(name);
        Flags flag;
        const VariableData* variable = nullptr;
        if (is_flag) {
            AtLine([&] {
                try {
                    flag = GetFlag(name);
                } catch (const InputError&) {
                    VariableRegistry::Instance().Get(name);  // reports the unknown variable, with suggestions
                }
            });
        } else {
            variable = &LookupVariable(name);
        }
        const Block block = Open("NodalData");
        while (NextBodyLine(block)) {
            const auto& tokens = mReader.Tokens();
            AtLine([&] {
                const IndexType node_id = mdpa::ParseId(tokens[0], "node id");
                Node* found = mRoot.Nodes().Find(node_id);
                CONTACT_CHECK(found != nullptr, InputError, "NodalData ", name, " refers to node ", node_id,
                              ", which is not defined");
                Node& node = *found;
                if (is_flag) {
                    // "id" or "id value" or "id fixed value": the last word is the value.
                    node.Set(flag, tokens.size() == 1 || mdpa::ParseBool(tokens.back(), "flag value"));
                    return;
                }
                CONTACT_CHECK(tokens.size() == 3, InputError, "a NodalData line needs: node_id is_fixed value, found ",
                              tokens.size(), " words");
                const bool fixed = mdpa::ParseBool(tokens[1], "fixity flag (0 or 1)");
                SetNodalValue(node, *variable, tokens[2], fixed);
            });
        }
    }

    void SetNodalValue(Node& node, const VariableData& variable, const std::string& value, bool fixed) {
        CONTACT_CHECK(node.SolutionStepsDataHas(variable), InputError, "NodalData ", variable.Name(),
                      " needs a solution-step variable, but ",
                      variable.IsComponent() ? variable.SourceVariable()->Name() : variable.Name(),
                      " is not one in model part ", mRoot.Name(),
                      "\n  fix: call AddNodalSolutionStepVariable before reading the mesh (the solver does it)");
        if (variable.Type() == VariableType::Array) {
            const auto& array_variable = static_cast<const Variable<Array3>&>(variable);
            node.FastGetSolutionStepValue(array_variable) = mdpa::ParseArray3(value);
            return;
        }
        CONTACT_CHECK(variable.Type() == VariableType::Double || variable.Type() == VariableType::Component,
                      InputError, "NodalData ", variable.Name(), " is of type ", VariableTypeName(variable.Type()),
                      "\n  expected: a real or 3-vector variable");
        const auto& scalar = static_cast<const Variable<double>&>(variable);
        node.FastGetSolutionStepValue(scalar) = mdpa::ParseDouble(value, "nodal value");
        if (fixed) node.Fix(scalar);
    }

    template <class TContainer>
    void ReadEntityData(const std::vector<std::string>& args, const std::string& kind, const TContainer& entities) {
        Expect(args.size() == 1, "\"Begin ", kind, "\" needs one variable name");
        const VariableData& variable = LookupVariable(args[0]);
        const Block block = Open(kind);
        while (NextBodyLine(block)) {
            const auto& tokens = mReader.Tokens();
            AtLine([&] {
                CONTACT_CHECK(tokens.size() == 2, InputError, "a ", kind, " line needs: id value, found ", tokens.size(), " words");
                const IndexType id = mdpa::ParseId(tokens[0], "entity id");
                auto* entity = entities.Find(id);
                CONTACT_CHECK(entity != nullptr, InputError, kind, " refers to ", kind == "ElementalData" ? "element " : "condition ",
                              id, ", which is not defined");
                mdpa::SetParsedValue(entity->Data(), variable, tokens[1]);
            });
        }
    }

    std::vector<IndexType> ReadIdList(const std::string& kind) {
        std::vector<IndexType> ids;
        const Block block = Open(kind);
        while (NextBodyLine(block))
            for (const auto& token : mReader.Tokens()) AtLine([&] { ids.push_back(mdpa::ParseId(token, "id")); });
        return ids;
    }

    void ReadSubModelPart(ModelPart& parent, const std::vector<std::string>& args) {
        Expect(args.size() == 1, "\"Begin SubModelPart\" needs one name (without spaces or dots)");
        ModelPart* part = nullptr;
        AtLine([&] { part = &parent.CreateSubModelPart(args[0]); });
        const Block block = Open("SubModelPart");
        while (NextBodyLine(block)) {
            const auto& tokens = mReader.Tokens();
            Expect(tokens[0] == "Begin" && tokens.size() >= 2, "expected a \"Begin SubModelPart...\" block inside SubModelPart ",
                   args[0], ", found ", Joined());
            const std::string kind = tokens[1];
            const std::vector<std::string> nested(tokens.begin() + 2, tokens.end());
            if (kind == "SubModelPart") {
                ReadSubModelPart(*part, nested);
                continue;
            }
            if (kind == "SubModelPartData") {
                ReadData(part->Data(), kind);
                continue;
            }
            Expect(std::find(kSubModelPartBlocks.begin(), kSubModelPartBlocks.end(), kind) != kSubModelPartBlocks.end(),
                   "unknown block ", mdpa::Quoted("Begin " + kind), " inside SubModelPart ", args[0], "\n  expected: one of ",
                   QuotedList(kSubModelPartBlocks), DidYouMean(kind, kSubModelPartBlocks));
            const auto ids = ReadIdList(kind);
            AtLine([&] {
                if (kind == "SubModelPartNodes") part->AddNodes(ids);
                else if (kind == "SubModelPartElements") part->AddElements(ids);
                else if (kind == "SubModelPartConditions") part->AddConditions(ids);
                else if (kind == "SubModelPartGeometries") part->AddGeometries(ids);
                else if (kind == "SubModelPartConstraints") part->AddMasterSlaveConstraints(ids);
                else if (kind == "SubModelPartProperties")
                    for (const IndexType id : ids) part->AddProperties(mRoot.pGetProperties(id));
                else if (kind == "SubModelPartTables")
                    for (const IndexType id : ids) part->AddTable(id, mRoot.GetRootModelPart().pGetTable(id));
            });
        }
    }

    MdpaLineReader mReader;
    ModelPart& mRoot;
    std::unordered_map<IndexType, std::size_t> mNodeLines;
    struct DegenerateFace {
        Condition::Pointer condition;
        std::size_t line = 0;
        std::string reason;
    };
    DegenerateFace mDegenerate;
    std::size_t mDegenerateCount = 0;
};

}  // namespace

ModelPartIO::ModelPartIO(std::string filename) : mFileName(std::move(filename)) {
    const bool has_extension = mFileName.size() > 5 && mFileName.compare(mFileName.size() - 5, 5, ".mdpa") == 0;
    if (!has_extension) mFileName += ".mdpa";
}

void ModelPartIO::ReadModelPart(ModelPart& rModelPart) {
    MdpaParser parser(mFileName, rModelPart);
    parser.Parse();
}

}  // namespace contact_app
