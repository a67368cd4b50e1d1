// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// A pair's part of the nodal interface sums, and the map that rebuilds the nodal quantities from it inside one pair
/// (docs/theory/mortar.md §7 "Nodal laws in a pair-wise assembly"). Internal to custom_conditions/.

#include <Eigen/Core>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/geometries/geometry.h"
#include "contact_app/kernel/serializer.h"
#include "custom_utilities/contact_utilities.h"

namespace contact_app {

/// What this pair added to the nodal sums of the last explicit pass, per slave node j:
/// a_j = Σ_k D_jk (to NODAL_AREA), g̃_j (to WEIGHTED_GAP) and s_j (to WEIGHTED_SLIP, frictional families only).
/// Invalid until the first explicit pass and after a pass that found the pair isolated.
template <int TDim, int TNumNodes>
struct PairNodalShare {
    Eigen::Matrix<double, TNumNodes, 1> area = Eigen::Matrix<double, TNumNodes, 1>::Zero();
    Eigen::Matrix<double, TNumNodes, 1> gap = Eigen::Matrix<double, TNumNodes, 1>::Zero();
    Eigen::Matrix<double, TNumNodes, TDim> slip = Eigen::Matrix<double, TNumNodes, TDim>::Zero();
    bool valid = false;

    void Save(Serializer& serializer) const {
        serializer.Save("NodalShareValid", valid);
        serializer.Save("NodalShareArea", area);
        serializer.Save("NodalShareGap", gap);
        serializer.Save("NodalShareSlip", slip);
    }
    void Load(Serializer& serializer) {
        serializer.Load("NodalShareValid", valid);
        serializer.Load("NodalShareArea", area);
        serializer.Load("NodalShareGap", gap);
        serializer.Load("NodalShareSlip", slip);
    }
};

/// Per slave node j, what the pairs transmit and the nodal slip, as functions of this pair's unknowns
/// (docs/theory/mortar.md §7). With A_j = NODAL_AREA = Σ_c a_j^c and ω_j = a_j⁰ / A_j this pair's share:
/// - the gap the pairs' augmentation transmits, Q_j = Σ_c ω_j^c g̃_j^c (AREA_WEIGHTED_PAIR_GAP / A_j): a slave node
///   receives Σ_c D_jj^c (kλ_n + ε g̃^c) = A_j (kλ_n + ε Q_j); rebuilt as Q̂_j(q) = Q_j + g̃_j(q) − g̃_j⁰;
/// - the nodal weighted slip S_j = WEIGHTED_SLIP, rebuilt as Ŝ_j(q) = S_j + (s_j(q) − s_j⁰)/ω_j.
/// At the state of the explicit pass both equal the nodal values, and a nodal law weighted by ω_j in each pair
/// assembles (Σ_c ω_j^c = 1) to the nodal law with its exact derivative. A node without a valid share keeps the pair's
/// own quantities (ω = 1, Q̂ = g̃(q), Ŝ = s(q)). The penalty families push with ε η̂_j Ĝ_j (PenaltyGap).
template <int TDim, int TNumNodes>
struct NodalInterfaceMap {
    Eigen::Matrix<double, TNumNodes, 1> weight = Eigen::Matrix<double, TNumNodes, 1>::Ones();             ///< ω_j
    Eigen::Matrix<double, TNumNodes, 1> gap_offset = Eigen::Matrix<double, TNumNodes, 1>::Zero();         ///< Q − g̃⁰
    Eigen::Matrix<double, TNumNodes, TDim> slip_offset = Eigen::Matrix<double, TNumNodes, TDim>::Zero();  ///< S − s⁰/ω

    template <class T>
    T TransmittedGap(int j, const T& pair_gap) const {
        return pair_gap + gap_offset[j];
    }
    Eigen::Matrix<double, TNumNodes, 1> nodal_gap_offset = Eigen::Matrix<double, TNumNodes, 1>::Zero();  ///< G − g̃⁰
    Eigen::Matrix<double, TNumNodes, 1> penalty_share = Eigen::Matrix<double, TNumNodes, 1>::Ones();  ///< η = Σa²/A²
    /// η_j Ĝ_j, the gap a penalty node is pushed with (λ̄ = ε η G, docs/theory/mortar.md §7 "Nodal penalty"), as a
    /// function of this pair's weighted gap g̃_j: Ĝ = G + g̃ − g̃⁰. Its derivative is this pair's part of η ∂G; the
    /// other pairs' parts enter the tangent through the nodal coupling (nodal_gap_coupling.h). η is held constant by
    /// the tangent (measured: with its derivative the ironing example's pressing steps cycle their active set).
    /// Without a valid share: the pair's own g̃ (η = 1).
    template <class T>
    T PenaltyGap(int j, const T& pair_gap) const {
        return (pair_gap + nodal_gap_offset[j]) * penalty_share[j];
    }
    Eigen::Matrix<double, TNumNodes, TDim> transmitted_slip_offset =
        Eigen::Matrix<double, TNumNodes, TDim>::Zero();  ///< T − ω s⁰
    Eigen::Matrix<double, TNumNodes, 1> inverse_nodal_area =
        Eigen::Matrix<double, TNumNodes, 1>::Zero();  ///< 1/A, 0 without a valid share

    template <class T>
    Eigen::Matrix<T, TDim, 1> Slip(int j, const Eigen::Matrix<T, TDim, 1>& pair_slip) const {
        return pair_slip / weight[j] + slip_offset.row(j).transpose().template cast<T>();
    }
    /// T̂_j(q) = T_j + (a_j(q) s_j(q) − a_j⁰ s_j⁰) / A_j: the slip the pairs' penalty stick rows transmit
    /// (Σ_c a^c s^c / A), with this pair's area and slip varying and A = NODAL_AREA held constant, as η is
    /// (docs/theory/mortar.md §7 "Nodal penalty"). Its derivative is this pair's part of ∂T; the other pairs' parts
    /// enter the tangent through the nodal coupling (nodal_gap_coupling.h). Without a valid share: the pair's own s.
    template <class T>
    Eigen::Matrix<T, TDim, 1> TransmittedSlip(int j, const T& pair_area,
                                              const Eigen::Matrix<T, TDim, 1>& pair_slip) const {
        if (inverse_nodal_area[j] == 0.0) return pair_slip;
        return pair_slip * (pair_area * inverse_nodal_area[j]) +
               transmitted_slip_offset.row(j).transpose().template cast<T>();
    }
};

/// Reads Q, S (if @p frictional) and A from the slave nodes.
template <int TDim, int TNumNodes>
NodalInterfaceMap<TDim, TNumNodes> MakeNodalInterfaceMap(const Geometry& slave,
                                                         const PairNodalShare<TDim, TNumNodes>& share,
                                                         bool frictional) {
    NodalInterfaceMap<TDim, TNumNodes> map;
    if (!share.valid) return map;
    for (int j = 0; j < TNumNodes; ++j) {
        const Node& node = slave[j];
        const double total_area = node.GetValue(NODAL_AREA);
        if (!(share.area[j] > 0.0) || !(total_area >= share.area[j] * (1.0 - 1e-12))) continue;
        map.weight[j] = share.area[j] / total_area;
        map.gap_offset[j] = ContactUtilities::TransmittedWeightedGap(node) - share.gap[j];
        map.nodal_gap_offset[j] = node.FastGetSolutionStepValue(WEIGHTED_GAP) - share.gap[j];
        map.penalty_share[j] = ContactUtilities::PenaltyShare(node);
        if (frictional) {
            map.slip_offset.row(j) = node.FastGetSolutionStepValue(WEIGHTED_SLIP).template head<TDim>().transpose() -
                                     share.slip.row(j) / map.weight[j];
            map.transmitted_slip_offset.row(j) =
                ContactUtilities::TransmittedWeightedSlip(node).template head<TDim>().transpose() -
                share.slip.row(j) * map.weight[j];
            map.inverse_nodal_area[j] = 1.0 / total_area;
        }
    }
    return map;
}

/// What the explicit pass adds to slave node j for this pair: g̃ to WEIGHTED_GAP, a to NODAL_AREA, a·g̃ to
/// AREA_WEIGHTED_PAIR_GAP and a² to SQUARED_PAIR_AREA (the slip is added by the frictional families).
inline void AddPairShareToNode(Node& node, double area, double gap) {
    node.FastGetSolutionStepValue(WEIGHTED_GAP) += gap;
    node.SetValue(NODAL_AREA, node.GetValue(NODAL_AREA) + area);
    node.SetValue(AREA_WEIGHTED_PAIR_GAP, node.GetValue(AREA_WEIGHTED_PAIR_GAP) + area * gap);
    node.SetValue(SQUARED_PAIR_AREA, node.GetValue(SQUARED_PAIR_AREA) + area * area);
}

}  // namespace contact_app
