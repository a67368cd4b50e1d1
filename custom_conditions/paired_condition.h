// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "contact_app/kernel/condition.h"

namespace contact_app {

/// A condition owning a slave face and a paired master face (Kratos PairedCondition): with a master the
/// geometry is a CouplingGeometry {slave, master}; without one (an .mdpa-created condition) it is the slave
/// face alone and Check() fails. The unit normal of the master face at its centre is cached in
/// mPairedNormal: refreshed in Initialize / InitializeSolutionStep and, when CONSIDER_NORMAL_VARIATION ≠ 0
/// (NO_DERIVATIVES_COMPUTATION), in InitializeNonLinearIteration. Names and sizes: docs/registered_conditions.md.
class PairedCondition : public Condition {
public:
    /// @param[in] id condition Id
    /// @param[in] geometry a CouplingGeometry {slave, master} or a bare slave face (shared, not null)
    /// @param[in] properties shared with the model part; may be null until the materials are assigned
    PairedCondition(IndexType id, Geometry::Pointer geometry, Properties::Pointer properties = nullptr);
    /// @param[in] id condition Id
    /// @param[in] slave slave face (shared, not null)
    /// @param[in] properties shared with the model part; may be null until the materials are assigned
    /// @param[in] master master face (shared; may be null: unpaired condition)
    PairedCondition(IndexType id, Geometry::Pointer slave, Properties::Pointer properties, Geometry::Pointer master);

    /// The prototype's slave geometry type on @p nodes, without master (Check() then fails).
    Pointer Create(IndexType new_id, const NodesArrayType& nodes, Properties::Pointer properties) const override;
    /// @p geometry is a CouplingGeometry {slave, master} or a bare slave face.
    Pointer Create(IndexType new_id, Geometry::Pointer geometry, Properties::Pointer properties) const override;
    /// The pair constructor the contact search uses (slave face, properties, master face).
    virtual Pointer Create(IndexType new_id, Geometry::Pointer slave, Properties::Pointer properties,
                           Geometry::Pointer master) const;

    void Initialize(const ProcessInfo& rCurrentProcessInfo) override;
    void InitializeSolutionStep(const ProcessInfo& rCurrentProcessInfo) override;
    void InitializeNonLinearIteration(const ProcessInfo& rCurrentProcessInfo) override;
    /// @throws InputError naming the condition id when no master geometry was paired (the .mdpa case)
    int Check(const ProcessInfo& rCurrentProcessInfo) const override;
    /// The three entry points of the local system are one CalculateConditionSystem each, with the part not asked for
    /// null: a pair computes its LHS and RHS in one pass (the AD tangent carries the residual).
    void CalculateLocalSystem(Matrix& rLeftHandSideMatrix, Vector& rRightHandSideVector,
                              const ProcessInfo& rCurrentProcessInfo) override;
    void CalculateLeftHandSide(Matrix& rLeftHandSideMatrix, const ProcessInfo& rCurrentProcessInfo) override;
    void CalculateRightHandSide(Vector& rRightHandSideVector, const ProcessInfo& rCurrentProcessInfo) override;
    /// The equation ids of GetDofList, in its order.
    void EquationIdVector(EquationIdVectorType& rResult, const ProcessInfo& rCurrentProcessInfo) const override;
    /// 0×0: a pair has no inertia.
    void CalculateMassMatrix(Matrix& rMassMatrix, const ProcessInfo& rCurrentProcessInfo) override;
    /// 0×0: a pair has no damping.
    void CalculateDampingMatrix(Matrix& rDampingMatrix, const ProcessInfo& rCurrentProcessInfo) override;
    /// Zeros, one per integration point of the slave face: a pair's results live on its nodes.
    void CalculateOnIntegrationPoints(const Variable<double>& rVariable, std::vector<double>& rOutput,
                                      const ProcessInfo& rCurrentProcessInfo) override;
    void CalculateOnIntegrationPoints(const Variable<Array3>& rVariable, std::vector<Array3>& rOutput,
                                      const ProcessInfo& rCurrentProcessInfo) override;
    /// Zero vectors of the working-space dimension, one per integration point of the slave face.
    void CalculateOnIntegrationPoints(const Variable<Vector>& rVariable, std::vector<Vector>& rOutput,
                                      const ProcessInfo& rCurrentProcessInfo) override;
    std::string Info() const override;
    /// Base state plus the cached master normal.
    void Save(Serializer& rSerializer) const override;
    void Load(Serializer& rSerializer) override;

    /// Whether a master face is paired.
    bool HasPairedGeometry() const { return GetGeometry().NumberOfGeometryParts() == 2; }
    /// The slave face (CouplingGeometry part 0).
    const Geometry& GetParentGeometry() const { return *pGetParentGeometry(); }
    Geometry::Pointer pGetParentGeometry() const;
    /// The master face (CouplingGeometry part 1). @throws InputError if none is paired
    const Geometry& GetPairedGeometry() const { return *pGetPairedGeometry(); }
    Geometry::Pointer pGetPairedGeometry() const;
    const Array3& GetPairedNormal() const { return mPairedNormal; }
    void SetPairedNormal(const Array3& normal) { mPairedNormal = normal; }

protected:
    /// @brief The pair's local system; the default is the empty one of a bare Condition.
    /// @param[out] pLhs the LHS, sized here (null: not asked for)
    /// @param[out] pRhs the RHS, sized here (null: not asked for)
    /// @param[in] rCurrentProcessInfo handed on from the entry point
    virtual void CalculateConditionSystem(Matrix* pLhs, Vector* pRhs, const ProcessInfo& rCurrentProcessInfo);
    /// "<name> #Id (slave <geometry>, master <geometry or none>)", the Info() of every pair condition.
    std::string PairInfo(const char* name) const;
    /// @throws InputError (in the words of @p name) unless the slave and master faces have @p num_slave and
    ///         @p num_master nodes
    void CheckNodeCounts(const char* name, int num_slave, int num_master) const;

private:
    void UpdatePairedNormal();
    Array3 mPairedNormal = Array3::Zero();
};

}  // namespace contact_app
