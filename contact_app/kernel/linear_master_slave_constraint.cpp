// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/linear_master_slave_constraint.h"

#include "contact_app/kernel/exceptions.h"

namespace contact_app {

LinearMasterSlaveConstraint::LinearMasterSlaveConstraint(IndexType id, DofsVectorType master_dofs,
                                                         DofsVectorType slave_dofs, Matrix relation,
                                                         Vector constant)
    : MasterSlaveConstraint(id, std::move(master_dofs), std::move(slave_dofs)),
      mRelation(std::move(relation)),
      mConstant(std::move(constant)) {
    const auto slaves = static_cast<Eigen::Index>(GetSlaveDofsVector().size());
    const auto masters = static_cast<Eigen::Index>(GetMasterDofsVector().size());
    CONTACT_CHECK(mRelation.rows() == slaves && mRelation.cols() == masters, InputError, Info(),
                  ": relation matrix is ", mRelation.rows(), "x", mRelation.cols(), ", expected ", slaves, "x",
                  masters, " (slave DoFs x master DoFs)");
    CONTACT_CHECK(mConstant.size() == slaves, InputError, Info(), ": constant vector has ", mConstant.size(),
                  " entries, expected one per slave DoF (", slaves, ")");
}

MasterSlaveConstraint::Pointer LinearMasterSlaveConstraint::Create(IndexType id, DofsVectorType master_dofs,
                                                                   DofsVectorType slave_dofs,
                                                                   const Matrix& relation,
                                                                   const Vector& constant) const {
    return std::make_shared<LinearMasterSlaveConstraint>(id, std::move(master_dofs), std::move(slave_dofs),
                                                         relation, constant);
}

void LinearMasterSlaveConstraint::CalculateLocalSystem(Matrix& rTransformationMatrix, Vector& rConstantVector,
                                                       const ProcessInfo&) {
    rTransformationMatrix = mRelation;
    rConstantVector = mConstant;
}

void LinearMasterSlaveConstraint::SetLocalSystem(const Matrix& rTransformationMatrix, const Vector& rConstantVector,
                                                 const ProcessInfo&) {
    const auto slaves = static_cast<Eigen::Index>(GetSlaveDofsVector().size());
    const auto masters = static_cast<Eigen::Index>(GetMasterDofsVector().size());
    CONTACT_CHECK(rTransformationMatrix.rows() == slaves && rTransformationMatrix.cols() == masters, InputError,
                  Info(), ": SetLocalSystem got a ", rTransformationMatrix.rows(), "x", rTransformationMatrix.cols(),
                  " relation matrix, expected ", slaves, "x", masters,
                  " (slave DoFs x master DoFs)\n  fix: call SetDofList with the matching DoF lists first");
    CONTACT_CHECK(rConstantVector.size() == slaves, InputError, Info(), ": SetLocalSystem got ",
                  rConstantVector.size(), " constants, expected one per slave DoF (", slaves, ")");
    mRelation = rTransformationMatrix;
    mConstant = rConstantVector;
    mTestRelation.resize(0, 0);
}

bool LinearMasterSlaveConstraint::CalculateTestRelation(Matrix& rTestRelation, const ProcessInfo&) {
    rTestRelation = mTestRelation;
    return mTestRelation.size() > 0;
}

void LinearMasterSlaveConstraint::SetTestRelation(const Matrix& rTestRelation, const ProcessInfo&) {
    CONTACT_CHECK(rTestRelation.size() == 0 ||
                      (rTestRelation.rows() == mRelation.rows() && rTestRelation.cols() == mRelation.cols()),
                  InputError, Info(), ": SetTestRelation got a ", rTestRelation.rows(), "x", rTestRelation.cols(),
                  " matrix, expected ", mRelation.rows(), "x", mRelation.cols(),
                  " (the shape of the relation T)\n  fix: call SetLocalSystem first, then SetTestRelation");
    mTestRelation = rTestRelation;
}

std::string LinearMasterSlaveConstraint::Info() const {
    return "LinearMasterSlaveConstraint #" + std::to_string(Id());
}

}  // namespace contact_app
