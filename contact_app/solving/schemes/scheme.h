// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>

#include "contact_app/kernel/condition.h"
#include "contact_app/kernel/element.h"
#include "contact_app/kernel/model_part.h"
#include "contact_app/solving/system_types.h"

namespace contact_app {

using DofsArrayType = std::vector<Dof*>;

/// Time integration (Kratos Scheme): turns element and condition local systems into the
/// contributions of one Newton iteration, predicts a step and updates the unknowns from Δx.
/// The base class is the incremental static scheme (ResidualBasedIncrementalUpdateStaticScheme):
/// contributions are the entities' own local systems; Update adds Δx to the free DoFs.
class Scheme {
public:
    using Pointer = std::shared_ptr<Scheme>;

    virtual ~Scheme() = default;

    /// Calls Initialize on the elements, conditions and constraints (once per analysis).
    virtual void Initialize(ModelPart& rModelPart);
    virtual void InitializeSolutionStep(ModelPart& rModelPart, SparseMatrixType& rA, SystemVectorType& rDx,
                                        SystemVectorType& rB);
    virtual void FinalizeSolutionStep(ModelPart& rModelPart, SparseMatrixType& rA, SystemVectorType& rDx,
                                      SystemVectorType& rB);
    virtual void InitializeNonLinIteration(ModelPart& rModelPart, SparseMatrixType& rA, SystemVectorType& rDx,
                                           SystemVectorType& rB);
    virtual void FinalizeNonLinIteration(ModelPart& rModelPart, SparseMatrixType& rA, SystemVectorType& rDx,
                                         SystemVectorType& rB);
    /// Predicts the unknowns of the new step (static: nothing).
    virtual void Predict(ModelPart& rModelPart, DofsArrayType& rDofSet, SparseMatrixType& rA, SystemVectorType& rDx,
                         SystemVectorType& rB);
    /// Predicts only what the step prescribes (DoFs whose velocity or acceleration is fixed) and keeps every free
    /// DoF at its last converged value, the derivatives following (static: nothing). The contact strategies predict
    /// so: extrapolating a body that is about to touch or slide pushes it through the contact surface.
    virtual void PredictPrescribed(ModelPart& rModelPart);
    /// u += Δx on every free DoF (Δx indexed by equation id).
    virtual void Update(ModelPart& rModelPart, DofsArrayType& rDofSet, SparseMatrixType& rA, SystemVectorType& rDx,
                        SystemVectorType& rB);

    /// Local LHS and RHS of an element or condition for this iteration, with its equation ids.
    virtual void CalculateSystemContributions(Element& rElement, Matrix& rLHS, Vector& rRHS,
                                              EquationIdVectorType& rEquationIds, const ProcessInfo& rProcessInfo);
    virtual void CalculateSystemContributions(Condition& rCondition, Matrix& rLHS, Vector& rRHS,
                                              EquationIdVectorType& rEquationIds, const ProcessInfo& rProcessInfo);
    virtual void CalculateRHSContribution(Element& rElement, Vector& rRHS, EquationIdVectorType& rEquationIds,
                                          const ProcessInfo& rProcessInfo);
    virtual void CalculateRHSContribution(Condition& rCondition, Vector& rRHS, EquationIdVectorType& rEquationIds,
                                          const ProcessInfo& rProcessInfo);
    virtual void CalculateLHSContribution(Element& rElement, Matrix& rLHS, EquationIdVectorType& rEquationIds,
                                          const ProcessInfo& rProcessInfo);
    virtual void CalculateLHSContribution(Condition& rCondition, Matrix& rLHS, EquationIdVectorType& rEquationIds,
                                          const ProcessInfo& rProcessInfo);

    /// Runs the entities' Check. @throws InputError from the first failing entity.
    virtual int Check(const ModelPart& rModelPart) const;
    virtual std::string Info() const { return "static"; }
};

/// True for entities taking part in the assembly: ACTIVE undefined or set.
template <class TEntity>
bool IsAssembled(const TEntity& rEntity) {
    return rEntity.IsNotDefined(ACTIVE) || rEntity.Is(ACTIVE);
}

}  // namespace contact_app
