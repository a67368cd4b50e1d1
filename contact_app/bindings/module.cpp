// SPDX-License-Identifier: BSD-3-Clause
#include <pybind11/pybind11.h>

#include "contact_app/application.h"
#include "contact_app/bindings/bindings.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/inverted_element_error.h"

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

/// InvertedElementError(ConvergenceError) with attributes element_id (0: unknown), quantity ("det J"/"det F"),
/// value and time (NaN: unknown). Registered after ConvergenceError, so its translator is tried first.
void BindInvertedElementError(py::module_& m) {
    static py::handle error_type;  // the class lives as long as the module holds it
    py::object base = m.attr("ConvergenceError");
    error_type = py::handle(PyErr_NewException("contact_app.InvertedElementError", base.ptr(), nullptr));
    m.attr("InvertedElementError") = py::reinterpret_borrow<py::object>(error_type);
    error_type.attr("__doc__") = "An element or law met det J <= 0 or det F <= 0 inside a Newton iteration "
                                 "(attributes: element_id, quantity, value, time).";
    py::register_exception_translator([](std::exception_ptr error) {
        try {
            if (error) std::rethrow_exception(error);
        } catch (const InvertedElementError& inverted) {
            py::object instance = error_type(inverted.what());
            instance.attr("element_id") = inverted.ElementId();
            instance.attr("quantity") = inverted.Quantity();
            instance.attr("value") = inverted.Value();
            instance.attr("time") = inverted.Time();
            PyErr_SetObject(error_type.ptr(), instance.ptr());
        }
    });
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
    BindInvertedElementError(m);
}

}  // namespace contact_app::bindings

PYBIND11_MODULE(_core, m) {
    using namespace contact_app::bindings;
    m.doc() = "Compiled core of contact_app (private: import contact_app instead).";
    contact_app::RegisterContactApplication();
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
