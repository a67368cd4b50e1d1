// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/kernel/master_slave_constraint.h"

namespace contact_app {

/// A constant linear relation u_s = T u_m + c (Kratos LinearMasterSlaveConstraint).
class LinearMasterSlaveConstraint : public MasterSlaveConstraint {
public:
    LinearMasterSlaveConstraint() = default;
    /// @param[in] id constraint Id
    /// @param[in] master_dofs,slave_dofs the DoFs of u_master and u_slave, in the column / row order of T (owned by
    ///            their nodes)
    /// @param[in] relation T, slaves × masters
    /// @param[in] constant c, one entry per slave
    /// @throws InputError if the sizes do not match the DoF counts.
    LinearMasterSlaveConstraint(IndexType id, DofsVectorType master_dofs, DofsVectorType slave_dofs,
                                Matrix relation, Vector constant);

    Pointer Create(IndexType id, DofsVectorType master_dofs, DofsVectorType slave_dofs, const Matrix& relation,
                   const Vector& constant) const override;
    void CalculateLocalSystem(Matrix& rTransformationMatrix, Vector& rConstantVector,
                              const ProcessInfo& rCurrentProcessInfo) override;
    /// Also drops the test relation (W = T until SetTestRelation): a new T makes the old W stale.
    /// @throws InputError if T is not slaves × masters or c not one entry per slave (set the DoF lists first)
    void SetLocalSystem(const Matrix& rTransformationMatrix, const Vector& rConstantVector,
                        const ProcessInfo& rCurrentProcessInfo) override;
    bool CalculateTestRelation(Matrix& rTestRelation, const ProcessInfo& rCurrentProcessInfo) override;
    /// @throws InputError if @p rTestRelation is neither empty nor of the shape of T
    void SetTestRelation(const Matrix& rTestRelation, const ProcessInfo& rCurrentProcessInfo) override;
    std::string Info() const override;

private:
    Matrix mRelation;
    Vector mConstant;
    Matrix mTestRelation;  ///< empty: W = T
};

}  // namespace contact_app
