// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/builder_and_solvers/block_builder_and_solver.h"

namespace contact_app {

void BlockBuilderAndSolver::SetUpSystem(ModelPart&) {
    for (std::size_t i = 0; i < mDofSet.size(); ++i) mDofSet[i]->SetEquationId(i);
    mEquationSystemSize = mDofSet.size();
}

void BlockBuilderAndSolver::ApplyDirichletConditions(Scheme&, ModelPart&, SparseMatrixType& rA, SystemVectorType&,
                                                     SystemVectorType& rB) {
    const std::size_t n = mEquationSystemSize;
    std::vector<char> fixed(n, 0);
    for (const Dof* dof : mDofSet)
        if (dof->IsFixed() && dof->EquationId() < n) fixed[dof->EquationId()] = 1;
    std::vector<char> row_has_entry(n, 0);
    for (int j = 0; j < rA.outerSize(); ++j) {
        for (SparseMatrixType::InnerIterator entry(rA, j); entry; ++entry) {
            const auto i = static_cast<std::size_t>(entry.row());
            if (i != static_cast<std::size_t>(j) && (fixed[i] || fixed[static_cast<std::size_t>(j)])) entry.valueRef() = 0.0;
            if (entry.value() != 0.0) row_has_entry[i] = 1;
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (fixed[i]) rB[static_cast<Eigen::Index>(i)] = 0.0;
        if (!row_has_entry[i]) {
            rA.coeffRef(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i)) = 1.0;
            rB[static_cast<Eigen::Index>(i)] = 0.0;
        }
    }
}

void BlockBuilderAndSolver::CalculateReactions(Scheme& rScheme, ModelPart& rModelPart, SparseMatrixType&,
                                               SystemVectorType&, SystemVectorType&) {
    SystemVectorType residual;
    AssembleResidual(rScheme, rModelPart, residual, mEquationSystemSize);
    for (Dof* dof : mDofSet)
        if (dof->HasReaction()) dof->GetSolutionStepReactionValue() = -residual[static_cast<Eigen::Index>(dof->EquationId())];
}

}  // namespace contact_app
