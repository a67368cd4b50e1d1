// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/kernel/dof.h"

namespace contact_app {

/// The machine-precision bound of a Newton correction (docs/theory/convergence_criteria.md). A block S of
/// unknowns is at round-off when its last correction cannot change the state it corrects:
/// \f$ \|\Delta x_S\| \le c\,\varepsilon\,\|z_S\| \f$, with \f$ z_i = |x_i| + |X_i| \f$ the unknown's value plus,
/// for a DISPLACEMENT component, the node's current coordinate (a displacement is only resolved to the precision
/// of the position it moves), ε the double precision and c = kRoundOffFactor. Below it a residual is round-off of
/// the forces that make it, and no ratio or absolute test can be met reliably.
class RoundOffBound {
public:
    /// Safety factor c over ε (a correction sums many rounded terms).
    static constexpr double kRoundOffFactor = 16.0;

    /// z of one DoF: |value|, plus |coordinate| for a DISPLACEMENT component.
    static double StateMagnitude(const Dof& rDof);
    /// c ε √(Σ z²) for a block whose state magnitudes squared sum to @p sum_of_squares.
    static double Floor(double sum_of_squares);
    /// Whether a correction of norm @p increment is at round-off of a state with Σ z² = @p state_sum_of_squares.
    /// A zero correction of a non-zero @p residual is not (the Newton step did nothing).
    static bool IsRoundOff(double increment, double state_sum_of_squares, double residual);
};

}  // namespace contact_app
