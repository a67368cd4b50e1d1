// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/solving/builder_and_solvers/builder_and_solver.h"

namespace contact_app {

/// Every DoF is an equation, fixed ones included (Kratos ResidualBasedBlockBuilderAndSolver).
/// Dirichlet rows keep their assembled diagonal with zero off-diagonals and b = 0, fixed columns
/// are zeroed, and empty rows get a unit diagonal, so Δx = 0 on fixed DoFs. Reactions are
/// written for every DoF.
class BlockBuilderAndSolver : public BuilderAndSolver {
public:
    using BuilderAndSolver::BuilderAndSolver;

    void SetUpSystem(ModelPart& rModelPart) override;
    void ApplyDirichletConditions(Scheme& rScheme, ModelPart& rModelPart, SparseMatrixType& rA,
                                  SystemVectorType& rDx, SystemVectorType& rB) override;
    void CalculateReactions(Scheme& rScheme, ModelPart& rModelPart, SparseMatrixType& rA, SystemVectorType& rDx,
                            SystemVectorType& rB) override;
    std::string Info() const override { return "block"; }
};

}  // namespace contact_app
