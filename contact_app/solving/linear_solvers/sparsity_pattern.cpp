// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/linear_solvers/sparsity_pattern.h"

#include <algorithm>
#include <cstddef>

namespace contact_app {

bool SparsityPattern::Matches(const SparseMatrixType& rA) const {
    const auto cols = static_cast<std::size_t>(rA.cols());
    const auto nnz = static_cast<std::size_t>(rA.nonZeros());
    if (mOuter.size() != cols + 1 || mInner.size() != nnz) return false;
    return std::equal(mOuter.begin(), mOuter.end(), rA.outerIndexPtr()) &&
           std::equal(mInner.begin(), mInner.end(), rA.innerIndexPtr());
}

void SparsityPattern::Assign(const SparseMatrixType& rA) {
    mOuter.assign(rA.outerIndexPtr(), rA.outerIndexPtr() + rA.cols() + 1);
    mInner.assign(rA.innerIndexPtr(), rA.innerIndexPtr() + rA.nonZeros());
}

void SparsityPattern::Clear() {
    mOuter.clear();
    mInner.clear();
}

}  // namespace contact_app
