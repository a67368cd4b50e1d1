// SPDX-License-Identifier: BSD-3-Clause
#include <pybind11/pybind11.h>

#include "contact_app/application.h"
#include "custom_conditions/contact_condition_registration.h"
#include "custom_strategies/contact_master_slave_constraint.h"
#include "custom_utilities/contact_restart_codecs.h"
#include "contact_app/bindings/bindings.h"
#include "contact_app/kernel/exceptions.h"

namespace py = pybind11;

namespace contact_app::bindings {

namespace {

/// Registers a C++ exception type as a Python exception class of the public package.
template <class TError>
void RegisterError(py::module_& m, const char* name, py::handle base, const char* doc) {
    auto& error = py::register_exception<TError>(m, name, base);
    error.attr("__module__") = "contact_app";
    error.attr("__doc__") = doc;
}

}  // namespace

void BindExceptions(py::module_& m) {
    RegisterError<InputError>(m, "InputError", PyExc_ValueError,
                              "Bad user input: JSON, mesh files, properties, names.");
    RegisterError<ConfigurationError>(m, "ConfigurationError", PyExc_Exception, "Options that cannot be combined.");
    RegisterError<ConvergenceError>(m, "ConvergenceError", PyExc_RuntimeError,
                                    "A non-linear or linear solve that did not converge.");
    RegisterError<InternalError>(m, "InternalError", PyExc_RuntimeError,
                                 "A broken internal invariant: a bug in contact_app.");
}

}  // namespace contact_app::bindings

PYBIND11_MODULE(_core, m) {
    using namespace contact_app::bindings;
    m.doc() = "Compiled core of contact_app (private: import contact_app instead).";
    contact_app::RegisterContactApplication();
    contact_app::RegisterContactConditions();  // not in RegisterContactApplication: avoids a library cycle
    contact_app::RegisterContactMasterSlaveConstraints();
    contact_app::RegisterContactRestartCodecs();
    BindExceptions(m);
    BindVariables(m);
    BindFlags(m);
    BindProperties(m);
    BindNode(m);
    BindGeometries(m);
    BindEntities(m);
    BindModelPart(m);
    BindIO(m);
    BindRegistry(m);
    BindUtilities(m);
    BindSolving(m);
    BindContact(m);
    BindContactProcesses(m);
    BindContactSearch(m);
    BindContactStrategies(m);
    BindMPCContact(m);
}
