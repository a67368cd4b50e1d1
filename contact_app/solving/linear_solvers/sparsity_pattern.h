// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "contact_app/solving/system_types.h"

namespace contact_app {

/// The compressed-column pattern of the last analysed matrix: a direct solver keeps its symbolic
/// analysis while the next matrix has the same pattern (same column starts and row indices).
class SparsityPattern {
public:
    /// True when rA (compressed) has the kept pattern.
    bool Matches(const SparseMatrixType& rA) const;
    /// Keeps the pattern of rA (compressed).
    void Assign(const SparseMatrixType& rA);
    void Clear();

private:
    std::vector<int> mOuter;
    std::vector<int> mInner;
};

}  // namespace contact_app
