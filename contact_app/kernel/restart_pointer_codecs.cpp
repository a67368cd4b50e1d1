// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/restart_pointer_codecs.h"

#include <map>

namespace contact_app {
namespace {

std::map<std::string, RestartPointerCodec>& Codecs() {
    static std::map<std::string, RestartPointerCodec> codecs;
    return codecs;
}

}  // namespace

void RegisterRestartPointerCodec(const std::string& variable_name, RestartPointerCodec codec) {
    Codecs()[variable_name] = std::move(codec);
}

const RestartPointerCodec* FindRestartPointerCodec(const std::string& variable_name) {
    const auto found = Codecs().find(variable_name);
    return found == Codecs().end() ? nullptr : &found->second;
}

}  // namespace contact_app
