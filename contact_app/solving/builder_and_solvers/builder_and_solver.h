// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <vector>

#include "contact_app/kernel/model_part.h"
#include "contact_app/solving/builder_and_solvers/assembly_contributor.h"
#include "contact_app/solving/linear_solvers/linear_solver.h"
#include "contact_app/solving/schemes/scheme.h"
#include "contact_app/solving/system_types.h"

namespace contact_app {

/// Wall-clock seconds spent in each phase since construction (or ResetTimings).
struct BuilderAndSolverTimings {
    double setup = 0.0;     ///< DoF set, numbering and sparsity graph
    double build = 0.0;     ///< assembly of A and b (RHS-only assemblies included: BuildRHS, reactions)
    double solve = 0.0;     ///< the linear solves
    double scatter = 0.0;   ///< of build: adding the local systems into A and b
    double residual = 0.0;  ///< of build: the RHS-only assemblies
    std::size_t builds = 0;           ///< LHS + RHS builds
    std::size_t residual_builds = 0;  ///< RHS-only assemblies (BuildRHS, reactions)
    std::size_t solves = 0;
};

/// Assembles and solves the global system (Kratos BuilderAndSolver). Owns the DoF set, the
/// equation numbering and the sparsity graph: the graph is built once per DoF-set change and every
/// Build scatters into the existing compressed matrix.
///
/// Derived classes decide the numbering and how Dirichlet DoFs are treated:
/// BlockBuilderAndSolver keeps fixed DoFs in the system, EliminationBuilderAndSolver removes them.
/// Master–slave constraints are applied through a global relation matrix T (A ← TᵀAT, b ← Tᵀb,
/// Δx ← TΔx; docs/theory/structural.md §5); a constraint with a test relation W of its own
/// (MasterSlaveConstraint::CalculateTestRelation) makes it A ← WᵀAT, b ← Wᵀb.
class BuilderAndSolver {
public:
    using Pointer = std::shared_ptr<BuilderAndSolver>;

    /// @param linear_solver shared with the caller (not null)
    explicit BuilderAndSolver(LinearSolver::Pointer linear_solver);
    virtual ~BuilderAndSolver() = default;

    /// Collects the DoFs of the assembled elements, conditions and constraints, sorted by
    /// (node id, variable). @throws InputError if an entity lists a DoF its node does not have.
    virtual void SetUpDofSet(Scheme& rScheme, ModelPart& rModelPart);
    /// Numbers the equations (sets each DoF's equation id).
    virtual void SetUpSystem(ModelPart& rModelPart) = 0;
    /// Builds the sparsity graph and sizes A, Δx, b.
    virtual void ResizeAndInitializeVectors(Scheme& rScheme, SparseMatrixType& rA, SystemVectorType& rDx,
                                            SystemVectorType& rB, ModelPart& rModelPart);

    /// Assembles A and b from every assembled element and condition.
    virtual void Build(Scheme& rScheme, ModelPart& rModelPart, SparseMatrixType& rA, SystemVectorType& rB);
    virtual void BuildLHS(Scheme& rScheme, ModelPart& rModelPart, SparseMatrixType& rA);
    /// Assembles b only (no local LHS is computed) and zeroes its fixed-DoF entries (what residual criteria read).
    virtual void BuildRHS(Scheme& rScheme, ModelPart& rModelPart, SystemVectorType& rB);
    /// Applies the master–slave constraints of the model part (no-op without constraints).
    virtual void ApplyConstraints(Scheme& rScheme, ModelPart& rModelPart, SparseMatrixType& rA, SystemVectorType& rB);
    virtual void ApplyDirichletConditions(Scheme& rScheme, ModelPart& rModelPart, SparseMatrixType& rA,
                                          SystemVectorType& rDx, SystemVectorType& rB) = 0;
    /// Solves A Δx = b (Δx = 0 when ‖b‖ = 0).
    virtual void SystemSolve(SparseMatrixType& rA, SystemVectorType& rDx, SystemVectorType& rB);
    /// Build, constraints, Dirichlet, solve and, with constraints, Δx ← TΔx.
    virtual void BuildAndSolve(Scheme& rScheme, ModelPart& rModelPart, SparseMatrixType& rA, SystemVectorType& rDx,
                               SystemVectorType& rB);
    /// Writes −(assembled residual) to the reaction variable of the DoFs the builder reports on.
    virtual void CalculateReactions(Scheme& rScheme, ModelPart& rModelPart, SparseMatrixType& rA,
                                    SystemVectorType& rDx, SystemVectorType& rB) = 0;

    /// Called by strategies around each step; the base updates the constraint state.
    virtual void InitializeSolutionStep(ModelPart& rModelPart, SparseMatrixType& rA, SystemVectorType& rDx,
                                        SystemVectorType& rB);
    virtual void FinalizeSolutionStep(ModelPart& rModelPart, SparseMatrixType& rA, SystemVectorType& rDx,
                                      SystemVectorType& rB);
    /// Drops the DoF set and graph (rebuilt by the next SetUpDofSet) and the solver's factorisation.
    virtual void Clear();

    DofsArrayType& GetDofSet() { return mDofSet; }
    const DofsArrayType& GetDofSet() const { return mDofSet; }
    /// Number of equations of the assembled system.
    std::size_t GetEquationSystemSize() const { return mEquationSystemSize; }
    bool GetDofSetIsInitializedFlag() const { return mDofSetIsInitialized; }
    LinearSolver& GetLinearSolver() { return *mLinearSolver; }
    /// Equation ids touched by a master–slave constraint (masters and slaves), for residual norms.
    const std::vector<char>& ConstrainedEquations() const { return mConstrainedEquations; }
    virtual std::string Info() const = 0;
    const BuilderAndSolverTimings& Timings() const { return mTimings; }
    void ResetTimings() { mTimings = {}; }
    /// Adds tangent blocks beyond the entities' own (graph and every LHS build); kept until the builder dies.
    void AddAssemblyContributor(AssemblyContributor::Pointer contributor) {
        mContributors.push_back(std::move(contributor));
    }
    const std::vector<AssemblyContributor::Pointer>& AssemblyContributors() const { return mContributors; }

protected:
    /// Adds the local systems of every assembled element and condition into @p pA and/or @p pB (null: not built),
    /// equation ids ≥ @p size skipped; evaluated in parallel, summed in entity order (bit-identical for any thread
    /// count, docs/architecture.md "Threading model"). @throws the first failing entity's exception.
    void AssembleEntities(Scheme& rScheme, ModelPart& rModelPart, SparseMatrixType* pA, SystemVectorType* pB,
                          std::size_t size);
    /// Assembles the full residual of every DoF id < @p size into @p rResidual (no Dirichlet, no constraints).
    void AssembleResidual(Scheme& rScheme, ModelPart& rModelPart, SystemVectorType& rResidual, std::size_t size);

    DofsArrayType mDofSet;
    BuilderAndSolverTimings mTimings;
    std::size_t mEquationSystemSize = 0;
    bool mDofSetIsInitialized = false;

private:
    bool HasActiveConstraints(const ModelPart& rModelPart) const;
    void BuildRelationMatrix(ModelPart& rModelPart);
    /// The contributors' LHS blocks into @p rA (ids ≥ the system size skipped).
    void AssembleContributors(ModelPart& rModelPart, SparseMatrixType& rA);

    std::vector<AssemblyContributor::Pointer> mContributors;

    LinearSolver::Pointer mLinearSolver;
    SparseMatrixType mT;           // relation matrix of the last ApplyConstraints
    SparseMatrixType mW;           // test relation (only when a constraint has its own, else empty)
    bool mHasTestRelation = false;
    bool mConstraintsApplied = false;
    std::vector<char> mConstrainedEquations;
    std::vector<char> mIsSlave;
};

}  // namespace contact_app
