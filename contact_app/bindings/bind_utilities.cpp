// SPDX-License-Identifier: BSD-3-Clause
#include <pybind11/numpy.h>

#include <tuple>
#include <unordered_map>
#include <utility>

#include "contact_app/bindings/binding_helpers.h"
#include "contact_app/bindings/bindings.h"
#include "contact_app/kernel/model_part.h"
#include "contact_app/kernel/node.h"
#include "contact_app/kernel/variables.h"

namespace contact_app::bindings {

namespace {

/// Stateless holder of nodal helpers (Kratos VariableUtils).
struct VariableUtils {};

/// VariableUtils.SetFlag over a model part container (mp.Nodes, ...), looped in C++: over a Python iterable each
/// entity costs a cast (0.27 ms for 100 nodes against 0.6 µs), and the contact processes call it every step.
template <class T>
auto SetFlagOnContainer() {
    return [](const VariableUtils&, const Flags& flag, bool value, const ContainerView<T>& view) {
        for (const auto& entity : *view.container) entity->Set(flag, value);
    };
}


// -- bulk arrays for the VTK output (one call per variable instead of one per node) --

/// Values as rows of doubles: scalars one, Array3 three, a Vector its length, a Matrix row by row.
void AppendRow(std::vector<double>& row, double value) { row.push_back(value); }
void AppendRow(std::vector<double>& row, const Array3& value) { row.insert(row.end(), value.data(), value.data() + 3); }
void AppendRow(std::vector<double>& row, const Vector& value) {
    row.insert(row.end(), value.data(), value.data() + value.size());
}
void AppendRow(std::vector<double>& row, const Matrix& value) {
    for (Eigen::Index i = 0; i < value.rows(); ++i)
        for (Eigen::Index j = 0; j < value.cols(); ++j) row.push_back(value(i, j));
}

/// Calls @p function with @p variable as its typed Variable<T> (T: bool, int, double, Array3, Vector, Matrix).
template <class F>
void WithTyped(const VariableData& variable, F&& function) {
    if (const auto* v = dynamic_cast<const Variable<double>*>(&variable)) return function(*v);
    if (const auto* v = dynamic_cast<const Variable<Array3>*>(&variable)) return function(*v);
    if (const auto* v = dynamic_cast<const Variable<int>*>(&variable)) return function(*v);
    if (const auto* v = dynamic_cast<const Variable<bool>*>(&variable)) return function(*v);
    if (const auto* v = dynamic_cast<const Variable<Vector>*>(&variable)) return function(*v);
    if (const auto* v = dynamic_cast<const Variable<Matrix>*>(&variable)) return function(*v);
    ThrowNotConvertible(variable);
}

/// (values, sizes): the rows padded with zeros to the widest, as an (n, width) float64 array, and each row's length.
std::pair<py::array_t<double>, py::array_t<std::int64_t>> PaddedRows(const std::vector<std::vector<double>>& rows) {
    std::size_t width = 0;
    for (const auto& row : rows) width = std::max(width, row.size());
    py::array_t<double> values({rows.size(), width});
    py::array_t<std::int64_t> sizes(static_cast<py::ssize_t>(rows.size()));
    auto v = values.mutable_unchecked<2>();
    auto s = sizes.mutable_unchecked<1>();
    for (std::size_t i = 0; i < rows.size(); ++i) {
        s(i) = static_cast<std::int64_t>(rows[i].size());
        for (std::size_t j = 0; j < width; ++j) v(i, j) = j < rows[i].size() ? rows[i][j] : 0.0;
    }
    return {values, sizes};
}

/// The nodes of @p ids, looked up in @p part (InputError for an id that is not there).
std::vector<const Node*> NodesById(const ModelPart& part, const py::array_t<std::int64_t>& ids) {
    std::unordered_map<IndexType, const Node*> by_id;
    by_id.reserve(part.NumberOfNodes());
    for (const auto& node : part.Nodes()) by_id.emplace(node->Id(), node.get());
    auto view = ids.unchecked<1>();
    std::vector<const Node*> nodes(static_cast<std::size_t>(view.shape(0)));
    for (py::ssize_t i = 0; i < view.shape(0); ++i) {
        auto found = by_id.find(static_cast<IndexType>(view(i)));
        CONTACT_CHECK(found != by_id.end(), InputError, "node ", view(i), " is not in model part \"", part.FullName(),
                      "\"");
        nodes[static_cast<std::size_t>(i)] = found->second;
    }
    return nodes;
}

/// The elements (or conditions) of @p part as a list of entity pointers.
template <class TFunction>
void ForEachEntity(const ModelPart& part, bool elements, TFunction&& function) {
    if (elements)
        for (const auto& element : part.Elements()) function(*element);
    else
        for (const auto& condition : part.Conditions()) function(*condition);
}

std::size_t EntityCount(const ModelPart& part, bool elements) {
    return elements ? part.NumberOfElements() : part.NumberOfConditions();
}

void BindBulkArrays(py::module_& m) {
    m.def(
        "BulkNodeIds",
        [](const ModelPart& part) {
            py::array_t<std::int64_t> ids(static_cast<py::ssize_t>(part.NumberOfNodes()));
            auto view = ids.mutable_unchecked<1>();
            py::ssize_t i = 0;
            for (const auto& node : part.Nodes()) view(i++) = static_cast<std::int64_t>(node->Id());
            return ids;
        },
        py::arg("model_part"), "Ids of the nodes of model_part in their order, as an int64 array.");
    m.def(
        "BulkEntities",
        [](const ModelPart& part, bool elements) {
            const std::size_t count = EntityCount(part, elements);
            py::array_t<std::int64_t> ids(static_cast<py::ssize_t>(count));
            py::array_t<std::int64_t> offsets(static_cast<py::ssize_t>(count + 1));
            py::array_t<std::int64_t> geometry(static_cast<py::ssize_t>(count));
            std::vector<std::int64_t> connectivity;
            std::vector<std::string> names;
            std::unordered_map<std::string, std::int64_t> codes;
            auto id = ids.mutable_unchecked<1>();
            auto offset = offsets.mutable_unchecked<1>();
            auto code = geometry.mutable_unchecked<1>();
            py::ssize_t i = 0;
            offset(0) = 0;
            ForEachEntity(part, elements, [&](const auto& entity) {
                const Geometry& shape = entity.GetGeometry();
                auto [found, added] = codes.emplace(shape.Name(), static_cast<std::int64_t>(names.size()));
                if (added) names.push_back(shape.Name());
                id(i) = static_cast<std::int64_t>(entity.Id());
                code(i) = found->second;
                for (std::size_t k = 0; k < shape.size(); ++k)
                    connectivity.push_back(static_cast<std::int64_t>(shape[k].Id()));
                offset(++i) = static_cast<std::int64_t>(connectivity.size());
            });
            return py::make_tuple(ids, geometry, names, py::array_t<std::int64_t>(connectivity.size(), connectivity.data()),
                                  offsets);
        },
        py::arg("model_part"), py::arg("elements"),
        "(ids, geometry codes, geometry names, node ids, offsets) of the elements (or conditions) of model_part: "
        "entity e has geometry names[codes[e]] and the nodes node_ids[offsets[e]:offsets[e + 1]].");
    m.def(
        "BulkNodalValues",
        [](const ModelPart& part, const py::array_t<std::int64_t>& ids, const VariableData& variable,
           bool historical) {
            const auto nodes = NodesById(part, ids);
            std::vector<std::vector<double>> rows(nodes.size());
            WithTyped(variable, [&](const auto& typed) {
                using T = typename std::decay_t<decltype(typed)>::ValueType;
                for (std::size_t i = 0; i < nodes.size(); ++i) {
                    if constexpr (std::is_same_v<T, double> || std::is_same_v<T, Array3>) {
                        if (historical) {
                            AppendRow(rows[i], const_cast<Node*>(nodes[i])->GetSolutionStepValue(typed, 0));
                            continue;
                        }
                    } else if (historical) {
                        ThrowNotConvertible(variable);
                    }
                    if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, int>)
                        AppendRow(rows[i], static_cast<double>(nodes[i]->GetValue(typed)));
                    else
                        AppendRow(rows[i], nodes[i]->GetValue(typed));
                }
            });
            return PaddedRows(rows);
        },
        py::arg("model_part"), py::arg("ids"), py::arg("variable"), py::arg("historical"),
        "(values, sizes) of variable on the nodes ids of model_part (historical: buffer step 0, else the "
        "non-historical value): rows padded with zeros to the widest, and each row's length.");
    m.def(
        "BulkNodalFlags",
        [](const ModelPart& part, const py::array_t<std::int64_t>& ids, const Flags& flag) {
            const auto nodes = NodesById(part, ids);
            py::array_t<double> values(static_cast<py::ssize_t>(nodes.size()));
            auto view = values.mutable_unchecked<1>();
            for (std::size_t i = 0; i < nodes.size(); ++i) view(i) = nodes[i]->Is(flag) ? 1.0 : 0.0;
            return values;
        },
        py::arg("model_part"), py::arg("ids"), py::arg("flag"), "1.0 where the node is flag, else 0.0.");
    m.def(
        "BulkNodalCoordinates",
        [](const ModelPart& part, const py::array_t<std::int64_t>& ids, bool initial) {
            const auto nodes = NodesById(part, ids);
            py::array_t<double> values({nodes.size(), std::size_t{3}});
            auto view = values.mutable_unchecked<2>();
            for (std::size_t i = 0; i < nodes.size(); ++i) {
                const Array3& x = initial ? nodes[i]->InitialCoordinates() : nodes[i]->Coordinates();
                for (int j = 0; j < 3; ++j) view(i, j) = x[j];
            }
            return values;
        },
        py::arg("model_part"), py::arg("ids"), py::arg("initial"), "(n, 3) initial or current coordinates.");
    m.def(
        "BulkEntityValues",
        [](const ModelPart& part, bool elements, const VariableData& variable) {
            std::vector<std::vector<double>> rows;
            rows.reserve(EntityCount(part, elements));
            WithTyped(variable, [&](const auto& typed) {
                using T = typename std::decay_t<decltype(typed)>::ValueType;
                ForEachEntity(part, elements, [&](const auto& entity) {
                    rows.emplace_back();
                    if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, int>)
                        AppendRow(rows.back(), static_cast<double>(entity.GetValue(typed)));
                    else
                        AppendRow(rows.back(), entity.GetValue(typed));
                });
            });
            return PaddedRows(rows);
        },
        py::arg("model_part"), py::arg("elements"), py::arg("variable"),
        "(values, sizes) of the non-historical variable on the elements (or conditions) of model_part.");
    m.def(
        "BulkEntityFlags",
        [](const ModelPart& part, bool elements, const Flags& flag) {
            py::array_t<double> values(static_cast<py::ssize_t>(EntityCount(part, elements)));
            auto view = values.mutable_unchecked<1>();
            py::ssize_t i = 0;
            ForEachEntity(part, elements, [&](const auto& entity) { view(i++) = entity.Is(flag) ? 1.0 : 0.0; });
            return values;
        },
        py::arg("model_part"), py::arg("elements"), py::arg("flag"), "1.0 where the entity is flag, else 0.0.");
    m.def(
        "BulkIntegrationPointValues",
        [](ModelPart& part, bool elements, const VariableData& variable, const ProcessInfo& info) {
            std::vector<std::vector<double>> rows;  // every point of an entity, one after the other
            std::vector<std::int64_t> points;
            rows.reserve(EntityCount(part, elements));
            auto collect = [&](const auto& typed) {
                using T = typename std::decay_t<decltype(typed)>::ValueType;
                ForEachEntity(part, elements, [&](const auto& entity) {
                    std::vector<T> output;
                    const_cast<std::decay_t<decltype(entity)>&>(entity).CalculateOnIntegrationPoints(typed, output, info);
                    points.push_back(static_cast<std::int64_t>(output.size()));
                    rows.emplace_back();
                    for (const T& value : output) AppendRow(rows.back(), value);
                });
            };
            if (const auto* v = dynamic_cast<const Variable<double>*>(&variable)) collect(*v);
            else if (const auto* v = dynamic_cast<const Variable<Array3>*>(&variable)) collect(*v);
            else if (const auto* v = dynamic_cast<const Variable<Vector>*>(&variable)) collect(*v);
            else if (const auto* v = dynamic_cast<const Variable<Matrix>*>(&variable)) collect(*v);
            else ThrowNotConvertible(variable);
            auto [values, sizes] = PaddedRows(rows);
            return std::make_tuple(values, sizes, py::array_t<std::int64_t>(points.size(), points.data()));
        },
        py::arg("model_part"), py::arg("elements"), py::arg("variable"), py::arg("process_info"),
        "(values, sizes, points): per element (or condition) of model_part the values of variable at its integration "
        "points one after the other (padded with zeros to the widest row), the row's length and the number of points.");
}

}  // namespace

void BindUtilities(py::module_& m) {
    BindBulkArrays(m);
    py::class_<VariableUtils>(m, "VariableUtils", "Nodal helpers (Kratos VariableUtils).")
        .def(py::init<>(), "The helpers.")
        .def(
            "UpdateCurrentPosition",
            [](const VariableUtils&, py::iterable nodes, const Variable<Array3>& variable, std::size_t step) {
                for (py::handle item : nodes) {
                    Node& node = item.cast<Node&>();
                    node.Coordinates() = node.InitialCoordinates() + node.GetSolutionStepValue(variable, step);
                }
            },
            py::arg("nodes"), py::arg_v("variable", VariableObject(DISPLACEMENT), "DISPLACEMENT"),
            py::arg("buffer_step") = 0,
            "Current coordinates = initial + historical variable (DISPLACEMENT) for every node of the iterable.")
        .def("SetFlag", SetFlagOnContainer<Node>(), py::arg("flag"), py::arg("value"), py::arg("entities"),
             "Sets flag to value on every node of a model part's Nodes (looped in C++).")
        .def("SetFlag", SetFlagOnContainer<Condition>(), py::arg("flag"), py::arg("value"), py::arg("entities"),
             "Sets flag to value on every condition of a model part's Conditions (looped in C++).")
        .def("SetFlag", SetFlagOnContainer<Element>(), py::arg("flag"), py::arg("value"), py::arg("entities"),
             "Sets flag to value on every element of a model part's Elements (looped in C++).")
        .def(
            "SetFlag",
            [](const VariableUtils&, const Flags& flag, bool value, py::iterable entities) {
                for (py::handle item : entities) item.cast<Flags&>().Set(flag, value);
            },
            py::arg("flag"), py::arg("value"), py::arg("entities"),
            "Sets flag to value on every node / element / condition of the iterable.")
        .def(
            "CopySolutionStepData",
            [](const VariableUtils&, ModelPart& model_part, std::size_t source, std::size_t destination) {
                // Historical storage holds doubles and 3-vectors only (the kernel refuses other kinds).
                const auto& variables = model_part.GetRootModelPart().pGetNodalSolutionStepVariablesList();
                if (!variables) return;
                for (const auto& node : model_part.Nodes())
                    for (const VariableData* variable : variables->Variables()) {
                        if (const auto* scalar = dynamic_cast<const Variable<double>*>(variable))
                            node->FastGetSolutionStepValue(*scalar, destination) =
                                node->FastGetSolutionStepValue(*scalar, source);
                        else if (const auto* vector = dynamic_cast<const Variable<Array3>*>(variable))
                            node->FastGetSolutionStepValue(*vector, destination) =
                                node->FastGetSolutionStepValue(*vector, source);
                    }
            },
            py::arg("model_part"), py::arg("source"), py::arg("destination"),
            "Copies every historical value of buffer step source into step destination on the nodes of "
            "model_part (restarting a step from the last converged state: source 1, destination 0).");
}

}  // namespace contact_app::bindings
