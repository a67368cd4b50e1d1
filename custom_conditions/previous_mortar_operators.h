// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/kernel/serializer.h"
#include "custom_utilities/mortar_types.h"

namespace contact_app {

/// The mortar operators of a pair at the start of the step (X0 + d(1)) and whether they exist for this step: the
/// slip of the Coulomb families and the slip direction of MPC friction are measured with them
/// (docs/theory/contact_residuals.md §2, docs/theory/mortar.md §9). Explicit state: a pair never reads stale operators.
template <int TNS, int TNM>
struct PreviousMortarOperators {
    MortarOperators<double, TNS, TNM> operators;
    bool initialized = false;  ///< computed for the current step (reset by FinalizeSolutionStep)
    bool overlap = false;      ///< the pair overlapped at the start of the step (otherwise operators are zero)

    void Reset() {
        operators.Initialize();
        initialized = overlap = false;
    }
    /// Stores the operators of this step (the pair overlapped iff D ≠ 0).
    void Set(const MortarOperators<double, TNS, TNM>& start_of_step) {
        operators = start_of_step;
        overlap = operators.D.norm() > 0.0;
        initialized = true;
    }
    void Save(Serializer& serializer) const {
        serializer.Save("PreviousMortarOperatorsInitialized", initialized);
        serializer.Save("PreviousMortarOperatorsOverlap", overlap);
        operators.Save(serializer, "Previous");
    }
    void Load(Serializer& serializer) {
        serializer.Load("PreviousMortarOperatorsInitialized", initialized);
        serializer.Load("PreviousMortarOperatorsOverlap", overlap);
        operators.Load(serializer, "Previous");
    }
};

}  // namespace contact_app
