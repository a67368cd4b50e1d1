// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/kernel/linear_master_slave_constraint.h"

namespace contact_app {

/// The multipoint constraint of the MPC contact route (Kratos ContactMasterSlaveConstraint,
/// docs/theory/contact_strategies.md §3): a LinearMasterSlaveConstraint u_s = T u_m + c whose DoF lists, T and c are
/// rewritten by the MPCMortarContactCondition that holds it in its CONSTRAINT_POINTER value (SetDofList +
/// SetLocalSystem in the condition's life-cycle hooks). It starts empty; the search toggles ACTIVE.
/// Registered as "ContactMasterSlaveConstraint" (RegisterContactMasterSlaveConstraints).
class ContactMasterSlaveConstraint : public LinearMasterSlaveConstraint {
public:
    ContactMasterSlaveConstraint() = default;
    /// @param[in] id constraint Id
    /// @param[in] master_dofs,slave_dofs the DoFs of u_master and u_slave, in the column / row order of T (owned by
    ///            their nodes)
    /// @param[in] relation T, slaves × masters
    /// @param[in] constant c, one entry per slave
    /// @throws InputError on a size mismatch
    ContactMasterSlaveConstraint(IndexType id, DofsVectorType master_dofs, DofsVectorType slave_dofs, Matrix relation,
                                 Vector constant);
    /// An empty constraint (no DoFs) waiting for its condition to fill it.
    explicit ContactMasterSlaveConstraint(IndexType id);

    Pointer Create(IndexType id, DofsVectorType master_dofs, DofsVectorType slave_dofs, const Matrix& relation,
                   const Vector& constant) const override;
    /// Nothing to do: the relation is refreshed by the condition, not by the constraint.
    void FinalizeNonLinearIteration(const ProcessInfo& rCurrentProcessInfo) override;
    std::string Info() const override;
};

/// Registers "ContactMasterSlaveConstraint" in Registry<MasterSlaveConstraint>. Idempotent.
void RegisterContactMasterSlaveConstraints();

}  // namespace contact_app
