// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "contact_app/solving/linear_solvers/linear_solver.h"
#include "contact_app/solving/linear_solvers/sparsity_pattern.h"

namespace contact_app {

/// The direct factorisations: UMFPACK (unsymmetric LU, the default, called directly), and through
/// Eigen's interfaces CHOLMOD (supernodal Cholesky, SPD only), KLU (LU for small and repeated
/// systems) and Eigen's own SparseLU.
enum class DirectSolverKind { UmfPack, Cholmod, Klu, SparseLU };

/// Fill-reducing ordering of UMFPACK's symbolic analysis (linear_solver_settings.ordering).
/// Auto: METIS (nested dissection) from kAutoMetisMinimumSize equations on, AMD below.
enum class FillReducingOrdering { Auto, Amd, Metis };

/// Systems with at least this many equations get METIS under "auto" (docs/architecture.md has the
/// measured crossover on the Hertz examples).
inline constexpr std::size_t kAutoMetisMinimumSize = 5000;

/// "auto", "amd" or "metis" → the ordering. @throws InputError naming linear_solver_settings.ordering.
FillReducingOrdering ParseFillReducingOrdering(const std::string& name);
/// The setting's name ("auto", "amd", "metis").
const char* FillReducingOrderingName(FillReducingOrdering ordering);
/// The accepted ordering names, sorted.
std::vector<std::string> FillReducingOrderingNames();

/// A direct solver that re-uses its symbolic analysis while the matrix pattern is unchanged and
/// only refactorises numerically.
class DirectSolver : public LinearSolver {
public:
    explicit DirectSolver(DirectSolverKind kind, FillReducingOrdering ordering = FillReducingOrdering::Auto);
    ~DirectSolver() override;

    void Solve(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) override;
    void Clear() override;
    std::string Info() const override;
    std::size_t NumberOfSymbolicAnalyses() const override { return mAnalyses; }
    LinearSolverStatistics Statistics() const override;

private:
    struct Backend;
    struct Umfpack;
    void SolveWithUmfpack(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB, bool analyse);

    DirectSolverKind mKind;
    FillReducingOrdering mOrdering;
    std::unique_ptr<Backend> mBackend;
    SparsityPattern mPattern;  // of the last analysed matrix
    std::size_t mAnalyses = 0;
    LinearSolverStatistics mStatistics;
};

}  // namespace contact_app
