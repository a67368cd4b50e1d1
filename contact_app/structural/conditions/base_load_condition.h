// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "contact_app/kernel/condition.h"

namespace contact_app {

/// Common part of the structural load conditions (docs/theory/structural.md §3): DISPLACEMENT_X/Y(/Z) DoFs node by node
/// (reactions REACTION_*), the local system RHS = f_ext, LHS = −∂f_ext/∂u, empty mass and damping
/// (inherited), and the load sources shared by the line and surface loads (docs/theory/structural.md §3).
/// Derived classes implement DofsPerNode() and CalculateAll(). Not registered itself.
class BaseLoadCondition : public Condition {
public:
    using Condition::Condition;

    /// @param[out] rLeftHandSideMatrix (n·d)×(n·d) load stiffness, resized here
    /// @param[out] rRightHandSideVector n·d external force, resized here
    /// @param[in] rCurrentProcessInfo the solution-step data (the loads read only nodal and condition values)
    void CalculateLocalSystem(Matrix& rLeftHandSideMatrix, Vector& rRightHandSideVector,
                              const ProcessInfo& rCurrentProcessInfo) override;
    /// @param[out] rLeftHandSideMatrix (n·d)×(n·d), resized here
    /// @param[in] rCurrentProcessInfo the solution-step data (the loads read only nodal and condition values)
    void CalculateLeftHandSide(Matrix& rLeftHandSideMatrix, const ProcessInfo& rCurrentProcessInfo) override;
    /// @param[out] rRightHandSideVector n·d, resized here
    /// @param[in] rCurrentProcessInfo the solution-step data (the loads read only nodal and condition values)
    void CalculateRightHandSide(Vector& rRightHandSideVector, const ProcessInfo& rCurrentProcessInfo) override;
    /// @param[out] rResult equation ids of DISPLACEMENT_X/Y(/Z), node by node
    /// @param[in] rCurrentProcessInfo not read (the Kratos signature)
    /// @throws InputError if a node lacks one of the DoFs
    void EquationIdVector(EquationIdVectorType& rResult, const ProcessInfo& rCurrentProcessInfo) const override;
    /// @param[out] rElementalDofList the DoFs in local-system order (owned by the nodes)
    /// @param[in] rCurrentProcessInfo not read (the Kratos signature)
    /// @throws InputError if a node lacks one of the DoFs
    void GetDofList(DofsVectorType& rElementalDofList, const ProcessInfo& rCurrentProcessInfo) const override;
    /// @param[out] rValues historical DISPLACEMENT at buffer step @p Step, local-system order
    /// @param[in] Step buffer step: 0 the current solution step, 1 the previous one
    void GetValuesVector(Vector& rValues, int Step = 0) const override;
    /// @param[out] rValues historical VELOCITY at buffer step @p Step
    /// @param[in] Step buffer step: 0 the current solution step, 1 the previous one
    /// @throws InputError if not historical
    void GetFirstDerivativesVector(Vector& rValues, int Step = 0) const override;
    /// @param[out] rValues historical ACCELERATION at buffer step @p Step
    /// @param[in] Step buffer step: 0 the current solution step, 1 the previous one
    /// @throws InputError if not historical
    void GetSecondDerivativesVector(Vector& rValues, int Step = 0) const override;
    /// @throws InputError naming the condition and node when DISPLACEMENT is not historical or a
    ///         DISPLACEMENT_* DoF is missing (plus the Entity checks: id, positive domain size)
    int Check(const ProcessInfo& rCurrentProcessInfo) const override;

protected:
    /// Displacement components per node: 2 or 3.
    virtual int DofsPerNode() const = 0;
    /// @brief Adds f_ext to @p pRhs and −∂f_ext/∂u to @p pLhs (either may be null; both come sized and zeroed).
    virtual void CalculateAll(Matrix* pLhs, Vector* pRhs, const ProcessInfo& rCurrentProcessInfo) const = 0;

    /// Pressure per node p_k = (PRESSURE + NEGATIVE_FACE_PRESSURE − POSITIVE_FACE_PRESSURE of the condition)
    /// + (historical NEGATIVE_FACE_PRESSURE − POSITIVE_FACE_PRESSURE of node k, where stored),
    /// docs/theory/structural.md §3.
    std::vector<double> NodalPressures() const;
    /// Historical @p variable of every node where stored; else the non-historical value when
    /// @p non_historical_fallback (zero if absent); else zero (docs/theory/structural.md §3).
    std::vector<Array3> NodalLoads(const Variable<Array3>& variable, bool non_historical_fallback) const;

private:
    void FillNodalVector(const Variable<Array3>& variable, Vector& rValues, int step) const;
};

}  // namespace contact_app
