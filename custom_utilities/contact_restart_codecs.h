// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace contact_app {

/// @brief Registers the checkpoint codecs of the contact pointer variables (INDEX_MAP: the pairs of a slave face,
///        master id → pair condition id) with RegisterRestartPointerCodec. Idempotent.
void RegisterContactRestartCodecs();

}  // namespace contact_app
