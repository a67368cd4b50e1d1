// SPDX-License-Identifier: BSD-3-Clause
#include <memory>
#include <string>

#include "contact_app/bindings/binding_helpers.h"
#include "contact_app/bindings/bindings.h"
#include "contact_app/kernel/variables.h"
#include "contact_app/kernel/registry.h"
#include "contact_app/kernel/constitutive_law.h"
#include "contact_app/kernel/process_info.h"
#include "contact_app/kernel/properties.h"
#include "contact_app/kernel/table.h"

namespace contact_app::bindings {

namespace {

/// "YOUNG_MODULUS, POISSON_RATIO": the variables stored in a container, in insertion order.
std::string StoredNames(const DataValueContainer& data) {
    std::string names;
    for (const auto& entry : data.Data()) names += (names.empty() ? "" : ", ") + entry.first->Name();
    return names;
}

void BindTable(py::module_& m) {
    py::class_<Table, std::shared_ptr<Table>>(m, "Table", "Piecewise-linear table y(x) (Kratos Table).")
        .def(py::init<>(), "An empty table.")
        .def("AddRow", &Table::PushBack, py::arg("x"), py::arg("y"), "Inserts a row (kept sorted by x).")
        .def("PushBack", &Table::PushBack, py::arg("x"), py::arg("y"), "Same as AddRow.")
        .def("GetValue", &Table::GetValue, py::arg("x"), "y(x), linearly interpolated or extrapolated.")
        .def("GetDerivative", &Table::GetDerivative, py::arg("x"), "dy/dx of the segment containing x.")
        .def("Size", &Table::Size, "Number of rows.")
        .def("__len__", &Table::Size, "Number of rows.")
        .def("Data", &Table::Data, "The rows as (x, y) tuples.")
        .def(
            "__repr__", [](const Table& self) { return py::str("<Table with {} rows>").format(self.Size()); },
            "<Table with n rows>.");
}

}  // namespace

void BindConstitutiveLaw(py::module_& m) {
    py::class_<ConstitutiveLaw, std::shared_ptr<ConstitutiveLaw>>(m, "ConstitutiveLaw",
                                                                  "A material law (Kratos ConstitutiveLaw).")
        .def("Clone", &ConstitutiveLaw::Clone, "An independent copy.")
        .def("WorkingSpaceDimension", &ConstitutiveLaw::WorkingSpaceDimension, "2 or 3.")
        .def("GetStrainSize", &ConstitutiveLaw::GetStrainSize, "Number of Voigt strain components.")
        .def("Info", &ConstitutiveLaw::Info, "The law's name.")
        .def("__repr__", [](const ConstitutiveLaw& self) { return "<ConstitutiveLaw " + self.Info() + ">"; });
    m.def(
        "create_constitutive_law",
        [](const std::string& name) { return Registry<ConstitutiveLaw>::Instance().Get(name).Clone(); },
        py::arg("name"), "A new law of a registered name; InputError (with a suggestion) for an unknown name.");
}

void BindProperties(py::module_& m) {
    BindTable(m);
    BindConstitutiveLaw(m);

    py::class_<Properties, std::shared_ptr<Properties>> properties(
        m, "Properties", "Material and condition parameters shared by entities (Kratos Properties).");
    properties.def(py::init<IndexType>(), py::arg("id"), "Stand-alone properties (use ModelPart.CreateNewProperties).")
        .def_property_readonly("Id", &Properties::Id, "Properties id.")
        .def(
            "CopyValuesFrom", [](Properties& self, const Properties& other) { self.Data() = other.Data(); },
            py::arg("other"),
            "Replaces the stored values (not the tables) by those of other; the contact processes give each pair "
            "property the material values of its body this way.");
    // The law overloads come first: the generic pointer-variable overload would otherwise refuse them.
    using LawVariable = Variable<std::shared_ptr<ConstitutiveLaw>>;
    auto set_law = [](Properties& self, const LawVariable& variable, std::shared_ptr<ConstitutiveLaw> law) {
        self.SetValue(variable, std::move(law));
    };
    auto get_law = [](const Properties& self, const LawVariable& variable) { return self.GetValue(variable); };
    properties.def("SetValue", set_law, py::arg("variable"), py::arg("value"), "Stores the constitutive law.")
        .def("__setitem__", set_law, py::arg("variable"), py::arg("value"), "Stores the constitutive law.")
        .def("GetValue", get_law, py::arg("variable"), "The constitutive law (None if unset).")
        .def("__getitem__", get_law, py::arg("variable"), "The constitutive law (None if unset).");
    DefValueAccess(properties, true);
    properties
        .def("HasTable", &Properties::HasTable, py::arg("input_variable"), py::arg("output_variable"),
             "True if a table maps input_variable to output_variable.")
        .def("GetTable", &Properties::GetTable, py::arg("input_variable"), py::arg("output_variable"),
             py::return_value_policy::reference_internal, "The table; InputError if there is none.")
        .def("SetTable", &Properties::SetTable, py::arg("input_variable"), py::arg("output_variable"), py::arg("table"),
             "Stores a copy of table for (input_variable, output_variable).")
        .def("NumberOfTables", &Properties::NumberOfTables, "Number of tables.")
        .def(
            "__repr__",
            [](const Properties& self) {
                return py::str("<Properties {}: {}>").format(self.Id(), StoredNames(self.Data()));
            },
            "<Properties id: stored variables>.");
    DefIdentity(properties);

    py::class_<ProcessInfo, Flags, std::shared_ptr<ProcessInfo>> process_info(
        m, "ProcessInfo", "Global values of an analysis (Kratos ProcessInfo): TIME, DELTA_TIME, STEP, switches.",
        py::multiple_inheritance());
    process_info.def(py::init<>(), "An empty ProcessInfo.");
    DefValueAccess(process_info, true);
    process_info.def(
        "__repr__",
        [](const ProcessInfo& self) { return py::str("<ProcessInfo: {}>").format(StoredNames(self.Data())); },
        "<ProcessInfo: stored variables>.");
    DefIdentity(process_info);
}

}  // namespace contact_app::bindings
