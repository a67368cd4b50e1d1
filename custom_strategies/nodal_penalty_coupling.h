// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/solving/builder_and_solvers/assembly_contributor.h"

namespace contact_app {

/// The tangent blocks between the pairs of one slave node that the penalty families' nodal pressure λ̄_j = ε η_j G_j
/// and the penalty slip direction creates (docs/theory/mortar.md §7 "Nodal penalty"): G_j sums the weighted gaps of all
/// pairs c of node j, so pair c's residual has the derivative b^c_j (∂(ηG)_j/∂q_d)ᵀ in the unknowns of every other
/// pair d; at a slipping node its direction reads the transmitted slip T_j = Σ_d a^d s^d / A_j, which adds
/// B^c_j ∂T_j/∂q_d. Each pair holds its own d = c block; this adds −b^c_j (∂(ηG)_j/∂q_d)ᵀ − B^c_j ∂T_j/∂q_d for
/// c ≠ d (LHS = −∂RHS/∂q) from the terms the pairs recorded in their tangent evaluation of the same build
/// (NodalGapCouplingSource). Works on the root's "ComputingContact" part; a
/// no-op without penalty pairs. Installed by the contact strategies on their builder.
class NodalPenaltyCoupling : public AssemblyContributor {
public:
    void AddGraph(ModelPart& rModelPart, const ProcessInfo& rProcessInfo, const BlockSink& rSink) override;
    void AddLHS(ModelPart& rModelPart, const ProcessInfo& rProcessInfo, const BlockSink& rSink) override;
};

}  // namespace contact_app
