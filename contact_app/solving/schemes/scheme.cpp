// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/schemes/scheme.h"

namespace contact_app {

namespace {

/// Calls @p hook(entity) on every element, condition and constraint of @p rModelPart.
template <class THook>
void ForEachEntity(ModelPart& rModelPart, THook hook) {
    for (const auto& element : rModelPart.Elements()) hook(*element);
    for (const auto& condition : rModelPart.Conditions()) hook(*condition);
    for (const auto& constraint : rModelPart.MasterSlaveConstraints()) hook(*constraint);
}

}  // namespace

void Scheme::Initialize(ModelPart& rModelPart) {
    const ProcessInfo& info = rModelPart.GetProcessInfo();
    ForEachEntity(rModelPart, [&](auto& entity) { entity.Initialize(info); });
}

void Scheme::InitializeSolutionStep(ModelPart& rModelPart, SparseMatrixType&, SystemVectorType&, SystemVectorType&) {
    const ProcessInfo& info = rModelPart.GetProcessInfo();
    ForEachEntity(rModelPart, [&](auto& entity) { entity.InitializeSolutionStep(info); });
}

void Scheme::FinalizeSolutionStep(ModelPart& rModelPart, SparseMatrixType&, SystemVectorType&, SystemVectorType&) {
    const ProcessInfo& info = rModelPart.GetProcessInfo();
    ForEachEntity(rModelPart, [&](auto& entity) { entity.FinalizeSolutionStep(info); });
}

void Scheme::InitializeNonLinIteration(ModelPart& rModelPart, SparseMatrixType&, SystemVectorType&,
                                       SystemVectorType&) {
    const ProcessInfo& info = rModelPart.GetProcessInfo();
    ForEachEntity(rModelPart, [&](auto& entity) { entity.InitializeNonLinearIteration(info); });
}

void Scheme::FinalizeNonLinIteration(ModelPart& rModelPart, SparseMatrixType&, SystemVectorType&, SystemVectorType&) {
    const ProcessInfo& info = rModelPart.GetProcessInfo();
    ForEachEntity(rModelPart, [&](auto& entity) { entity.FinalizeNonLinearIteration(info); });
}

void Scheme::Predict(ModelPart&, DofsArrayType&, SparseMatrixType&, SystemVectorType&, SystemVectorType&) {}

void Scheme::PredictPrescribed(ModelPart&) {}

void Scheme::Update(ModelPart&, DofsArrayType& rDofSet, SparseMatrixType&, SystemVectorType& rDx, SystemVectorType&) {
    for (Dof* dof : rDofSet)
        if (dof->IsFree()) dof->GetSolutionStepValue() += rDx[static_cast<Eigen::Index>(dof->EquationId())];
}

void Scheme::CalculateSystemContributions(Element& rElement, Matrix& rLHS, Vector& rRHS,
                                          EquationIdVectorType& rEquationIds, const ProcessInfo& rProcessInfo) {
    rElement.CalculateLocalSystem(rLHS, rRHS, rProcessInfo);
    rElement.EquationIdVector(rEquationIds, rProcessInfo);
}

void Scheme::CalculateSystemContributions(Condition& rCondition, Matrix& rLHS, Vector& rRHS,
                                          EquationIdVectorType& rEquationIds, const ProcessInfo& rProcessInfo) {
    rCondition.CalculateLocalSystem(rLHS, rRHS, rProcessInfo);
    rCondition.EquationIdVector(rEquationIds, rProcessInfo);
}

void Scheme::CalculateRHSContribution(Element& rElement, Vector& rRHS, EquationIdVectorType& rEquationIds,
                                      const ProcessInfo& rProcessInfo) {
    rElement.CalculateRightHandSide(rRHS, rProcessInfo);
    rElement.EquationIdVector(rEquationIds, rProcessInfo);
}

void Scheme::CalculateRHSContribution(Condition& rCondition, Vector& rRHS, EquationIdVectorType& rEquationIds,
                                      const ProcessInfo& rProcessInfo) {
    rCondition.CalculateRightHandSide(rRHS, rProcessInfo);
    rCondition.EquationIdVector(rEquationIds, rProcessInfo);
}

void Scheme::CalculateLHSContribution(Element& rElement, Matrix& rLHS, EquationIdVectorType& rEquationIds,
                                      const ProcessInfo& rProcessInfo) {
    rElement.CalculateLeftHandSide(rLHS, rProcessInfo);
    rElement.EquationIdVector(rEquationIds, rProcessInfo);
}

void Scheme::CalculateLHSContribution(Condition& rCondition, Matrix& rLHS, EquationIdVectorType& rEquationIds,
                                      const ProcessInfo& rProcessInfo) {
    rCondition.CalculateLeftHandSide(rLHS, rProcessInfo);
    rCondition.EquationIdVector(rEquationIds, rProcessInfo);
}

int Scheme::Check(const ModelPart& rModelPart) const {
    const ProcessInfo& info = rModelPart.GetProcessInfo();
    for (const auto& element : rModelPart.Elements()) element->Check(info);
    for (const auto& condition : rModelPart.Conditions()) condition->Check(info);
    for (const auto& constraint : rModelPart.MasterSlaveConstraints()) constraint->Check(info);
    return 0;
}

}  // namespace contact_app
