// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/solving/builder_and_solvers/assembly_contributor.h"

namespace contact_app {

/// The tangent blocks of nodal normals that follow the iterate (docs/theory/mortar.md §7 "Normals that follow the
/// iterate"): with CONSIDER_NORMAL_VARIATION ≠ 0 the criteria recompute the mean nodal NORMAL n_j before every build,
/// so pair c's residual depends on the coordinates of every node k of the contact-surface faces through its slave
/// node j. The pairs hold n_j in their local tangents and record B^c_j = ∂RHS^c/∂n_j (NodalNormalCouplingSource);
/// this adds −B^c_j ∂n_j/∂u_k (LHS = −∂RHS/∂q, moving mesh: ∂x = ∂u) with ∂n_j/∂x_k from MeanNormalDerivatives over
/// the root's "Contact" part. Works on the root's "ComputingContact" part; a no-op without such pairs. Installed by the
/// contact strategies on their builder.
class NodalNormalCoupling : public AssemblyContributor {
public:
    void AddGraph(ModelPart& rModelPart, const ProcessInfo& rProcessInfo, const BlockSink& rSink) override;
    void AddLHS(ModelPart& rModelPart, const ProcessInfo& rProcessInfo, const BlockSink& rSink) override;
};

}  // namespace contact_app
