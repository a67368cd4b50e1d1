// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/contact_master_slave_constraint.h"

#include "contact_app/kernel/registry.h"

namespace contact_app {

ContactMasterSlaveConstraint::ContactMasterSlaveConstraint(IndexType id, DofsVectorType master_dofs,
                                                           DofsVectorType slave_dofs, Matrix relation, Vector constant)
    : LinearMasterSlaveConstraint(id, std::move(master_dofs), std::move(slave_dofs), std::move(relation),
                                  std::move(constant)) {}

ContactMasterSlaveConstraint::ContactMasterSlaveConstraint(IndexType id)
    : LinearMasterSlaveConstraint(id, {}, {}, Matrix(0, 0), Vector(0)) {}

MasterSlaveConstraint::Pointer ContactMasterSlaveConstraint::Create(IndexType id, DofsVectorType master_dofs,
                                                                    DofsVectorType slave_dofs, const Matrix& relation,
                                                                    const Vector& constant) const {
    return std::make_shared<ContactMasterSlaveConstraint>(id, std::move(master_dofs), std::move(slave_dofs), relation,
                                                          constant);
}

void ContactMasterSlaveConstraint::FinalizeNonLinearIteration(const ProcessInfo&) {}

std::string ContactMasterSlaveConstraint::Info() const {
    return "ContactMasterSlaveConstraint #" + std::to_string(Id());
}

void RegisterContactMasterSlaveConstraints() {
    static bool registered = false;
    if (registered) return;
    registered = true;
    Registry<MasterSlaveConstraint>::Instance().Add("ContactMasterSlaveConstraint",
                                                    std::make_shared<ContactMasterSlaveConstraint>());
}

}  // namespace contact_app
