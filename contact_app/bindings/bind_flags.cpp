// SPDX-License-Identifier: BSD-3-Clause
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "contact_app/bindings/bindings.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/flags.h"

namespace contact_app::bindings {

namespace {

/// "Flags(ACTIVE, SLIP=False)": the named flags defined in @p flags with their values.
std::string FlagsRepr(const Flags& flags) {
    std::string text;
    for (const NamedFlag& entry : RegisteredFlags()) {
        if (!flags.IsDefined(entry.flag)) continue;
        text += (text.empty() ? "" : ", ") + std::string(entry.name) + (flags.Is(entry.flag) ? "" : "=False");
    }
    return "Flags(" + text + ")";
}

}  // namespace

void BindFlags(py::module_& m) {
    // shared_ptr holder: Node, ProcessInfo, Element, ... derive from Flags and are held by shared_ptr.
    // The derived classes are bound with py::multiple_inheritance(): Flags is not always at offset 0
    // (it follows the vtable pointer of Element, Condition, MasterSlaveConstraint), so pybind11 must
    // use the registered static casts instead of reinterpreting the pointer.
    py::class_<Flags, std::shared_ptr<Flags>>(m, "Flags", "Up to 64 tri-state flags (Kratos Flags).")
        .def(py::init<>(), "All flags undefined.")
        .def("Is", &Flags::Is, py::arg("flag"), "True if every bit defined in flag has the value flag gives it.")
        .def("IsNot", &Flags::IsNot, py::arg("flag"), "not Is(flag).")
        .def("IsDefined", &Flags::IsDefined, py::arg("flag"), "True if every bit of flag is defined here.")
        .def("IsNotDefined", &Flags::IsNotDefined, py::arg("flag"), "not IsDefined(flag).")
        .def("Set", &Flags::Set, py::arg("flag"), py::arg("value") = true, "Defines the bits of flag with value.")
        .def("Reset", &Flags::Reset, py::arg("flag"), "Makes the bits of flag undefined again.")
        .def("Flip", &Flags::Flip, py::arg("flag"), "Negates (and defines) the bits of flag.")
        .def("Clear", &Flags::Clear, "Makes every flag undefined.")
        .def("AsFalse", &Flags::AsFalse, "The same bits, defined and reset.")
        .def("__or__", &Flags::operator|, py::is_operator(), "Union of the defined bits.")
        .def("__eq__", &Flags::operator==, py::is_operator(), "Same defined bits with the same values.")
        .def(
            "__hash__",
            [](const Flags& self) { return std::hash<std::uint64_t>()(self.DefinedBits() * 31 ^ self.ValueBits()); },
            "Hash of the bits.")
        .def("__repr__", &FlagsRepr, "Flags(ACTIVE, SLIP=False).");

    for (const NamedFlag& entry : RegisteredFlags()) m.attr(entry.name) = entry.flag;
    m.def(
        "registered_flags",
        [] {
            py::list names;
            for (const NamedFlag& entry : RegisteredFlags()) names.append(entry.name);
            return names;
        },
        "Names of every named flag, in bit order.");
    m.def(
        "get_flag",
        [](const std::string& name) {
            try {
                return GetFlag(name);
            } catch (const InputError& error) {
                throw py::key_error(error.what());
            }
        },
        py::arg("name"), "The flag called name; KeyError (with a suggestion) for an unknown name.");
}

}  // namespace contact_app::bindings
