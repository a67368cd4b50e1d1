// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "contact_app/solving/linear_solvers/linear_solver.h"

namespace contact_app {

/// Static condensation of the dual Lagrange multipliers of the active slave nodes (Kratos MixedULMLinearSolver,
/// docs/theory/condensation.md), on top of any inner solver.
///
/// Each free VECTOR_LAGRANGE_MULTIPLIER component λ_e of an ACTIVE SLAVE node is paired with the free DISPLACEMENT
/// component of the same node and direction (row s(e)). With the dual basis the coupling K_{s(e),e} is the only
/// multiplier entry of that row (D is diagonal), so the pair rows give λ_E = K_SE⁻¹ (r_S − K_S,R Δu_R), and the
/// remaining rows (every other equation, including the multiplier rows) form the reduced square system
///   (K_R,R − K_R,E K_SE⁻¹ K_S,R) Δu_R = r_R − K_R,E K_SE⁻¹ r_S,
/// solved with the inner solver; λ_E is recovered afterwards. This is the reference's reduction written over the
/// general row/unknown split (the reference's N | M | SI | SA blocks are its special case).
/// Scalar normal multipliers (ALMContactFrictionless) are condensed the same way, each paired with the displacement
/// row of its node where it couples most (the largest normal component); the reference condenses vector
/// multipliers only. When the inner solver wants the unknown layout (an AMG), each kept multiplier row takes the
/// place of its paired displacement row, so the reduced matrix keeps a displacement-sized diagonal.
/// Unlike the reference, the condensation is only used when it is exact: if a paired row couples to another
/// condensed multiplier beyond round-off (|K| > 1e-10 of its own coupling: a standard instead of a dual basis), or
/// no data were provided (systems with master–slave constraints), the full system goes to the inner solver
/// unchanged (reported by LastSolveWasCondensed()).
class MixedULMLinearSolver : public LinearSolver {
public:
    /// @param inner solver of the reduced (displacement-sized) system (not null)
    explicit MixedULMLinearSolver(LinearSolver::Pointer inner);

    void Solve(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) override;
    void Clear() override;
    std::string Info() const override;
    std::size_t NumberOfSymbolicAnalyses() const override { return mInner->NumberOfSymbolicAnalyses(); }
    /// The inner solver's figures, under this solver's name.
    LinearSolverStatistics Statistics() const override {
        LinearSolverStatistics statistics = mInner->Statistics();
        statistics.solver = Info();
        return statistics;
    }
    bool AdditionalPhysicalDataIsNeeded() const override { return true; }
    void ProvideAdditionalData(const std::vector<Dof*>& rDofSet, ModelPart& rModelPart) override;
    bool UnknownLayoutIsNeeded() const override { return mInner->UnknownLayoutIsNeeded(); }

    /// Whether the last Solve condensed the multipliers, and how many it condensed.
    bool LastSolveWasCondensed() const { return mLastCondensed; }
    std::size_t LastCondensedMultipliers() const { return mLastCondensedCount; }

private:
    LinearSolver::Pointer mInner;
    /// Solves the full system with the inner solver (handing it the full layout when it wants one).
    void SolveFull(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB);

    /// (multiplier equation, paired slave displacement equation) of the next solve; empty = no data.
    std::vector<std::pair<int, int>> mPairs;
    /// Scalar multipliers (LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) of active slave nodes and the free displacement
    /// equations of their node: paired in Solve with the row of the largest coupling (the normal's largest
    /// component).
    std::vector<std::pair<int, std::vector<int>>> mScalarCandidates;
    UnknownLayout mLayout;  // of the full system, when the inner solver wants one
    bool mHaveData = false;
    bool mLastCondensed = false;
    std::size_t mLastCondensedCount = 0;
};

}  // namespace contact_app
