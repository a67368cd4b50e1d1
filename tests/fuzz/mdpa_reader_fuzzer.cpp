// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target for the .mdpa reader (ModelPartIO): any bytes must end in success or in an
// InputError that names the file. Any other exception, a crash, a sanitizer report or a hang (libFuzzer's
// -timeout) is a finding. Built only with -DCONTACT_APP_BUILD_FUZZ=ON and clang (docs/running.md, "Fuzzing").
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <typeinfo>

#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/io/model_part_io.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/model.h"

namespace {

/// The file each input is written to (one per process: libFuzzer workers run in separate processes).
const std::string& InputPath() {
    static const std::string path = "/tmp/contact_app_mdpa_fuzz_" + std::to_string(getpid()) + ".mdpa";
    return path;
}

[[noreturn]] void Finding(const char* kind, const std::string& what) {
    std::fprintf(stderr, "\nFINDING: %s escaped the .mdpa reader:\n%s\n", kind, what.c_str());
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const bool registered = (contact_app::RegisterContactApplication(), true);
    (void)registered;
    {
        std::ofstream file(InputPath(), std::ios::binary | std::ios::trunc);
        file.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    contact_app::Model model;
    contact_app::ModelPart& part = model.CreateModelPart("Structure", 2);
    // The historical variables a structural contact case stores, so that NodalData blocks reach their values.
    for (const contact_app::VariableData* variable :
         {static_cast<const contact_app::VariableData*>(&contact_app::DISPLACEMENT),
          static_cast<const contact_app::VariableData*>(&contact_app::REACTION),
          static_cast<const contact_app::VariableData*>(&contact_app::VELOCITY),
          static_cast<const contact_app::VariableData*>(&contact_app::NORMAL),
          static_cast<const contact_app::VariableData*>(&contact_app::NODAL_H),
          static_cast<const contact_app::VariableData*>(&contact_app::WEIGHTED_GAP)})
        part.AddNodalSolutionStepVariable(*variable);
    try {
        contact_app::ModelPartIO(InputPath()).ReadModelPart(part);
    } catch (const contact_app::InputError& error) {
        const std::string what = error.what();
        if (what.find(InputPath()) == std::string::npos) Finding("an InputError without the file name", what);
    } catch (const std::exception& error) {
        Finding(typeid(error).name(), error.what());
    }
    return 0;
}
