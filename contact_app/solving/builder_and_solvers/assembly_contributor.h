// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <memory>

#include "contact_app/kernel/model_part.h"

namespace contact_app {

/// Tangent blocks that no single element or condition holds, added by the builder after the entities: rows of one
/// entity's DoFs, columns of another's (the contact layer's nodal penalty couples the pairs of a slave node through
/// the node's weighted gap). A contributor adds no residual: its entities already hold it.
class AssemblyContributor {
public:
    using Pointer = std::shared_ptr<AssemblyContributor>;
    /// Receives a block: global row ids, global column ids, and (when assembling) its values, rows × columns.
    using BlockSink =
        std::function<void(const EquationIdVectorType& rRows, const EquationIdVectorType& rColumns, const Matrix* pBlock)>;

    virtual ~AssemblyContributor() = default;
    /// Every block it may fill while the DoF set stays (pBlock null): the builder adds them to the sparsity graph.
    virtual void AddGraph(ModelPart& rModelPart, const ProcessInfo& rProcessInfo, const BlockSink& rSink) = 0;
    /// Its LHS blocks at the current state, after the entities' own systems were computed in this build.
    virtual void AddLHS(ModelPart& rModelPart, const ProcessInfo& rProcessInfo, const BlockSink& rSink) = 0;
};

}  // namespace contact_app
