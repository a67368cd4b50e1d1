// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/convergence_criteria/composite_criteria.h"

#include "contact_app/kernel/exceptions.h"

namespace contact_app {

CompositeCriteria::CompositeCriteria(Mode mode, ConvergenceCriteria::Pointer first, ConvergenceCriteria::Pointer second)
    : mMode(mode), mFirst(std::move(first)), mSecond(std::move(second)) {
    CONTACT_CHECK(mFirst && mSecond, InternalError, Info(), " needs two criteria");
}

void CompositeCriteria::Initialize(ModelPart& rModelPart) {
    mFirst->Initialize(rModelPart);
    mSecond->Initialize(rModelPart);
    mInitialized = true;
}

void CompositeCriteria::InitializeSolutionStep(ModelPart& rModelPart, DofsArrayType& rDofSet,
                                               const SparseMatrixType& rA, const SystemVectorType& rDx,
                                               const SystemVectorType& rB, const BuilderAndSolver& rBuilder) {
    mFirst->InitializeSolutionStep(rModelPart, rDofSet, rA, rDx, rB, rBuilder);
    mSecond->InitializeSolutionStep(rModelPart, rDofSet, rA, rDx, rB, rBuilder);
}

void CompositeCriteria::InitializePredictedResidual(DofsArrayType& rDofSet, const SystemVectorType& rB,
                                                    const BuilderAndSolver& rBuilder) {
    mFirst->InitializePredictedResidual(rDofSet, rB, rBuilder);
    mSecond->InitializePredictedResidual(rDofSet, rB, rBuilder);
}

void CompositeCriteria::FinalizeSolutionStep(ModelPart& rModelPart, DofsArrayType& rDofSet,
                                             const SparseMatrixType& rA, const SystemVectorType& rDx,
                                             const SystemVectorType& rB) {
    mFirst->FinalizeSolutionStep(rModelPart, rDofSet, rA, rDx, rB);
    mSecond->FinalizeSolutionStep(rModelPart, rDofSet, rA, rDx, rB);
}

bool CompositeCriteria::PreCriteria(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                                    const SystemVectorType& rDx, const SystemVectorType& rB) {
    const bool first = mFirst->PreCriteria(rModelPart, rDofSet, rA, rDx, rB);
    const bool second = mSecond->PreCriteria(rModelPart, rDofSet, rA, rDx, rB);
    return Combine(first, second);
}

bool CompositeCriteria::PostCriteria(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                                     const SystemVectorType& rDx, const SystemVectorType& rB,
                                     const BuilderAndSolver& rBuilder) {
    const bool first = mFirst->PostCriteria(rModelPart, rDofSet, rA, rDx, rB, rBuilder);
    const bool second = mSecond->PostCriteria(rModelPart, rDofSet, rA, rDx, rB, rBuilder);
    return Combine(first, second);
}

bool CompositeCriteria::GetActualizeRHSflag() const {
    return mFirst->GetActualizeRHSflag() || mSecond->GetActualizeRHSflag();
}

std::string CompositeCriteria::LastNorms() const { return mFirst->LastNorms() + "; " + mSecond->LastNorms(); }

}  // namespace contact_app
