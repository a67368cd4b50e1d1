// SPDX-License-Identifier: BSD-3-Clause
#include <string>

#include "contact_app/bindings/bindings.h"
#include "contact_app/io/model_part_io.h"

namespace contact_app::bindings {

void BindIO(py::module_& m) {
    py::class_<ModelPartIO>(m, "ModelPartIO", "Reader of Kratos .mdpa files (Kratos ModelPartIO, read side).")
        .def(py::init<std::string>(), py::arg("filename"), "Reader of filename, with or without the .mdpa extension.")
        .def("ReadModelPart", &ModelPartIO::ReadModelPart, py::arg("model_part"),
             py::call_guard<py::gil_scoped_release>(),
             "Reads the whole file into model_part; InputError on bad content.")
        .def("FileName", &ModelPartIO::FileName, "The resolved path of the file.");
}

}  // namespace contact_app::bindings
