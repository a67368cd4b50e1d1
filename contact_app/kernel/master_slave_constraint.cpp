// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/master_slave_constraint.h"

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/linear_master_slave_constraint.h"

namespace contact_app {

MasterSlaveConstraint::Pointer MasterSlaveConstraint::Create(IndexType id, DofsVectorType master_dofs,
                                                             DofsVectorType slave_dofs, const Matrix& relation,
                                                             const Vector& constant) const {
    return std::make_shared<LinearMasterSlaveConstraint>(id, std::move(master_dofs), std::move(slave_dofs),
                                                         relation, constant);
}

void MasterSlaveConstraint::Initialize(const ProcessInfo&) {}
void MasterSlaveConstraint::InitializeSolutionStep(const ProcessInfo&) {}
void MasterSlaveConstraint::InitializeNonLinearIteration(const ProcessInfo&) {}
void MasterSlaveConstraint::FinalizeNonLinearIteration(const ProcessInfo&) {}
void MasterSlaveConstraint::FinalizeSolutionStep(const ProcessInfo&) {}

void MasterSlaveConstraint::GetDofList(DofsVectorType& rSlaveDofsVector, DofsVectorType& rMasterDofsVector,
                                       const ProcessInfo&) const {
    rSlaveDofsVector = mSlaveDofs;
    rMasterDofsVector = mMasterDofs;
}

void MasterSlaveConstraint::SetDofList(const DofsVectorType& rSlaveDofsVector,
                                       const DofsVectorType& rMasterDofsVector, const ProcessInfo&) {
    mSlaveDofs = rSlaveDofsVector;
    mMasterDofs = rMasterDofsVector;
}

void MasterSlaveConstraint::EquationIdVector(EquationIdVectorType& rSlaveEquationIds,
                                             EquationIdVectorType& rMasterEquationIds, const ProcessInfo&) const {
    rSlaveEquationIds.resize(mSlaveDofs.size());
    rMasterEquationIds.resize(mMasterDofs.size());
    for (std::size_t i = 0; i < mSlaveDofs.size(); ++i) rSlaveEquationIds[i] = mSlaveDofs[i]->EquationId();
    for (std::size_t i = 0; i < mMasterDofs.size(); ++i) rMasterEquationIds[i] = mMasterDofs[i]->EquationId();
}

void MasterSlaveConstraint::CalculateLocalSystem(Matrix& rTransformationMatrix, Vector& rConstantVector,
                                                 const ProcessInfo&) {
    rTransformationMatrix.setZero(static_cast<Eigen::Index>(mSlaveDofs.size()),
                                  static_cast<Eigen::Index>(mMasterDofs.size()));
    rConstantVector.setZero(static_cast<Eigen::Index>(mSlaveDofs.size()));
}

void MasterSlaveConstraint::SetLocalSystem(const Matrix&, const Vector&, const ProcessInfo&) {
    CONTACT_THROW(InputError, Info(), " does not store a relation matrix (SetLocalSystem)",
                  "\n  fix: use a LinearMasterSlaveConstraint or a ContactMasterSlaveConstraint");
}

bool MasterSlaveConstraint::CalculateTestRelation(Matrix& rTestRelation, const ProcessInfo&) {
    rTestRelation.resize(0, 0);
    return false;
}

void MasterSlaveConstraint::SetTestRelation(const Matrix&, const ProcessInfo&) {
    CONTACT_THROW(InputError, Info(), " does not store a test relation (SetTestRelation)",
                  "\n  fix: use a LinearMasterSlaveConstraint or a ContactMasterSlaveConstraint");
}

void MasterSlaveConstraint::Apply(const ProcessInfo& rCurrentProcessInfo) {
    Matrix relation;
    Vector constant;
    CalculateLocalSystem(relation, constant, rCurrentProcessInfo);
    Vector master_values(static_cast<Eigen::Index>(mMasterDofs.size()));
    for (std::size_t j = 0; j < mMasterDofs.size(); ++j) master_values[j] = mMasterDofs[j]->GetSolutionStepValue();
    const Vector slave_values = relation * master_values + constant;
    for (std::size_t i = 0; i < mSlaveDofs.size(); ++i) mSlaveDofs[i]->GetSolutionStepValue() = slave_values[i];
}

int MasterSlaveConstraint::Check(const ProcessInfo&) const {
    CONTACT_CHECK(mId >= 1, InputError, Info(), ": constraint ids start at 1");
    for (const Dof* dof : mSlaveDofs)
        CONTACT_CHECK(dof != nullptr, InternalError, Info(), " holds a null slave DoF");
    for (const Dof* dof : mMasterDofs)
        CONTACT_CHECK(dof != nullptr, InternalError, Info(), " holds a null master DoF");
    return 0;
}

std::string MasterSlaveConstraint::Info() const { return "MasterSlaveConstraint #" + std::to_string(mId); }

}  // namespace contact_app
