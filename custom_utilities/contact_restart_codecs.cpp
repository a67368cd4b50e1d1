// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/contact_restart_codecs.h"

#include <cstdint>
#include <cstring>
#include <string>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/restart_pointer_codecs.h"
#include "custom_utilities/index_map.h"

namespace contact_app {
namespace {

// An IndexMap is stored as pairs of 64-bit ids (master id, pair condition id), in key order.
std::string SaveIndexMap(const std::shared_ptr<void>& value) {
    const auto& map = *std::static_pointer_cast<IndexMap>(value);
    std::string bytes;
    for (const auto& [master, pair] : map) {
        const std::uint64_t ids[2] = {master, pair};
        bytes.append(reinterpret_cast<const char*>(ids), sizeof(ids));
    }
    return bytes;
}

void LoadIndexMap(DataValueContainer& container, const std::string& bytes) {
    CONTACT_CHECK(bytes.size() % 16 == 0, InputError, "checkpoint: an INDEX_MAP of ", bytes.size(),
                  " bytes is not a list of id pairs\n  fix: load a checkpoint written by this contact_app version");
    auto map = std::make_shared<IndexMap>();
    for (std::size_t i = 0; i < bytes.size(); i += 16) {
        std::uint64_t ids[2];
        std::memcpy(ids, bytes.data() + i, sizeof(ids));
        map->AddId(ids[0]);
        map->SetNewEntityId(ids[0], ids[1]);
    }
    container.SetValue(INDEX_MAP, map);
}

}  // namespace

void RegisterContactRestartCodecs() {
    RegisterRestartPointerCodec(INDEX_MAP.Name(), RestartPointerCodec{SaveIndexMap, LoadIndexMap});
}

}  // namespace contact_app
