// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <vector>

#include "contact_app/kernel/variable_data.h"

namespace contact_app {

/// Layout of the historical (solution-step) data of the nodes of one root model part:
/// which variables are stored and at which offset (in doubles) of a node's per-step block.
/// Offsets never change once assigned, so adding a variable only appends to the block.
class VariablesList {
public:
    using Pointer = std::shared_ptr<VariablesList>;

    /// Appends @p variable (a component adds its 3-vector). No-op if already present.
    /// @throws InputError if the variable kind cannot be stored historically.
    void Add(const VariableData& variable);
    bool Has(const VariableData& variable) const;
    /// Offset of @p variable (of its component, for DISPLACEMENT_X) in a step block.
    /// @throws InputError if the variable is not in the list.
    std::size_t Offset(const VariableData& variable) const {
        const std::size_t key = variable.Key();
        if (key < mOffsets.size() && mOffsets[key] >= 0) return static_cast<std::size_t>(mOffsets[key]);
        return MissingOffset(variable);
    }
    /// Number of doubles in one step block.
    std::size_t DataSize() const { return mDataSize; }
    const std::vector<const VariableData*>& Variables() const { return mVariables; }

private:
    std::size_t MissingOffset(const VariableData& variable) const;

    std::vector<long> mOffsets;  // by variable key; -1 = absent; components get source offset + index
    std::vector<const VariableData*> mVariables;
    std::size_t mDataSize = 0;
};

}  // namespace contact_app
