// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// Mortar integration / segmentation settings of every pair condition (contact families, mesh tying, MPC):
/// INTEGRATION_ORDER_CONTACT, CONSIDER_TESSELLATION from the Properties; DISTANCE_THRESHOLD, ZERO_TOLERANCE_FACTOR
/// from the ProcessInfo (MortarContactCondition adds the axisymmetric thickness). Internal to custom_conditions/.

#include <cmath>
#include <limits>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/geometries/geometry.h"
#include "contact_app/kernel/process_info.h"
#include "contact_app/kernel/properties.h"
#include "custom_utilities/mortar_geometry_adapters.h"
#include "custom_utilities/mortar_normals.h"
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

/// Whether every master node lies at most @p threshold in front of the slave face (along its centre normal, from its
/// node average) at the start of the step: X0 + u(1) on a mesh that follows the displacement, the mesh coordinates on
/// a fixed mesh (move_mesh_flag false, or coordinates set by hand) or with a buffer of 1, as the passes read them.
/// @param slave the pair's slave face
/// @param master the pair's master face
/// @param threshold DISTANCE_THRESHOLD of the ProcessInfo
template <int TDim, int TNS, int TNM>
bool WithinDistanceAtStepStart(const Geometry& slave, const Geometry& master, double threshold) {
    bool slave_follows = true, master_follows = true;
    CurrentCoordinates<TDim, TNS>(slave, &slave_follows);
    CurrentCoordinates<TDim, TNM>(master, &master_follows);
    const bool start_of_step =
        slave_follows && master_follows && slave[0].GetBufferSize() > 1 && master[0].GetBufferSize() > 1;
    const auto x1 = start_of_step ? CoordinatesAtStep<TDim, TNS>(slave, 1) : MeshCoordinates<TDim, TNS>(slave);
    const auto x2 = start_of_step ? CoordinatesAtStep<TDim, TNM>(master, 1) : MeshCoordinates<TDim, TNM>(master);
    const SpatialVector<double, TDim> normal = FaceCenterUnitNormal<TDim, TNS, double>(x1);
    const SpatialVector<double, TDim> center = x1.colwise().mean().transpose();
    for (int j = 0; j < TNM; ++j)
        if (!((x2.row(j).transpose() - center).dot(normal) <= threshold)) return false;
    return true;
}

/// The segmentation settings of one pair's passes. The distance rule (a master node farther than DISTANCE_THRESHOLD in
/// front of the slave face → no cells) is decided on the start-of-step configuration (WithinDistanceAtStepStart), so
/// it holds for every pass of the step: decided on each iterate it switched whole pairs on and off between Newton
/// iterates (docs/theory/mortar.md §1 "The distance rule"). The returned distance_threshold is +∞ (within) or −∞
/// (beyond), or the ProcessInfo's value when that is ≥ 1e24 (no rule).
/// @param process_info DISTANCE_THRESHOLD, ZERO_TOLERANCE_FACTOR
/// @param properties CONSIDER_TESSELLATION
/// @param slave the pair's slave face
/// @param master the pair's master face
template <int TDim, int TNS, int TNM>
SegmentationSettings PairSegmentationSettings(const ProcessInfo& process_info, const Properties::Pointer& properties,
                                              const Geometry& slave, const Geometry& master) {
    SegmentationSettings settings = SegmentationSettingsFrom(process_info, properties);
    if (!std::isfinite(settings.distance_threshold) || settings.distance_threshold >= 1.0e24) return settings;
    settings.distance_threshold = WithinDistanceAtStepStart<TDim, TNS, TNM>(slave, master, settings.distance_threshold)
                                      ? std::numeric_limits<double>::infinity()
                                      : -std::numeric_limits<double>::infinity();
    return settings;
}

}  // namespace contact_app::pair_settings
