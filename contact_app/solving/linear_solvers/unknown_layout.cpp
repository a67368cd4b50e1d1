// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/linear_solvers/unknown_layout.h"

#include <sstream>

#include "contact_app/kernel/dof.h"
#include "contact_app/kernel/model_part.h"
#include "contact_app/kernel/node.h"
#include "contact_app/kernel/variables.h"

namespace contact_app {

UnknownLayout UnknownLayout::Subset(const std::vector<int>& kept) const {
    UnknownLayout subset;
    subset.dimension = dimension;
    subset.model_part = model_part;
    subset.node.reserve(kept.size());
    subset.component.reserve(kept.size());
    subset.coordinates.reserve(kept.size());
    for (const int k : kept) {
        const auto i = static_cast<std::size_t>(k);
        const bool known = k >= 0 && i < size();
        subset.node.push_back(known ? node[i] : 0);
        subset.component.push_back(known ? component[i] : -1);
        subset.coordinates.push_back(known ? coordinates[i] : std::array<double, 3>{0.0, 0.0, 0.0});
    }
    return subset;
}

UnknownLayout UnknownLayoutFromDofs(const std::vector<Dof*>& rDofSet, std::size_t size, const ModelPart& rModelPart) {
    UnknownLayout layout;
    layout.model_part = &rModelPart;
    layout.node.assign(size, 0);
    layout.component.assign(size, -1);
    layout.coordinates.assign(size, {0.0, 0.0, 0.0});
    const Variable<double>* const displacements[] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
    for (const Dof* dof : rDofSet) {
        const std::size_t equation = dof->EquationId();
        if (equation >= size) continue;
        const Node& node = dof->GetNode();
        layout.node[equation] = static_cast<int>(node.Id());
        const auto& x = node.Coordinates();
        layout.coordinates[equation] = {x[0], x[1], x[2]};
        for (int c = 0; c < 3; ++c)
            if (dof->GetVariable() == *displacements[c]) {
                layout.component[equation] = c;
                layout.dimension = std::max(layout.dimension, c == 2 ? 3 : 2);
            }
    }
    return layout;
}

std::string NewtonStepText(const ModelPart* pModelPart) {
    if (pModelPart == nullptr) return "";
    const ProcessInfo& info = pModelPart->GetProcessInfo();
    std::ostringstream text;
    text << "step " << info.GetValue(STEP) << " (TIME " << info.GetValue(TIME) << "), Newton iteration "
         << info.GetValue(NL_ITERATION_NUMBER);
    return text.str();
}

}  // namespace contact_app
