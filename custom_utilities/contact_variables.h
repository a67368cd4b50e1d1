// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>

#include "contact_app/kernel/variables.h"

namespace contact_app {

class IndexMap;
class IndexSet;
class FrictionalLaw;

// Contact variables (Kratos ContactStructuralMechanicsApplication, docs/input_layer.md §6),
// plus names later Kratos versions added. Core variables the contact layer uses (NORMAL, NODAL_H,
// VECTOR_LAGRANGE_MULTIPLIER, ...) are kernel variables.

/// X(type, NAME)
#define CONTACT_APP_CONTACT_VARIABLES(X)                                                          \
    X(std::shared_ptr<MasterSlaveConstraint>, CONSTRAINT_POINTER)                                 \
    X(double, REACTION_CHECK_STIFFNESS_FACTOR) X(int, INNER_LOOP_ITERATION)                       \
    X(int, INTEGRATION_ORDER_CONTACT) X(double, DISTANCE_THRESHOLD) X(double, ZERO_TOLERANCE_FACTOR) \
    X(double, ACTIVE_CHECK_FACTOR) X(double, SLIP_THRESHOLD) X(double, NORMAL_GAP)                \
    X(double, WEIGHTED_GAP) X(double, WEIGHTED_SCALAR_RESIDUAL) X(bool, ACTIVE_SET_COMPUTED)      \
    X(bool, ACTIVE_SET_CONVERGED) X(bool, SLIP_SET_CONVERGED) X(double, SLIP_AUGMENTATION_COEFFICIENT) \
    X(double, DYNAMIC_FACTOR) X(double, LAGRANGE_MULTIPLIER_CONTACT_PRESSURE)                     \
    X(double, AUGMENTED_NORMAL_CONTACT_PRESSURE) X(int, CONSIDER_NORMAL_VARIATION)                \
    X(bool, ADAPT_PENALTY) X(double, MAX_GAP_FACTOR) X(std::string, TYING_VARIABLE)               \
    X(double, MAX_GAP_THRESHOLD) X(std::shared_ptr<FrictionalLaw>, FRICTIONAL_LAW)                \
    X(double, TRESCA_FRICTION_THRESHOLD) X(std::shared_ptr<IndexMap>, INDEX_MAP)                  \
    X(std::shared_ptr<IndexSet>, INDEX_SET) X(double, OPERATOR_THRESHOLD)                         \
    X(bool, CONSIDER_TESSELLATION) X(double, BUILD_SCALE_FACTOR)                                  \
    X(double, AREA_WEIGHTED_PAIR_GAP) X(double, SQUARED_PAIR_AREA) X(double, SLIP_TRIAL_FACTOR)

/// X(NAME), each with _X, _Y, _Z components.
#define CONTACT_APP_CONTACT_ARRAY3_VARIABLES(X)                                                   \
    X(AUXILIAR_COORDINATES) X(DELTA_COORDINATES) X(TANGENT_SLIP) X(WEIGHTED_SLIP)                 \
    X(WEIGHTED_VECTOR_RESIDUAL) X(AUGMENTED_TANGENT_CONTACT_PRESSURE) X(PAIRED_NORMAL)           \
    X(AREA_WEIGHTED_PAIR_SLIP)

CONTACT_APP_CONTACT_VARIABLES(CONTACT_APP_DECLARE_VARIABLE)
CONTACT_APP_CONTACT_ARRAY3_VARIABLES(CONTACT_APP_DECLARE_ARRAY3_VARIABLE)

/// Links the definitions in (they register themselves at static initialisation); called by
/// RegisterContactApplication().
void RegisterContactVariables();

}  // namespace contact_app
