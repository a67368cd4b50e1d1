// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

namespace contact_app {

/// One registered contact condition name, decoded (docs/registered_conditions.md §1).
struct ContactConditionName {
    std::string name;    ///< e.g. "ALMNVFrictionlessAxisymMortarContactCondition2D2N"
    std::string family;  ///< "ALMFrictionless", "ALMFrictionlessComponents", "ALMFrictional", "PenaltyFrictionless", ...
    bool normal_variation = false;
    bool axisymmetric = false;
    int dim = 0, num_slave = 0, num_master = 0;
    int matrix_size = 0;  ///< local system size of the family for this pair
};

/// Every name of the table (the names RegisterContactConditions adds), in table order.
const std::vector<ContactConditionName>& RegisteredContactConditionNames();

/// Registers the prototypes of the contact condition families in Registry<Condition>, from one
/// table (method × NV × family × axisym × pair). Idempotent.
void RegisterContactConditions();

}  // namespace contact_app
