// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "contact_app/solving/system_types.h"

namespace contact_app {

class Dof;
class ModelPart;

/// Solves A x = b for the global system (Kratos LinearSolver). Direct solvers keep their
/// symbolic factorisation while the sparsity pattern of A is unchanged.
class LinearSolver {
public:
    using Pointer = std::shared_ptr<LinearSolver>;

    virtual ~LinearSolver() = default;
    /// @param[in] rA square system matrix @param[in,out] rX initial guess (iterative) / solution
    /// @param[in] rB right-hand side. @throws ConvergenceError if the solve fails (singular matrix,
    /// iteration limit), naming the solver and the reason.
    virtual void Solve(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) = 0;
    /// Forgets cached factorisations (the next Solve analyses the pattern again).
    virtual void Clear() {}
    /// The solver's own name, e.g. "umfpack".
    virtual std::string Info() const = 0;
    /// Number of symbolic analyses performed so far (a pattern-reuse diagnostic).
    virtual std::size_t NumberOfSymbolicAnalyses() const { return 0; }
    /// True when Solve needs to know which DoF each equation is (condensing solvers).
    virtual bool AdditionalPhysicalDataIsNeeded() const { return false; }
    /// The DoF set (equation id = position in the system) and the model part of the next Solve.
    virtual void ProvideAdditionalData(const std::vector<Dof*>& rDofSet, ModelPart& rModelPart) {}
};

}  // namespace contact_app
