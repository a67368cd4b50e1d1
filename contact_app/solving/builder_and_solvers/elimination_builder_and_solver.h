// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/solving/builder_and_solvers/builder_and_solver.h"

namespace contact_app {

/// Only free DoFs are equations (Kratos ResidualBasedEliminationBuilderAndSolver): free DoFs are
/// numbered 0..n_free−1, fixed ones after them and are skipped during assembly. Reactions are
/// written for fixed DoFs (and constraint slaves).
class EliminationBuilderAndSolver : public BuilderAndSolver {
public:
    using BuilderAndSolver::BuilderAndSolver;

    void SetUpSystem(ModelPart& rModelPart) override;
    void ApplyDirichletConditions(Scheme& rScheme, ModelPart& rModelPart, SparseMatrixType& rA,
                                  SystemVectorType& rDx, SystemVectorType& rB) override;
    void CalculateReactions(Scheme& rScheme, ModelPart& rModelPart, SparseMatrixType& rA, SystemVectorType& rDx,
                            SystemVectorType& rB) override;
    std::string Info() const override { return "elimination"; }
};

}  // namespace contact_app
