// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <utility>

#include "custom_conditions/paired_condition.h"

namespace contact_app {

/// The 2D axisymmetric variant of a contact family TFamily (its 2D2N pair): the same residual with every Gauss
/// weight (and, for the Coulomb families, the start-of-step operators and the explicit gap and slip) times
/// 2π r / THICKNESS, r = x-coordinate of the point (differentiated exactly by the AD tangent);
/// docs/theory/contact_residuals.md §9. The condition table builds it from the family's 2D2N pair (the registered
/// names `...FrictionlessAxisymMortarContactCondition2D2N`, ...); the family's .cpp instantiates it
/// (CONTACT_APP_INSTANTIATE_AXISYM_FAMILY).
template <class TFamily>
class MortarContactAxisymCondition : public TFamily {
public:
    using BaseType = TFamily;
    using BaseType::BaseType;
    using BaseType::Create;

    Condition::Pointer Create(IndexType new_id, Geometry::Pointer slave, Properties::Pointer properties,
                              Geometry::Pointer master) const override {
        return std::make_shared<MortarContactAxisymCondition>(new_id, std::move(slave), std::move(properties),
                                                              std::move(master));
    }
    bool IsAxisymmetric() const override { return true; }
};

}  // namespace contact_app
