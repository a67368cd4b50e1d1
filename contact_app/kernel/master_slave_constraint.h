// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>

#include "contact_app/kernel/data_value_holder.h"
#include "contact_app/kernel/dof.h"
#include "contact_app/kernel/flags.h"
#include "contact_app/kernel/process_info.h"
#include "contact_app/kernel/types.h"

namespace contact_app {

/// A multipoint constraint u_slave = T · u_master + c (Kratos MasterSlaveConstraint).
/// The base class stores the DoF lists; derived classes supply T and c in CalculateLocalSystem
/// and may rebuild them in the life-cycle hooks (the contact MPC constraint does).
class MasterSlaveConstraint : public Flags, public DataValueHolder {
public:
    using Pointer = std::shared_ptr<MasterSlaveConstraint>;

    explicit MasterSlaveConstraint(IndexType id = 0) : mId(id) {}
    MasterSlaveConstraint(IndexType id, DofsVectorType master_dofs, DofsVectorType slave_dofs)
        : mId(id), mMasterDofs(std::move(master_dofs)), mSlaveDofs(std::move(slave_dofs)) {}
    virtual ~MasterSlaveConstraint() = default;

    /// A new constraint of the same class.
    /// @param[in] id constraint Id
    /// @param[in] master_dofs,slave_dofs the DoFs of u_master and u_slave, in the column / row order of T (owned by
    ///            their nodes)
    /// @param[in] relation T, slaves × masters
    /// @param[in] constant c, one entry per slave
    /// @throws InputError if the sizes do not match the DoF counts.
    virtual Pointer Create(IndexType id, DofsVectorType master_dofs, DofsVectorType slave_dofs,
                           const Matrix& relation, const Vector& constant) const;

    IndexType Id() const { return mId; }
    void SetId(IndexType id) { mId = id; }

    virtual void Initialize(const ProcessInfo& rCurrentProcessInfo);
    virtual void InitializeSolutionStep(const ProcessInfo& rCurrentProcessInfo);
    virtual void InitializeNonLinearIteration(const ProcessInfo& rCurrentProcessInfo);
    virtual void FinalizeNonLinearIteration(const ProcessInfo& rCurrentProcessInfo);
    virtual void FinalizeSolutionStep(const ProcessInfo& rCurrentProcessInfo);

    virtual void GetDofList(DofsVectorType& rSlaveDofsVector, DofsVectorType& rMasterDofsVector,
                            const ProcessInfo& rCurrentProcessInfo) const;
    virtual void SetDofList(const DofsVectorType& rSlaveDofsVector, const DofsVectorType& rMasterDofsVector,
                            const ProcessInfo& rCurrentProcessInfo);
    virtual void EquationIdVector(EquationIdVectorType& rSlaveEquationIds, EquationIdVectorType& rMasterEquationIds,
                                  const ProcessInfo& rCurrentProcessInfo) const;
    const DofsVectorType& GetSlaveDofsVector() const { return mSlaveDofs; }
    const DofsVectorType& GetMasterDofsVector() const { return mMasterDofs; }

    /// The relation T (slaves × masters) and constant c. Base: an empty relation.
    virtual void CalculateLocalSystem(Matrix& rTransformationMatrix, Vector& rConstantVector,
                                      const ProcessInfo& rCurrentProcessInfo);
    /// Replaces T and c (a condition refreshing its constraint, e.g. the MPC mortar contact condition).
    /// @throws InputError in the base (no stored relation) or if the sizes do not match the DoF lists
    virtual void SetLocalSystem(const Matrix& rTransformationMatrix, const Vector& rConstantVector,
                                const ProcessInfo& rCurrentProcessInfo);
    /// The test relation W (slaves × masters, the shape of T) when it differs from T: the builder then forms the
    /// reduced system WᵀAT, Wᵀb instead of TᵀAT, Tᵀb, i.e. the residual of a slave DoF (its constraint force) reaches
    /// the masters with the weights W. A force proportional to the constraint force (MPC Coulomb slip: μ|λ| along
    /// the slip, λ the normal constraint force) is carried that way, with its dependence on λ in the tangent.
    /// @return false (the base, every kinematic constraint): W = T
    virtual bool CalculateTestRelation(Matrix& rTestRelation, const ProcessInfo& rCurrentProcessInfo);
    /// Replaces W; an empty matrix means W = T. @throws InputError in the base or if the shape is not that of T
    virtual void SetTestRelation(const Matrix& rTestRelation, const ProcessInfo& rCurrentProcessInfo);
    /// Sets the slave values to T · u_master + c.
    virtual void Apply(const ProcessInfo& rCurrentProcessInfo);
    virtual int Check(const ProcessInfo& rCurrentProcessInfo) const;
    virtual std::string Info() const;

protected:
    DofsVectorType& MasterDofs() { return mMasterDofs; }
    DofsVectorType& SlaveDofs() { return mSlaveDofs; }

private:
    IndexType mId;
    DofsVectorType mMasterDofs;
    DofsVectorType mSlaveDofs;
};

}  // namespace contact_app
