// SPDX-License-Identifier: BSD-3-Clause
#include <functional>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <pybind11/stl.h>

#include "contact_app/application.h"
#include "contact_app/bindings/bindings.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/string_utilities.h"
#include "custom_processes/contact_search_process.h"
#include "custom_processes/mpc_contact_search_process.h"
#include "custom_utilities/index_map.h"

namespace contact_app::bindings {

namespace {

using Setter = std::function<void(ContactSearchSettings&, const py::handle&)>;

template <class T>
Setter Field(T ContactSearchSettings::*member) {
    return [member](ContactSearchSettings& settings, const py::handle& value) { settings.*member = value.cast<T>(); };
}

/// Every settings key (docs/theory/contact_search.md §5) and how to store it; the octree keys may also come nested in
/// "octree_search_parameters".
const std::map<std::string, Setter>& SettingsKeys() {
    static const std::map<std::string, Setter> keys = {
        {"allocation_size", Field(&ContactSearchSettings::allocation_size)},
        {"bucket_size", Field(&ContactSearchSettings::bucket_size)},
        {"search_factor", Field(&ContactSearchSettings::search_factor)},
        {"type_search", [](ContactSearchSettings& s, const py::handle& v) { s.type_search = ParseSearchTreeType(v.cast<std::string>()); }},
        {"check_gap", [](ContactSearchSettings& s, const py::handle& v) { s.check_gap = ParseCheckGap(v.cast<std::string>()); }},
        {"simple_search", Field(&ContactSearchSettings::simple_search)},
        {"condition_name", Field(&ContactSearchSettings::condition_name)},
        {"final_string", Field(&ContactSearchSettings::final_string)},
        {"id_name", Field(&ContactSearchSettings::id_name)},
        {"inverted_search", Field(&ContactSearchSettings::inverted_search)},
        {"dynamic_search", Field(&ContactSearchSettings::dynamic_search)},
        {"static_check_movement", Field(&ContactSearchSettings::static_check_movement)},
        {"predefined_master_slave", Field(&ContactSearchSettings::predefined_master_slave)},
        {"normal_orientation_threshold", Field(&ContactSearchSettings::normal_orientation_threshold)},
        {"consider_gap_threshold", Field(&ContactSearchSettings::consider_gap_threshold)},
        {"predict_correct_lagrange_multiplier", Field(&ContactSearchSettings::predict_correct_lagrange_multiplier)},
        {"pure_slip", Field(&ContactSearchSettings::pure_slip)},
        {"debug_mode", Field(&ContactSearchSettings::debug_mode)},
        {"bounding_box_factor", Field(&ContactSearchSettings::bounding_box_factor)},
        {"debug_obb", Field(&ContactSearchSettings::debug_obb)},
        {"OBB_intersection_type", Field(&ContactSearchSettings::OBB_intersection_type)},
        {"build_from_bounding_box", Field(&ContactSearchSettings::build_from_bounding_box)},
        {"lower_bounding_box_coefficient", Field(&ContactSearchSettings::lower_bounding_box_coefficient)},
        {"higher_bounding_box_coefficient", Field(&ContactSearchSettings::higher_bounding_box_coefficient)},
    };
    return keys;
}

void Assign(ContactSearchSettings& settings, const py::dict& values, const std::string& where) {
    const auto& keys = SettingsKeys();
    for (const auto& [key_handle, value] : values) {
        const std::string key = py::str(key_handle);
        if (key == "octree_search_parameters" && where.empty()) {
            Assign(settings, value.cast<py::dict>(), "octree_search_parameters › ");
            continue;
        }
        const auto found = keys.find(key);
        if (found == keys.end()) {
            std::vector<std::string> names;
            for (const auto& entry : keys) names.push_back(entry.first);
            CONTACT_THROW(InputError, "ContactSearchSettings: unknown key \"", key, "\"\n  where:    search_parameters › ",
                          where, key, "\n  expected: one of ", QuotedList(names), DidYouMean(key, names));
        }
        try {
            found->second(settings, value);
        } catch (const py::cast_error&) {
            CONTACT_THROW(InputError, "ContactSearchSettings: key \"", key, "\" has the wrong type (got ",
                          std::string(py::str(value.get_type())), ": ", std::string(py::repr(value)), ")");
        }
    }
    settings.Validate();
}

ContactSearchSettings FromDict(const py::dict& values) {
    ContactSearchSettings settings;
    Assign(settings, values, "");
    return settings;
}

/// (slave face id, master face id, pair condition id or 0) of every INDEX_MAP entry of the contact part.
std::vector<std::tuple<IndexType, IndexType, IndexType>> Pairs(ContactSearchProcess& self) {
    std::vector<std::tuple<IndexType, IndexType, IndexType>> pairs;
    for (const auto& face : self.GetContactModelPart().Conditions())
        if (const auto map = face->GetValue(INDEX_MAP))
            for (const auto& [master, pair] : *map) pairs.emplace_back(face->Id(), master, pair);
    return pairs;
}

void BindSearch(py::module_& m) {
    using TProcess = ContactSearchProcess;
    py::class_<TProcess> cls(m, "ContactSearchProcess",
                             "Mortar contact search (Kratos AdvancedContactSearchProcess; simple_search: "
                             "SimpleContactSearchProcess).");
    cls.def(py::init<ModelPart&, ContactSearchSettings, Properties::Pointer, bool>(), py::arg("main_model_part"),
            py::arg("settings"), py::arg("pair_properties") = nullptr, py::arg("resume") = false,
            py::keep_alive<1, 2>(),
            "Search over main_model_part.Contact[.ContactSub<id_name>]; pairs get pair_properties (None: the slave "
            "face's). resume: adopt the pairs and flags a restart file restored instead of erasing them.")
        .def("ExecuteInitialize", &TProcess::ExecuteInitialize, "CheckContactModelParts, CreatePointListMortar, InitializeMortarConditions.")
        .def("ExecuteInitializeSolutionStep", &TProcess::ExecuteInitializeSolutionStep, "ClearMortarConditions + UpdateMortarConditions.")
        .def("ExecuteFinalizeSolutionStep", &TProcess::ExecuteFinalizeSolutionStep, "ClearMortarConditions.")
        .def("Execute", &TProcess::Execute, "The three phases in a row.")
        .def("ClearMortarConditions", &TProcess::ClearMortarConditions, "Erase inactive pairs, zero inactive multipliers.")
        .def("CheckContactModelParts", &TProcess::CheckContactModelParts, "Clone faces claimed by another search.")
        .def("CreatePointListMortar", &TProcess::CreatePointListMortar, "Rebuild the master point list and tree.")
        .def("UpdateMortarConditions", &TProcess::UpdateMortarConditions, "The search of the step.")
        .def("ResetContactOperators", &TProcess::ResetContactOperators, "Erase inactive pairs (all if MODIFIED).")
        .def("InvertSearch", &TProcess::InvertSearch, "Swap the slave and master roles.")
        .def("GetPairs", &Pairs, "[(slave face id, master face id, pair condition id or 0)] from the INDEX_MAPs.")
        .def(
            "GetLastSearchTimings",
            [](const TProcess& self) {
                const auto& t = self.LastTimings();
                py::dict d;
                d["tree_build"] = t.tree_build;
                d["queries"] = t.queries;
                d["total"] = t.total;
                d["slave_faces"] = t.slave_faces;
                d["master_faces"] = t.master_faces;
                d["candidates"] = t.candidates;
                return d;
            },
            "Seconds spent in the last UpdateMortarConditions (tree_build, queries, total) and counts.")
        .def_property("penetration_checked", &TProcess::PenetrationChecked, &TProcess::SetPenetrationChecked,
                      "Whether the first search's check for initially penetrating slave nodes ran (restart state).")
        .def("GetContactModelPart", &TProcess::GetContactModelPart, py::return_value_policy::reference_internal)
        .def("GetComputingModelPart", &TProcess::GetComputingModelPart, py::return_value_policy::reference_internal)
        .def_property_readonly("settings", &TProcess::Settings, "The settings (a copy).");
}

}  // namespace

void BindContactSearch(py::module_& m) {
    py::class_<ContactSearchSettings> settings(m, "ContactSearchSettings",
                                               "Settings of the contact search (Kratos search_parameters keys).");
    settings
        .def(py::init([](const py::kwargs& kwargs) { return FromDict(kwargs); }),
             "Defaults, overridden by keyword arguments (unknown keys raise InputError).")
        .def_static("from_dict", &FromDict, py::arg("values"), "Settings from a dict; unknown keys raise InputError.")
        .def_property(
            "type_search", [](const ContactSearchSettings& s) { return SearchTreeTypeName(s.type_search); },
            [](ContactSearchSettings& s, const std::string& v) { s.type_search = ParseSearchTreeType(v); },
            "in_radius, in_box, in_radius_with_obb, in_box_with_obb, octree_with_obb (or InRadius, ...).")
        .def_property(
            "check_gap", [](const ContactSearchSettings& s) { return CheckGapName(s.check_gap); },
            [](ContactSearchSettings& s, const std::string& v) { s.check_gap = ParseCheckGap(v); },
            "no_check, direct_check, check_mapping (or NoCheck, DirectCheck, MappingCheck).")
        .def("Validate", &ContactSearchSettings::Validate, "InputError for out-of-range values.");
#define CONTACT_APP_SETTINGS_FIELD(name) settings.def_readwrite(#name, &ContactSearchSettings::name);
    CONTACT_APP_SETTINGS_FIELD(allocation_size)
    CONTACT_APP_SETTINGS_FIELD(bucket_size)
    CONTACT_APP_SETTINGS_FIELD(search_factor)
    CONTACT_APP_SETTINGS_FIELD(simple_search)
    CONTACT_APP_SETTINGS_FIELD(condition_name)
    CONTACT_APP_SETTINGS_FIELD(final_string)
    CONTACT_APP_SETTINGS_FIELD(id_name)
    CONTACT_APP_SETTINGS_FIELD(inverted_search)
    CONTACT_APP_SETTINGS_FIELD(dynamic_search)
    CONTACT_APP_SETTINGS_FIELD(static_check_movement)
    CONTACT_APP_SETTINGS_FIELD(predefined_master_slave)
    CONTACT_APP_SETTINGS_FIELD(normal_orientation_threshold)
    CONTACT_APP_SETTINGS_FIELD(consider_gap_threshold)
    CONTACT_APP_SETTINGS_FIELD(predict_correct_lagrange_multiplier)
    CONTACT_APP_SETTINGS_FIELD(pure_slip)
    CONTACT_APP_SETTINGS_FIELD(debug_mode)
    CONTACT_APP_SETTINGS_FIELD(bounding_box_factor)
    CONTACT_APP_SETTINGS_FIELD(debug_obb)
    CONTACT_APP_SETTINGS_FIELD(OBB_intersection_type)
    CONTACT_APP_SETTINGS_FIELD(build_from_bounding_box)
    CONTACT_APP_SETTINGS_FIELD(lower_bounding_box_coefficient)
    CONTACT_APP_SETTINGS_FIELD(higher_bounding_box_coefficient)
#undef CONTACT_APP_SETTINGS_FIELD

    BindSearch(m);
    py::class_<MPCContactSearchProcess, ContactSearchProcess>(
        m, "MPCContactSearchProcess", "Contact search that also creates a ContactMasterSlaveConstraint per pair.")
        .def(py::init<ModelPart&, ContactSearchSettings, Properties::Pointer, bool>(), py::arg("main_model_part"),
             py::arg("settings"), py::arg("pair_properties") = nullptr, py::arg("resume") = false,
             py::keep_alive<1, 2>(),
             "As ContactSearchProcess; ConfigurationError at the first pair if the constraint is not registered.");
}

}  // namespace contact_app::bindings
