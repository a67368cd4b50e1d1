// SPDX-License-Identifier: BSD-3-Clause
/// What the assembled-tangent tests of the contact contributors share: setting an unknown on a moving mesh, the dense
/// sink of an AssemblyContributor, and the central differences of an assembled residual.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "contact_app/kernel/condition.h"
#include "contact_app/kernel/node.h"
#include "contact_app/kernel/variables.h"
#include "contact_app/solving/builder_and_solvers/assembly_contributor.h"

namespace contact_app::testing {

/// Sets unknown @p dof to @p value; a displacement moves its node (a moving mesh: x = X0 + u).
inline void SetUnknown(Dof* dof, double value) {
    dof->GetSolutionStepValue() = value;
    Node& node = dof->GetNode();
    node.Coordinates() = node.InitialCoordinates() + node.FastGetSolutionStepValue(DISPLACEMENT);
}

/// A contributor's sink that adds its blocks into the dense matrix @p rTotal (global ids = row/column indices).
inline AssemblyContributor::BlockSink DenseSink(Eigen::MatrixXd& rTotal) {
    return [&rTotal](const EquationIdVectorType& rows, const EquationIdVectorType& cols, const Matrix* block) {
        for (std::size_t a = 0; a < rows.size(); ++a)
            for (std::size_t b = 0; b < cols.size(); ++b) rTotal(rows[a], cols[b]) += (*block)(a, b);
    };
}

/// The pairs' RHS assembled over @p num_dofs unknowns (global ids = indices).
inline Eigen::VectorXd AssembledResidual(const std::vector<Condition::Pointer>& pairs, std::size_t num_dofs,
                                         const ProcessInfo& info) {
    Eigen::VectorXd total = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(num_dofs));
    EquationIdVectorType ids;
    for (const auto& pair : pairs) {
        Vector rhs;
        pair->CalculateRightHandSide(rhs, info);
        pair->EquationIdVector(ids, info);
        for (std::size_t a = 0; a < ids.size(); ++a) total[static_cast<Eigen::Index>(ids[a])] += rhs[a];
    }
    return total;
}

/// The pairs' local LHS assembled over @p num_dofs unknowns (a tangent evaluation: the pairs record their coupling
/// terms for the contributors).
inline Eigen::MatrixXd AssembledLocalTangents(const std::vector<Condition::Pointer>& pairs, std::size_t num_dofs,
                                              const ProcessInfo& info) {
    const auto n = static_cast<Eigen::Index>(num_dofs);
    Eigen::MatrixXd total = Eigen::MatrixXd::Zero(n, n);
    EquationIdVectorType ids;
    for (const auto& pair : pairs) {
        Matrix lhs;
        Vector rhs;
        pair->CalculateLocalSystem(lhs, rhs, info);
        pair->EquationIdVector(ids, info);
        for (std::size_t a = 0; a < ids.size(); ++a)
            for (std::size_t b = 0; b < ids.size(); ++b) total(ids[a], ids[b]) += lhs(a, b);
    }
    return total;
}

/// −∂R/∂u of the assembled residual @p residual() (a vector over @p dofs) by central differences of step @p h, column
/// i moving unknown i (SetUnknown).
template <class TResidual>
Eigen::MatrixXd CentralDifferenceLhs(const std::vector<Dof*>& dofs, TResidual&& residual, double h = 1e-7) {
    const auto n = static_cast<Eigen::Index>(dofs.size());
    Eigen::MatrixXd fd(n, n);
    for (std::size_t i = 0; i < dofs.size(); ++i) {
        const double u = dofs[i]->GetSolutionStepValue();
        SetUnknown(dofs[i], u + h);
        const Eigen::VectorXd plus = residual();
        SetUnknown(dofs[i], u - h);
        const Eigen::VectorXd minus = residual();
        SetUnknown(dofs[i], u);
        fd.col(static_cast<Eigen::Index>(i)) = -(plus - minus) / (2.0 * h);
    }
    return fd;
}

}  // namespace contact_app::testing
