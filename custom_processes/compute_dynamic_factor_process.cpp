// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/compute_dynamic_factor_process.h"

#include <algorithm>
#include <cmath>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/model_part.h"

namespace contact_app {

void ComputeDynamicFactorProcess::Execute() {
    CONTACT_CHECK(mrModelPart.HasNodalSolutionStepVariable(WEIGHTED_GAP) && mrModelPart.GetBufferSize() >= 2, InputError,
                  "ComputeDynamicFactorProcess: model part ", mrModelPart.FullName(), " must store WEIGHTED_GAP as a",
                  " historical variable with a buffer of at least 2 (buffer ", mrModelPart.GetBufferSize(), ")",
                  "\n  fix: use an ALM or penalty mortar_type (it adds WEIGHTED_GAP) and buffer_size >= 2");
    for (const auto& node : mrModelPart.Nodes()) {
        const bool is_slave = node->IsDefined(SLAVE) ? node->Is(SLAVE) : true;
        if (!is_slave) continue;
        const double gap = node->FastGetSolutionStepValue(WEIGHTED_GAP, 0);
        const double gap_old = node->FastGetSolutionStepValue(WEIGHTED_GAP, 1);
        const bool enters_contact = gap < 0.0 && gap_old >= 0.0;  // then gap − gap_old < 0: no division by zero
        node->SetValue(DYNAMIC_FACTOR, enters_contact ? std::min(1.0, std::abs(gap) / std::abs(gap - gap_old)) : 1.0);
    }
}

}  // namespace contact_app
