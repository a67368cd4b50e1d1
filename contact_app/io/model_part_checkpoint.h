// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace contact_app {

class ModelPart;

/// Checkpoint of a whole root model part (the restart file of Kratos' FileSerializer), in contact_app's own
/// versioned binary format: a 32-byte header — magic "\x89CAREST\n", u32 format version, u32 header size,
/// u64 payload size, u64 payload hash (Hash()) — then the payload: the model part tree (names, flags, values,
/// membership), the historical variables by name, the nodes (coordinates, flags, values, every buffer step,
/// DoFs with fixity, reaction and equation id), properties with their tables, shared geometries (pairs keep
/// their slave and master faces), elements and conditions (registered name, properties, values and the
/// Entity::Save state), master-slave constraints and the ProcessInfo. Pointer values are stored through
/// RestartPointerCodec (contact_app/kernel/restart_pointer_codecs.h). Native byte order (little endian).
/// Format and guarantees: docs/running.md, "Restart and checkpoints".
class ModelPartCheckpoint {
public:
    static constexpr std::uint32_t kFormatVersion = 3;  ///< 2: constraints store their test relation; 3: MPC pairs
                                                        ///< store their start-of-step operators as the Coulomb families
    static constexpr std::size_t kHeaderSize = 32;

    /// What the header and the first payload section say (Inspect()).
    struct Summary {
        std::uint32_t version = 0;
        std::uint64_t payload_size = 0;
        std::uint64_t checksum = 0;
        std::string model_part_name;
        double time = 0.0;
        long long step = 0;
    };

    /// @brief The checkpoint bytes (header + payload) of the root of @p model_part.
    /// @throws ConfigurationError for a value the format cannot store (a pointer variable without codec)
    static std::string Save(const ModelPart& model_part);
    /// @brief Rebuilds the saved model part into @p model_part, an empty root of the same name (variables may
    ///        be declared). Everything is decoded and checked before @p model_part is modified.
    /// @param[in,out] model_part the empty root model part that receives the checkpoint
    /// @param[in] bytes the checkpoint bytes, as Save() wrote them
    /// @param[in] source the file name, for messages
    /// @throws InputError naming @p source for a short, corrupt, foreign, other-version or mismatched checkpoint
    static void Load(ModelPart& model_part, const std::string& bytes, const std::string& source);
    /// @brief Checks the header and the hash and reads the first section (name, TIME, STEP).
    /// @throws InputError as Load()
    static Summary Inspect(const std::string& bytes, const std::string& source);
    /// @brief The 64-bit payload hash of the header (word-wise multiply-rotate, full avalanche at the end).
    static std::uint64_t Hash(const char* data, std::size_t size);
};

}  // namespace contact_app
