// SPDX-License-Identifier: BSD-3-Clause
#include <functional>
#include <map>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include <pybind11/stl.h>

#include "custom_utilities/contact_variables.h"
#include "contact_app/bindings/bindings.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/string_utilities.h"
#include "custom_processes/contact_search_process.h"
#include "custom_processes/mpc_contact_search_process.h"
#include "custom_utilities/index_map.h"

namespace contact_app::bindings {

namespace {

using Setter = std::function<void(ContactSearchSettings&, const py::handle&, const std::string& where)>;

/// A settings value from Python: the enums from their spellings (ParseSearchTreeType, ParseCheckGap).
template <class T>
T FromPython(const py::handle& value, const std::string& where) {
    if constexpr (std::is_same_v<T, SearchTreeType>)
        return ParseSearchTreeType(value.cast<std::string>(), where);
    else if constexpr (std::is_same_v<T, CheckGap>)
        return ParseCheckGap(value.cast<std::string>(), where);
    else
        return value.cast<T>();
}

/// Every settings key (ForEachSearchSetting) and how to store it.
const std::map<std::string, Setter>& SettingsKeys() {
    static const std::map<std::string, Setter> keys = [] {
        std::map<std::string, Setter> result;
        ForEachSearchSetting([&](const char* key, auto member) {
            using T = std::remove_reference_t<decltype(std::declval<ContactSearchSettings&>().*member)>;
            result[key] = [member](ContactSearchSettings& settings, const py::handle& value, const std::string& where) {
                settings.*member = FromPython<T>(value, where);
            };
        });
        return result;
    }();
    return keys;
}

/// Assigns @p values (keys of SettingsKeys; "max_number_results" for allocation_size; the octree keys also nested in
/// "octree_search_parameters"). @p where: the JSON path of the block, for the messages.
void Assign(ContactSearchSettings& settings, const py::dict& values, const std::string& where, bool nested = false) {
    const auto& keys = SettingsKeys();
    for (const auto& [key_handle, value] : values) {
        const std::string written = py::str(key_handle);
        if (written == "octree_search_parameters" && !nested) {
            Assign(settings, value.cast<py::dict>(), where + " › octree_search_parameters", true);
            continue;
        }
        const std::string key = written == "max_number_results" ? "allocation_size" : written;
        const auto found = keys.find(key);
        if (found == keys.end()) {
            std::vector<std::string> names;
            for (const auto& entry : keys) names.push_back(entry.first);
            CONTACT_THROW(InputError, "ContactSearchSettings: unknown key \"", key, "\"\n  where:    ", where, " › ", key,
                          "\n  expected: one of ", QuotedList(names), DidYouMean(key, names));
        }
        try {
            found->second(settings, value, where);
        } catch (const py::cast_error&) {
            CONTACT_THROW(InputError, "ContactSearchSettings: key \"", written, "\" has the wrong type (got ",
                          std::string(py::str(value.get_type())), ": ", std::string(py::repr(value)), ")",
                          "\n  where:    ", where, " › ", written);
        }
    }
}

/// Defaults overridden by @p values, validated; @p where names the block in the messages.
ContactSearchSettings FromDict(const py::dict& values, const std::string& where) {
    const std::string block = where.empty() ? "search_parameters" : where;
    ContactSearchSettings settings;
    Assign(settings, values, block);
    settings.Validate(block);
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
        .def(py::init([](const py::kwargs& kwargs) { return FromDict(kwargs, ""); }),
             "Defaults, overridden by keyword arguments (unknown keys raise InputError).")
        .def_static("from_dict", &FromDict, py::arg("values"), py::arg("where") = "",
                    "Settings from a dict or a search_parameters block (max_number_results, octree_search_parameters); "
                    "unknown keys, wrong types and values out of range raise InputError, located at where.")
        .def(
            "Validate", [](const ContactSearchSettings& self) { self.Validate(); }, "InputError for out-of-range values.");
    ForEachSearchSetting([&](const char* key, auto member) {
        using T = std::remove_reference_t<decltype(std::declval<ContactSearchSettings&>().*member)>;
        if constexpr (std::is_same_v<T, SearchTreeType>)
            settings.def_property(
                key, [member](const ContactSearchSettings& s) { return SearchTreeTypeName(s.*member); },
                [member](ContactSearchSettings& s, const std::string& v) { s.*member = ParseSearchTreeType(v); },
                "in_radius, in_box, in_radius_with_obb, in_box_with_obb, octree_with_obb (or InRadius, ...).");
        else if constexpr (std::is_same_v<T, CheckGap>)
            settings.def_property(
                key, [member](const ContactSearchSettings& s) { return CheckGapName(s.*member); },
                [member](ContactSearchSettings& s, const std::string& v) { s.*member = ParseCheckGap(v); },
                "no_check, direct_check, check_mapping (or NoCheck, DirectCheck, MappingCheck).");
        else
            settings.def_readwrite(key, member);
    });

    BindSearch(m);
    py::class_<MPCContactSearchProcess, ContactSearchProcess>(
        m, "MPCContactSearchProcess", "Contact search that also creates a ContactMasterSlaveConstraint per pair.")
        .def(py::init<ModelPart&, ContactSearchSettings, Properties::Pointer, bool>(), py::arg("main_model_part"),
             py::arg("settings"), py::arg("pair_properties") = nullptr, py::arg("resume") = false,
             py::keep_alive<1, 2>(),
             "As ContactSearchProcess; ConfigurationError at the first pair if the constraint is not registered.");
}

}  // namespace contact_app::bindings
