// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/builder_and_solvers/elimination_builder_and_solver.h"

namespace contact_app {

void EliminationBuilderAndSolver::SetUpSystem(ModelPart&) {
    std::size_t next_free = 0;
    for (Dof* dof : mDofSet)
        if (dof->IsFree()) dof->SetEquationId(next_free++);
    mEquationSystemSize = next_free;
    std::size_t next_fixed = next_free;
    for (Dof* dof : mDofSet)
        if (dof->IsFixed()) dof->SetEquationId(next_fixed++);
}

void EliminationBuilderAndSolver::ApplyDirichletConditions(Scheme&, ModelPart&, SparseMatrixType& rA,
                                                           SystemVectorType&, SystemVectorType& rB) {
    // Fixed DoFs are not in the system; only equations nothing contributes to need a diagonal.
    const Eigen::VectorXd diagonal = rA.diagonal();
    for (Eigen::Index i = 0; i < rA.rows(); ++i) {
        if (diagonal[i] == 0.0 && rA.col(i).cwiseAbs().sum() == 0.0) {
            rA.coeffRef(i, i) = 1.0;
            rB[i] = 0.0;
        }
    }
}

void EliminationBuilderAndSolver::CalculateReactions(Scheme& rScheme, ModelPart& rModelPart, SparseMatrixType&,
                                                     SystemVectorType&, SystemVectorType&) {
    SystemVectorType residual;
    AssembleResidual(rScheme, rModelPart, residual, mDofSet.size());
    const auto& constrained = ConstrainedEquations();
    for (Dof* dof : mDofSet) {
        const std::size_t id = dof->EquationId();
        const bool slave = id < constrained.size() && constrained[id];
        if (dof->HasReaction() && (dof->IsFixed() || slave))
            dof->GetSolutionStepReactionValue() = -residual[static_cast<Eigen::Index>(id)];
    }
}

}  // namespace contact_app
