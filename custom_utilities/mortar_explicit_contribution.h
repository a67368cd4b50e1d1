// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "custom_utilities/mortar_operators.h"

namespace contact_app {

/// Nodal results of one pair's explicit contribution (to be added to the slave nodes' non-historical
/// WEIGHTED_GAP, WEIGHTED_SLIP, NODAL_AREA by the caller — AddExplicitContribution or a process).
template <class T, int TDim, int TNumNodes>
struct ExplicitMortarContribution {
    bool isolated = true;  ///< no cells, or overlap / slave area ≤ 1e−5: set ISOLATED, add nothing
    bool dual = false;     ///< dual basis succeeded (NODAL_AREA is only produced then)
    Eigen::Matrix<T, TNumNodes, 1> weighted_gap = Eigen::Matrix<T, TNumNodes, 1>::Zero();
    NodeCoordinates<T, TDim, TNumNodes> weighted_slip = NodeCoordinates<T, TDim, TNumNodes>::Zero();
    Eigen::Matrix<T, TNumNodes, 1> nodal_area = Eigen::Matrix<T, TNumNodes, 1>::Zero();
};

/// Options of the explicit contributions (Kratos MortarExplicitContributionUtilities arguments).
struct ExplicitContributionOptions {
    bool dual_lm = true;             ///< use dual multipliers when Ae succeeds
    bool compute_nodal_area = false; ///< NODAL_AREA_i += Σ_k D_ik = ∫N_i over the overlap (any basis)
};

/// @brief g̃_i = −n_i·(D x1 − M x2)_i (the reference's sign: positive = open gap).
/// @param[in] operators D (n_s × n_s) and M (n_s × n_m) of the pair in the current configuration
/// @param[in] x1 n_s × d current slave coordinates
/// @param[in] x2 n_m × d current master coordinates
/// @param[in] normals n_s × d nodal NORMAL of the slave nodes
template <int TDim, int TNumNodes, int TNumNodesMaster, class T, class TNormal>
Eigen::Matrix<T, TNumNodes, 1> WeightedGap(const MortarOperators<T, TNumNodes, TNumNodesMaster>& operators,
                                          const NodeCoordinates<T, TDim, TNumNodes>& x1,
                                          const NodeCoordinates<T, TDim, TNumNodesMaster>& x2,
                                          const NodeCoordinates<TNormal, TDim, TNumNodes>& normals);

/// @brief Weighted slip increment of the step, Δt·(ṡ_i − (n_i·ṡ_i) n_i), with the slip rate
///        objective:     ṡ = [(D − D_prev) x1 − (M − M_prev) x2] / Δt,
///        non-objective: ṡ = −[D (x1 − x1_prev) − M (x2 − x2_prev)] / Δt   (signs as the reference).
/// @param[in] operators D and M of the pair in the current configuration
/// @param[in] previous operators at the start of the step
/// @param[in] x1 n_s × d current slave coordinates
/// @param[in] x2 n_m × d current master coordinates
/// @param[in] x1_previous,x2_previous start-of-step coordinates X0 + u(step−1), same shapes as @p x1, @p x2
/// @param[in] normals n_s × d nodal NORMAL of the slave nodes; the normal part of the rate is removed
/// @param[in] delta_time Δt (DELTA_TIME, 1 if absent)
/// @param[in] objective true: the rate from the change of D and M (first formula); false: from the
///            coordinate increments (second formula)
template <int TDim, int TNumNodes, int TNumNodesMaster, class T, class TNormal>
NodeCoordinates<T, TDim, TNumNodes> WeightedSlip(const MortarOperators<T, TNumNodes, TNumNodesMaster>& operators,
                                                 const MortarOperators<double, TNumNodes, TNumNodesMaster>& previous,
                                                 const NodeCoordinates<T, TDim, TNumNodes>& x1,
                                                 const NodeCoordinates<T, TDim, TNumNodesMaster>& x2,
                                                 const NodeCoordinates<double, TDim, TNumNodes>& x1_previous,
                                                 const NodeCoordinates<double, TDim, TNumNodesMaster>& x2_previous,
                                                 const NodeCoordinates<TNormal, TDim, TNumNodes>& normals,
                                                 double delta_time, bool objective);

/// @brief Frictionless explicit contribution of one pair: segmentation, ISOLATED rule, dual basis, D, M,
///        weighted gap and (optionally) nodal area (AddExplicitContributionOfMortarCondition).
template <int TDim, int TNumNodes, int TNumNodesMaster, class T, class TNormal>
ExplicitMortarContribution<T, TDim, TNumNodes> ComputeExplicitMortarContribution(
    const MortarIntegrator<TDim, TNumNodes, TNumNodesMaster, T>& integrator,
    const NodeCoordinates<T, TDim, TNumNodes>& x1, const SpatialVector<TNormal, TDim>& slave_normal,
    const NodeCoordinates<T, TDim, TNumNodesMaster>& x2, const NodeCoordinates<TNormal, TDim, TNumNodes>& normals,
    const ExplicitContributionOptions& options);

/// @brief As ComputeExplicitMortarContribution, plus the weighted slip (frictional families,
///        AddExplicitContributionOfMortarFrictionalCondition). @p previous comes from
///        ComputePreviousMortarOperators at the start of the step.
template <int TDim, int TNumNodes, int TNumNodesMaster, class T, class TNormal>
ExplicitMortarContribution<T, TDim, TNumNodes> ComputeExplicitFrictionalMortarContribution(
    const MortarIntegrator<TDim, TNumNodes, TNumNodesMaster, T>& integrator,
    const NodeCoordinates<T, TDim, TNumNodes>& x1, const SpatialVector<TNormal, TDim>& slave_normal,
    const NodeCoordinates<T, TDim, TNumNodesMaster>& x2, const NodeCoordinates<TNormal, TDim, TNumNodes>& normals,
    const MortarOperators<double, TNumNodes, TNumNodesMaster>& previous,
    const NodeCoordinates<double, TDim, TNumNodes>& x1_previous,
    const NodeCoordinates<double, TDim, TNumNodesMaster>& x2_previous, double delta_time, bool objective,
    const ExplicitContributionOptions& options);

/// @brief D and M of the pair in the given configuration (dual LM requested), to be stored as the
///        "previous" operators of the step (a plain copy).
/// @param[in] integrator the pair's mortar integrator (segmentation and integration settings)
/// @param[in] x1 n_s × d slave coordinates in that configuration
/// @param[in] slave_normal d-vector, slave condition normal (the segmentation direction)
/// @param[in] x2 n_m × d master coordinates in that configuration
/// @param[in] normals n_s × d unit nodal NORMAL of the slave nodes
/// @param[out] dual whether Ae succeeded
/// @return zero operators for an isolated pair
template <int TDim, int TNumNodes, int TNumNodesMaster>
MortarOperators<double, TNumNodes, TNumNodesMaster> ComputePreviousMortarOperators(
    const MortarIntegrator<TDim, TNumNodes, TNumNodesMaster, double>& integrator,
    const NodeCoordinates<double, TDim, TNumNodes>& x1, const SpatialVector<double, TDim>& slave_normal,
    const NodeCoordinates<double, TDim, TNumNodesMaster>& x2, const NodeCoordinates<double, TDim, TNumNodes>& normals,
    bool& dual);

}  // namespace contact_app
