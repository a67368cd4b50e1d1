// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "contact_app/kernel/model_part.h"

namespace contact_app {

/// Reader of Kratos `.mdpa` files (Kratos ModelPartIO, read side).
///
/// Grammar (docs/input_layer.md §5): `Begin <Block> [args]` … `End <Block>` with
/// ModelPartData, Properties (with nested Table), Table, Nodes, Geometries, Elements, Conditions,
/// Constraints, NodalData, ElementalData, ConditionalData and nested SubModelPart blocks;
/// `//` comments anywhere. Every error is an InputError naming the file, the line and what was expected.
class ModelPartIO {
public:
    /// @param filename path with or without the `.mdpa` extension (Kratos passes it without).
    explicit ModelPartIO(std::string filename);

    /// Reads the whole file into @p rModelPart (normally an empty root model part).
    /// @throws InputError for a missing file or malformed content.
    void ReadModelPart(ModelPart& rModelPart);

    /// The resolved path of the file read.
    const std::string& FileName() const { return mFileName; }

private:
    std::string mFileName;
};

}  // namespace contact_app
