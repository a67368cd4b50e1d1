// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// Mortar integration / segmentation settings of every pair condition (contact families, mesh tying, MPC):
/// INTEGRATION_ORDER_CONTACT, CONSIDER_TESSELLATION from the Properties; DISTANCE_THRESHOLD, ZERO_TOLERANCE_FACTOR
/// from the ProcessInfo (MortarContactCondition adds the axisymmetric thickness). Internal to custom_conditions/.

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/process_info.h"
#include "contact_app/kernel/properties.h"
#include "custom_utilities/mortar_types.h"

namespace contact_app::pair_settings {

inline MortarIntegrationSettings IntegrationSettingsFrom(const Properties::Pointer& properties) {
    MortarIntegrationSettings settings;
    if (properties && properties->Has(INTEGRATION_ORDER_CONTACT))
        settings.integration_order = properties->GetValue(INTEGRATION_ORDER_CONTACT);
    return settings;
}

inline SegmentationSettings SegmentationSettingsFrom(const ProcessInfo& process_info,
                                                     const Properties::Pointer& properties) {
    SegmentationSettings settings;
    if (process_info.Has(DISTANCE_THRESHOLD)) settings.distance_threshold = process_info.GetValue(DISTANCE_THRESHOLD);
    if (process_info.Has(ZERO_TOLERANCE_FACTOR))
        settings.zero_tolerance_factor = process_info.GetValue(ZERO_TOLERANCE_FACTOR);
    if (properties && properties->Has(CONSIDER_TESSELLATION))
        settings.consider_tessellation = properties->GetValue(CONSIDER_TESSELLATION);
    return settings;
}

}  // namespace contact_app::pair_settings
