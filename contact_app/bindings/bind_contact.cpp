// SPDX-License-Identifier: BSD-3-Clause
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "contact_app/bindings/bindings.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/model_part.h"
#include "contact_app/kernel/registry.h"
#include "contact_app/kernel/serializer.h"
#include "custom_conditions/paired_condition.h"

namespace contact_app::bindings {

namespace {

using ModelPartClass = py::class_<ModelPart, Flags, std::shared_ptr<ModelPart>>;
using ConditionClass = py::class_<Condition, Flags, std::shared_ptr<Condition>>;

const PairedCondition& PairedPrototype(const std::string& name) {
    const Condition& prototype = Registry<Condition>::Instance().Get(name);
    const auto* paired = dynamic_cast<const PairedCondition*>(&prototype);
    CONTACT_CHECK(paired != nullptr, InputError, "condition \"", name, "\" is not a paired (contact) condition",
                  "\n  expected: a contact, mesh-tying or MPC condition name such as ALMFrictionlessMortarContactCondition2D2N",
                  "\n  fix:      use CreateNewCondition for ordinary conditions");
    return *paired;
}

Geometry::PointsArrayType RootNodes(const ModelPart& part, const std::vector<IndexType>& ids) {
    Geometry::PointsArrayType nodes;
    for (const IndexType id : ids) nodes.push_back(part.GetRootModelPart().pGetNode(id));
    return nodes;
}

std::shared_ptr<Condition> CreateNewPairedCondition(ModelPart& part, const std::string& name, IndexType id,
                                                    const std::vector<IndexType>& slave_ids,
                                                    const std::vector<IndexType>& master_ids,
                                                    Properties::Pointer properties) {
    const PairedCondition& prototype = PairedPrototype(name);
    CONTACT_CHECK(!part.GetRootModelPart().HasCondition(id), InputError, "condition id ", id,
                  " is already used in model part ", part.GetRootModelPart().Name());
    auto slave = prototype.GetParentGeometry().Create(RootNodes(part, slave_ids));
    const Geometry& master_type = prototype.HasPairedGeometry() ? prototype.GetPairedGeometry() : prototype.GetParentGeometry();
    auto master = master_type.Create(RootNodes(part, master_ids));
    auto condition = prototype.Create(id, slave, std::move(properties), master);
    part.AddCondition(condition);
    return condition;
}

const PairedCondition& AsPaired(const Condition& condition) {
    const auto* paired = dynamic_cast<const PairedCondition*>(&condition);
    CONTACT_CHECK(paired != nullptr, InputError, condition.Info(), " is not a paired condition and has no paired geometry");
    return *paired;
}

}  // namespace

void BindContact(py::module_& m) {
    auto model_part = py::reinterpret_borrow<ModelPartClass>(m.attr("ModelPart"));
    model_part.def("CreateNewPairedCondition", &CreateNewPairedCondition, py::arg("name"), py::arg("id"),
                   py::arg("slave_node_ids"), py::arg("master_node_ids"), py::arg("properties"),
                   "A paired (contact / mesh-tying / MPC) condition over a slave and a master face.");
    auto condition = py::reinterpret_borrow<ConditionClass>(m.attr("Condition"));
    condition
        .def(
            "GetPairedGeometry", [](const Condition& self) { return AsPaired(self).pGetPairedGeometry(); },
            "The master face of a paired condition; InputError for other conditions or unpaired ones.")
        .def(
            "GetParentGeometry", [](const Condition& self) { return AsPaired(self).pGetParentGeometry(); },
            "The slave face of a paired condition.")
        .def(
            "IsPaired", [](const Condition& self) { return dynamic_cast<const PairedCondition*>(&self) != nullptr; },
            "True for contact, mesh-tying and MPC pair conditions.")
        .def(
            "Save",
            [](const Condition& self) {
                Serializer serializer;
                self.Save(serializer);
                return py::bytes(serializer.Data());
            },
            "The restart state of the condition (id, flags and, for pairs, the master normal and the frictional "
            "start-of-step operators) as bytes.")
        .def(
            "Load",
            [](Condition& self, const py::bytes& data) {
                Serializer serializer{std::string(data)};
                self.Load(serializer);
            },
            py::arg("data"), "Restores the state written by Save() of a condition of the same class; InputError otherwise.");
}

}  // namespace contact_app::bindings
