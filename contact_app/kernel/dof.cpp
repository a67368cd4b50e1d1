// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/dof.h"

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/node.h"

namespace contact_app {

std::size_t Dof::Id() const { return mNode->Id(); }

const Variable<double>& Dof::GetReaction() const {
    CONTACT_CHECK(mReaction != nullptr, InputError, "the DoF ", mVariable->Name(), " of node ", mNode->Id(),
                  " has no reaction variable",
                  "\n  fix: add the DoF with a reaction, e.g. AddDof(DISPLACEMENT_X, REACTION_X)");
    return *mReaction;
}

double& Dof::GetSolutionStepValue(std::size_t step) { return mNode->FastGetSolutionStepValue(*mVariable, step); }

double Dof::GetSolutionStepValue(std::size_t step) const {
    return mNode->FastGetSolutionStepValue(*mVariable, step);
}

double& Dof::GetSolutionStepReactionValue(std::size_t step) {
    return mNode->FastGetSolutionStepValue(GetReaction(), step);
}

}  // namespace contact_app
