// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <vector>

#include "contact_app/kernel/variable_data.h"

namespace contact_app {

class Node;

/// One degree of freedom of a node: the unknown variable (DISPLACEMENT_X), the variable that
/// receives its reaction (REACTION_X), its fixity and its equation id. Owned by its node; the
/// value lives in the node's historical data.
class Dof {
public:
    using EquationIdType = std::size_t;

    /// @param[in] node      owner (outlives the DoF)
    /// @param[in] variable  the unknown (DISPLACEMENT_X, a multiplier component, ...), a registered variable
    /// @param[in] reaction  may be nullptr (no reaction variable)
    Dof(Node& node, const Variable<double>& variable, const Variable<double>* reaction)
        : mNode(&node), mVariable(&variable), mReaction(reaction) {}

    /// Id of the owning node (Kratos Dof::Id()).
    std::size_t Id() const;
    Node& GetNode() const { return *mNode; }
    const Variable<double>& GetVariable() const { return *mVariable; }
    bool HasReaction() const { return mReaction != nullptr; }
    /// @throws InputError if the DoF was added without a reaction variable.
    const Variable<double>& GetReaction() const;
    void SetReaction(const Variable<double>& reaction) { mReaction = &reaction; }

    double& GetSolutionStepValue(std::size_t step = 0);
    double GetSolutionStepValue(std::size_t step = 0) const;
    double& GetSolutionStepReactionValue(std::size_t step = 0);

    void FixDof() { mFixed = true; }
    void FreeDof() { mFixed = false; }
    bool IsFixed() const { return mFixed; }
    bool IsFree() const { return !mFixed; }

    EquationIdType EquationId() const { return mEquationId; }
    void SetEquationId(EquationIdType id) { mEquationId = id; }

private:
    Node* mNode;
    const Variable<double>* mVariable;
    const Variable<double>* mReaction;
    EquationIdType mEquationId = 0;
    bool mFixed = false;
};

using DofsVectorType = std::vector<Dof*>;
using EquationIdVectorType = std::vector<std::size_t>;

}  // namespace contact_app
