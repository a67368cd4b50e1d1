// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/convergence_criteria/round_off_bound.h"

#include <cmath>
#include <limits>

#include "contact_app/kernel/node.h"
#include "contact_app/kernel/variables.h"

namespace contact_app {

double RoundOffBound::StateMagnitude(const Dof& rDof) {
    const VariableData& variable = rDof.GetVariable();
    double position = 0.0;
    if (variable.IsComponent() && *variable.SourceVariable() == DISPLACEMENT)
        position = std::abs(rDof.GetNode().Coordinates()[variable.ComponentIndex()]);
    return std::abs(rDof.GetSolutionStepValue()) + position;
}

double RoundOffBound::Floor(double sum_of_squares) {
    return kRoundOffFactor * std::numeric_limits<double>::epsilon() * std::sqrt(sum_of_squares);
}

bool RoundOffBound::IsRoundOff(double increment, double state_sum_of_squares, double residual) {
    if (increment == 0.0 && residual != 0.0) return false;
    return increment <= Floor(state_sum_of_squares);
}

}  // namespace contact_app
