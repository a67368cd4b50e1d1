// SPDX-License-Identifier: BSD-3-Clause
#include <memory>
#include <string>
#include <vector>

#include "contact_app/bindings/binding_helpers.h"
#include "contact_app/bindings/bindings.h"
#include "contact_app/kernel/model.h"
#include "contact_app/kernel/model_part.h"

namespace contact_app::bindings {

namespace {

using ModelPartClass = py::class_<ModelPart, Flags, std::shared_ptr<ModelPart>>;
constexpr auto kInternal = py::return_value_policy::reference_internal;

/// Index-based iterator, so that a container changed during the loop cannot leave it dangling.
template <class T>
struct ContainerIterator {
    const EntityContainer<T>* container;
    std::size_t index = 0;
};

template <class T>
void BindContainer(py::module_& m, const std::string& name) {
    using View = ContainerView<T>;
    using Iterator = ContainerIterator<T>;
    py::class_<Iterator>(m, (name + "Iterator").c_str(), "Iterator over a model part container, in id order.")
        .def(
            "__iter__", [](py::object self) { return self; }, "The iterator itself.")
        .def(
            "__next__",
            [](Iterator& self) {
                if (self.index >= self.container->size()) throw py::stop_iteration();
                return self.container->Pointers()[self.index++];
            },
            "The next entity.");
    py::class_<View>(m, name.c_str(), "Read-only container of a model part: len(), iteration in id order, `in`.")
        .def(
            "__len__", [](const View& self) { return self.container->size(); }, "Number of entities.")
        .def(
            "__iter__", [](const View& self) { return Iterator{self.container}; }, py::keep_alive<0, 1>(),
            "Iterates in id order.")
        .def(
            "__contains__", [](const View& self, IndexType id) { return self.container->Contains(id); }, py::arg("id"),
            "True if an entity with this id is present.")
        .def(
            "__contains__",
            [](const View& self, const T& entity) { return self.container->Find(entity.Id()) == &entity; },
            py::arg("entity"), "True if this entity is present.")
        .def(
            "__repr__", [name](const View& self) { return py::str("<{} of {}>").format(name, self.container->size()); },
            "<NodesArray of n>.");
}

/// Getter of a container property: a view that keeps the model part alive.
template <class T>
py::cpp_function ViewGetter(const EntityContainer<T>& (ModelPart::*get)() const) {
    return py::cpp_function([get](const ModelPart& self) { return ContainerView<T>{&(self.*get)()}; },
                            py::keep_alive<0, 1>());
}

void DefHierarchy(ModelPartClass& mp) {
    mp.def_property_readonly("Name", &ModelPart::Name, "Name (without the parents).")
        .def("FullName", &ModelPart::FullName, "Dotted path from the root, e.g. \"Structure.Contact_Part\".")
        .def("IsSubModelPart", &ModelPart::IsSubModelPart, "True unless this is a root model part.")
        .def("CreateSubModelPart", &ModelPart::CreateSubModelPart, py::arg("name"), kInternal, "A new sub model part.")
        .def("GetSubModelPart", &ModelPart::GetSubModelPart, py::arg("name"), kInternal,
             "A sub model part by name or dotted path \"A.B\".")
        .def("HasSubModelPart", &ModelPart::HasSubModelPart, py::arg("name"), "True if the sub model part exists.")
        .def("RemoveSubModelPart", &ModelPart::RemoveSubModelPart, py::arg("name"), "Deletes a sub model part.")
        .def("GetSubModelPartNames", &ModelPart::GetSubModelPartNames, "Names of the direct sub model parts.")
        .def("NumberOfSubModelParts", &ModelPart::NumberOfSubModelParts, "Number of direct sub model parts.")
        .def_property_readonly(
            "SubModelParts",
            [](py::object self) { return ReferenceList(self.cast<const ModelPart&>().SubModelParts(), self); },
            "The direct sub model parts.")
        .def(
            "GetRootModelPart", [](ModelPart& self) -> ModelPart& { return self.GetRootModelPart(); }, kInternal,
            "The root of the hierarchy.")
        .def("GetParentModelPart", &ModelPart::GetParentModelPart, kInternal, "The parent (itself for a root).")
        .def("GetModel", &ModelPart::GetModel, py::return_value_policy::reference,
             "The owning Model (None if stand-alone).");
}

void DefNodesAndData(ModelPartClass& mp) {
    mp.def("AddNodalSolutionStepVariable", &ModelPart::AddNodalSolutionStepVariable, py::arg("variable"),
           "Declares a historical variable (before nodes are created).")
        .def("HasNodalSolutionStepVariable", &ModelPart::HasNodalSolutionStepVariable, py::arg("variable"),
             "True if the variable is historical.")
        .def("SetBufferSize", &ModelPart::SetBufferSize, py::arg("buffer_size"), "Number of historical steps kept.")
        .def("GetBufferSize", &ModelPart::GetBufferSize, "Number of historical steps kept.")
        .def("CloneTimeStep", &ModelPart::CloneTimeStep, py::arg("time"),
             "Shifts the buffers; sets TIME, DELTA_TIME, STEP.")
        .def("CreateNewNode", &ModelPart::CreateNewNode, py::arg("id"), py::arg("x"), py::arg("y"), py::arg("z"),
             "A new node (ids are unique per root).")
        .def("AddNode", &ModelPart::AddNode, py::arg("node"), "Adds a node of the same root.")
        .def("AddNodes", &ModelPart::AddNodes, py::arg("ids"), "Adds root nodes by id.")
        .def("HasNode", &ModelPart::HasNode, py::arg("id"), "True if the node is here.")
        .def("GetNode", &ModelPart::pGetNode, py::arg("id"), "The node; InputError if missing.")
        .def("RemoveNode", &ModelPart::RemoveNode, py::arg("id"), "Removes the node here and below.")
        .def("RemoveNodeFromAllLevels", &ModelPart::RemoveNodeFromAllLevels, py::arg("id"),
             "Removes the node everywhere.")
        .def("NumberOfNodes", &ModelPart::NumberOfNodes, "Number of nodes.")
        .def("CreateNewProperties", &ModelPart::CreateNewProperties, py::arg("id"), "New properties.")
        .def("GetProperties", &ModelPart::pGetProperties, py::arg("id"),
             "The properties (created if missing, as Kratos).")
        .def("HasProperties", &ModelPart::HasProperties, py::arg("id"), "True if the properties exist here.")
        .def("AddProperties", &ModelPart::AddProperties, py::arg("properties"), "Adds properties.")
        .def("NumberOfProperties", &ModelPart::NumberOfProperties, "Number of properties.")
        .def_property_readonly("ProcessInfo", &ModelPart::pGetProcessInfo, "The ProcessInfo shared by the hierarchy.")
        .def_property_readonly("Nodes", ViewGetter(&ModelPart::Nodes), "The nodes (NodesArray).")
        .def_property_readonly("Properties", ViewGetter(&ModelPart::PropertiesArray),
                               "The properties (PropertiesArray).")
        .def("AddTable", &ModelPart::AddTable, py::arg("id"), py::arg("table"), "Adds a table.")
        .def("HasTable", &ModelPart::HasTable, py::arg("id"), "True if the table exists.")
        .def("GetTable", &ModelPart::pGetTable, py::arg("id"), "The table; InputError if missing.")
        .def("NumberOfTables", &ModelPart::NumberOfTables, "Number of tables.")
        .def("AddGeometry", &ModelPart::AddGeometry, py::arg("id"), py::arg("geometry"), "Adds a geometry.")
        .def("HasGeometry", &ModelPart::HasGeometry, py::arg("id"), "True if the geometry exists.")
        .def("GetGeometry", &ModelPart::pGetGeometry, py::arg("id"), "The geometry; InputError if missing.")
        .def("NumberOfGeometries", &ModelPart::NumberOfGeometries, "Number of geometries.");
    DefValueAccess(mp);
}

void DefEntities(ModelPartClass& mp) {
    const auto ids = py::arg("node_ids");
    const auto props = py::arg("properties");
    mp.def("CreateNewElement", &ModelPart::CreateNewElement, py::arg("name"), py::arg("id"), ids, props,
           "A registered element on root nodes.")
        .def("AddElement", &ModelPart::AddElement, py::arg("element"), "Adds an element of the same root.")
        .def("AddElements", &ModelPart::AddElements, py::arg("ids"), "Adds root elements by id.")
        .def("HasElement", &ModelPart::HasElement, py::arg("id"), "True if the element is here.")
        .def("GetElement", &ModelPart::pGetElement, py::arg("id"), "The element; InputError if missing.")
        .def("RemoveElement", &ModelPart::RemoveElement, py::arg("id"), "Removes the element here and below.")
        .def("NumberOfElements", &ModelPart::NumberOfElements, "Number of elements.")
        .def("CreateNewCondition", &ModelPart::CreateNewCondition, py::arg("name"), py::arg("id"), ids, props,
             "A registered condition on root nodes.")
        .def("AddCondition", &ModelPart::AddCondition, py::arg("condition"), "Adds a condition of the same root.")
        .def("AddConditions", &ModelPart::AddConditions, py::arg("ids"), "Adds root conditions by id.")
        .def("HasCondition", &ModelPart::HasCondition, py::arg("id"), "True if the condition is here.")
        .def("GetCondition", &ModelPart::pGetCondition, py::arg("id"), "The condition; InputError if missing.")
        .def("RemoveCondition", &ModelPart::RemoveCondition, py::arg("id"), "Removes the condition here and below.")
        .def("RemoveConditionsFlagged", &ModelPart::RemoveConditionsFlagged, py::arg("flag"),
             "Removes the conditions with flag set; returns how many.")
        .def("NumberOfConditions", &ModelPart::NumberOfConditions, "Number of conditions.")
        .def(
            "CreateNewMasterSlaveConstraint",
            [](ModelPart& self, const std::string& name, IndexType id, DofsVectorType masters, DofsVectorType slaves,
               const Matrix& relation, const Vector& constant) {
                return self.CreateNewMasterSlaveConstraint(name, id, std::move(masters), std::move(slaves), relation,
                                                           constant);
            },
            py::arg("name"), py::arg("id"), py::arg("master_dofs"), py::arg("slave_dofs"), py::arg("relation"),
            py::arg("constant"), "A registered constraint: slaves = relation @ masters + constant.")
        .def(
            "CreateNewMasterSlaveConstraint",
            [](ModelPart& self, const std::string& name, IndexType id, Node& master,
               const Variable<double>& master_variable, Node& slave, const Variable<double>& slave_variable,
               double weight, double constant) {
                return self.CreateNewMasterSlaveConstraint(name, id, master, master_variable, slave, slave_variable,
                                                           weight, constant);
            },
            py::arg("name"), py::arg("id"), py::arg("master_node"), py::arg("master_variable"), py::arg("slave_node"),
            py::arg("slave_variable"), py::arg("weight"), py::arg("constant"), "slave = weight * master + constant.")
        .def("AddMasterSlaveConstraint", &ModelPart::AddMasterSlaveConstraint, py::arg("constraint"),
             "Adds a constraint.")
        .def("AddMasterSlaveConstraints", &ModelPart::AddMasterSlaveConstraints, py::arg("ids"),
             "Adds root constraints by id.")
        .def("HasMasterSlaveConstraint", &ModelPart::HasMasterSlaveConstraint, py::arg("id"),
             "True if the constraint is here.")
        .def(
            "GetMasterSlaveConstraint",
            [](const ModelPart& self, IndexType id) {
                self.GetMasterSlaveConstraint(id);  // throws the descriptive InputError when missing
                return self.MasterSlaveConstraints().FindPointer(id);
            },
            py::arg("id"), "The constraint; InputError if missing.")
        .def("RemoveMasterSlaveConstraint", &ModelPart::RemoveMasterSlaveConstraint, py::arg("id"),
             "Removes the constraint.")
        .def("NumberOfMasterSlaveConstraints", &ModelPart::NumberOfMasterSlaveConstraints, "Number of constraints.")
        .def_property_readonly("Elements", ViewGetter(&ModelPart::Elements), "The elements (ElementsArray).")
        .def_property_readonly("Conditions", ViewGetter(&ModelPart::Conditions), "The conditions (ConditionsArray).")
        .def_property_readonly("MasterSlaveConstraints", ViewGetter(&ModelPart::MasterSlaveConstraints),
                               "The constraints (MasterSlaveConstraintsArray).");
}

void DefModel(py::class_<Model>& model) {
    model.def(py::init<>(), "An empty model.")
        .def("CreateModelPart", &Model::CreateModelPart, py::arg("name"), py::arg("buffer_size") = 1, kInternal,
             "A new root model part (dotted names create sub model parts).")
        .def("GetModelPart", &Model::GetModelPart, py::arg("name"), kInternal, "A model part by name or dotted path.")
        .def("__getitem__", &Model::GetModelPart, py::arg("name"), kInternal, "Same as GetModelPart(name).")
        .def("HasModelPart", &Model::HasModelPart, py::arg("name"), "True if the model part exists.")
        .def("__contains__", &Model::HasModelPart, py::arg("name"), "Same as HasModelPart(name).")
        .def("DeleteModelPart", &Model::DeleteModelPart, py::arg("name"),
             "Deletes a model part (Python references to it become invalid).")
        .def("GetModelPartNames", &Model::GetModelPartNames, "Sorted names of the root model parts.")
        .def(
            "__repr__", [](const Model& self) { return py::str("<Model {}>").format(self.GetModelPartNames()); },
            "<Model [names]>.");
}

}  // namespace

void BindModelPart(py::module_& m) {
    BindContainer<Node>(m, "NodesArray");
    BindContainer<Element>(m, "ElementsArray");
    BindContainer<Condition>(m, "ConditionsArray");
    BindContainer<MasterSlaveConstraint>(m, "MasterSlaveConstraintsArray");
    BindContainer<Properties>(m, "PropertiesArray");

    // Model is registered before ModelPart's methods so that signatures naming it (GetModel) show the
    // Python name, not the C++ one; its own methods are added after ModelPart exists.
    py::class_<Model> model(m, "Model", "Owner of the root model parts (Kratos Model).");
    ModelPartClass mp(m, "ModelPart", "A named set of nodes, elements, conditions and properties (Kratos ModelPart).",
                      py::multiple_inheritance());
    DefHierarchy(mp);
    DefNodesAndData(mp);
    DefEntities(mp);
    mp.def(
          "Info", [](const ModelPart& self) { return self.Info(); }, "Multi-line summary of the hierarchy.")
        .def(
            "__str__", [](const ModelPart& self) { return self.Info(); }, "Same as Info().")
        .def(
            "__repr__", [](const ModelPart& self) { return "<ModelPart " + self.FullName() + ">"; },
            "<ModelPart Full.Name>.");
    DefIdentity(mp);
    DefModel(model);
}

}  // namespace contact_app::bindings
