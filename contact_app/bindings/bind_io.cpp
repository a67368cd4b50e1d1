// SPDX-License-Identifier: BSD-3-Clause
#include <string>

#include "contact_app/bindings/bindings.h"
#include "contact_app/io/model_part_checkpoint.h"
#include "contact_app/io/model_part_io.h"
#include "contact_app/kernel/model_part.h"

namespace contact_app::bindings {

void BindIO(py::module_& m) {
    py::class_<ModelPartIO>(m, "ModelPartIO", "Reader of Kratos .mdpa files (Kratos ModelPartIO, read side).")
        .def(py::init<std::string>(), py::arg("filename"), "Reader of filename, with or without the .mdpa extension.")
        .def("ReadModelPart", &ModelPartIO::ReadModelPart, py::arg("model_part"),
             py::call_guard<py::gil_scoped_release>(),
             "Reads the whole file into model_part; InputError on bad content.")
        .def("FileName", &ModelPartIO::FileName, "The resolved path of the file.");

    // Checkpoints (restart files): the bytes cross as Python bytes; the file itself is written by
    // contact_app.io.restart_utility (atomic replace).
    m.def(
        "SaveCheckpoint",
        [](const ModelPart& model_part) {
            std::string bytes;
            {
                py::gil_scoped_release release;
                bytes = ModelPartCheckpoint::Save(model_part);
            }
            return py::bytes(bytes);
        },
        py::arg("model_part"), "Checkpoint bytes (header + payload) of the root of model_part.");
    m.def(
        "LoadCheckpoint",
        [](ModelPart& model_part, const py::bytes& data, const std::string& source) {
            std::string bytes = data;
            py::gil_scoped_release release;
            ModelPartCheckpoint::Load(model_part, bytes, source);
        },
        py::arg("model_part"), py::arg("data"), py::arg("source"),
        "Rebuilds a checkpoint into model_part (an empty root of the saved name); InputError naming source if not "
        "intact or not matching, with model_part untouched.");
    m.def(
        "InspectCheckpoint",
        [](const py::bytes& data, const std::string& source) {
            const std::string bytes = data;
            const auto summary = ModelPartCheckpoint::Inspect(bytes, source);
            py::dict result;
            result["version"] = summary.version;
            result["payload_size"] = summary.payload_size;
            result["checksum"] = summary.checksum;
            result["model_part_name"] = summary.model_part_name;
            result["time"] = summary.time;
            result["step"] = summary.step;
            return result;
        },
        py::arg("data"), py::arg("source"),
        "Header, hash and first section of checkpoint bytes: version, sizes, model part name, TIME, STEP.");
    m.attr("CHECKPOINT_FORMAT_VERSION") = ModelPartCheckpoint::kFormatVersion;
}

}  // namespace contact_app::bindings
