// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/structural/conditions/point_load_condition.h"

#include <memory>

#include "contact_app/kernel/variables.h"

namespace contact_app {

template <int TDim>
typename PointLoadCondition<TDim>::Pointer PointLoadCondition<TDim>::Create(IndexType new_id, Geometry::Pointer geometry,
                                                                            Properties::Pointer properties) const {
    return std::make_shared<PointLoadCondition<TDim>>(new_id, std::move(geometry), std::move(properties));
}

template <int TDim>
void PointLoadCondition<TDim>::CalculateAll(Matrix*, Vector* pRhs, const ProcessInfo&) const {
    if (pRhs == nullptr) return;  // the LHS stays zero: the force does not depend on u
    const Array3 condition_load = this->GetValue(POINT_LOAD);
    const auto nodal_loads = this->NodalLoads(POINT_LOAD, false);
    for (std::size_t i = 0; i < nodal_loads.size(); ++i) {
        const Array3 load = condition_load + nodal_loads[i];
        for (int k = 0; k < TDim; ++k) (*pRhs)[static_cast<Eigen::Index>(i) * TDim + k] += load[k];
    }
}

template class PointLoadCondition<2>;
template class PointLoadCondition<3>;

}  // namespace contact_app
