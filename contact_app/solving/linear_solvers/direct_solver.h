// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "contact_app/solving/linear_solvers/linear_solver.h"

namespace contact_app {

/// The direct factorisations available through Eigen: UMFPACK (unsymmetric LU, the default),
/// CHOLMOD (supernodal Cholesky, SPD only), KLU (LU for small and repeated systems) and Eigen's
/// own SparseLU.
enum class DirectSolverKind { UmfPack, Cholmod, Klu, SparseLU };

/// A direct solver that re-uses its symbolic analysis while the matrix pattern is unchanged and
/// only refactorises numerically.
class DirectSolver : public LinearSolver {
public:
    explicit DirectSolver(DirectSolverKind kind);
    ~DirectSolver() override;

    void Solve(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) override;
    void Clear() override;
    std::string Info() const override;
    std::size_t NumberOfSymbolicAnalyses() const override { return mAnalyses; }

private:
    struct Backend;
    bool PatternChanged(const SparseMatrixType& rA) const;

    DirectSolverKind mKind;
    std::unique_ptr<Backend> mBackend;
    std::vector<int> mOuter;  // pattern of the last analysed matrix
    std::vector<int> mInner;
    std::size_t mAnalyses = 0;
};

}  // namespace contact_app
