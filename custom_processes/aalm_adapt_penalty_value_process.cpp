// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/aalm_adapt_penalty_value_process.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/model_part.h"
#include "custom_utilities/contact_utilities.h"

namespace contact_app {

namespace {

/// The adapted penalty for the gaps of one node (the branches of the reference, literally).
double AdaptedPenalty(double previous, double gap, double gap_old, double max_gap) {
    const double abs_gap = std::abs(gap);
    if (gap * gap_old < 0.0) {
        if (std::abs(gap_old) > max_gap)
            return std::abs(previous * gap_old / gap * (abs_gap + max_gap) / (gap - gap_old));
        return std::abs(previous * gap_old / (10.0 * gap));
    }
    if (abs_gap <= max_gap) return previous;
    if (std::abs(gap - gap_old) > std::max({gap / 10.0, gap_old, 5.0 * max_gap})) return 2.0 * previous;
    // The reference guards the next branch with "|g| ≤ 1.01|g_old| or |g| ≥ 0.99|g_old|", which always holds.
    const double growth = std::sqrt(abs_gap / max_gap - 1.0) + 1.0;
    if (abs_gap < 10.0 * max_gap) return previous * growth * growth;
    if (abs_gap > 1.01 * std::abs(gap_old)) return 2.0 * previous * gap_old / gap;
    return previous * growth;
}

}  // namespace

void AALMAdaptPenaltyValueProcess::Execute() {
    CONTACT_CHECK(mrModelPart.HasNodalSolutionStepVariable(WEIGHTED_GAP) && mrModelPart.GetBufferSize() >= 2, InputError,
                  "AALMAdaptPenaltyValueProcess: model part ", mrModelPart.FullName(), " must store WEIGHTED_GAP as a",
                  " historical variable with a buffer of at least 2 (buffer ", mrModelPart.GetBufferSize(), ")",
                  "\n  fix: use an ALM mortar_type (it adds WEIGHTED_GAP) and buffer_size >= 2");
    const ProcessInfo& process_info = mrModelPart.GetProcessInfo();
    const bool first_iteration = process_info.GetValue(STEP) == 1 && process_info.GetValue(NL_ITERATION_NUMBER) == 1;
    const double max_gap_factor = process_info.GetValue(MAX_GAP_FACTOR);
    for (const auto& node : mrModelPart.Nodes()) {
        const double area = node->GetValue(NODAL_AREA);
        if (area <= std::numeric_limits<double>::epsilon()) continue;
        const double previous =
            first_iteration ? process_info.GetValue(INITIAL_PENALTY) : node->GetValue(INITIAL_PENALTY);
        const double gap = node->FastGetSolutionStepValue(WEIGHTED_GAP, 0) / area;
        const double gap_old = node->FastGetSolutionStepValue(WEIGHTED_GAP, 1) / area;
        const double max_gap = max_gap_factor * ContactUtilities::NodalH(*node);
        node->SetValue(INITIAL_PENALTY, AdaptedPenalty(previous, gap, gap_old, max_gap));
    }
}

}  // namespace contact_app
