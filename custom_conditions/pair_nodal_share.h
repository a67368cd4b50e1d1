// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// A pair's part of the nodal interface sums, and the map that rebuilds the nodal quantities from it inside one pair
/// (docs/theory/mortar.md §7 "Nodal laws in a pair-wise assembly"). Internal to custom_conditions/.

#include <array>

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
///   receives Σ_c D_jj^c (kλ_n + ε g̃^c) = A_j (kλ_n + ε Q_j); rebuilt as Q̂_j(q) = Q_j + (Q̃_j(q) − Q_j)/ω_j with
///   Q̃_j(q) = (Σ_c a^c g̃^c + a_j(q) g̃_j(q) − a_j⁰ g̃_j⁰) / (A_j + a_j(q) − a_j⁰), this pair's share varying in the
///   weights too (TransmittedGap);
/// - the nodal weighted slip S_j = WEIGHTED_SLIP, rebuilt as Ŝ_j(q) = S_j + (s_j(q) − s_j⁰)/ω_j.
/// At the state of the explicit pass both equal the nodal values, and a nodal law weighted by ω_j in each pair
/// assembles (Σ_c ω_j^c = 1) to the nodal law with its exact derivative. A node without a valid share keeps the pair's
/// own quantities (ω = 1, Q̂ = g̃(q), Ŝ = s(q)). The penalty families push with ε η̂_j Ĝ_j (PenaltyGap).
template <int TDim, int TNumNodes>
struct NodalInterfaceMap {
    Eigen::Matrix<double, TNumNodes, 1> weight = Eigen::Matrix<double, TNumNodes, 1>::Ones();             ///< ω_j
    Eigen::Matrix<double, TNumNodes, 1> gap_offset = Eigen::Matrix<double, TNumNodes, 1>::Zero();         ///< Q − g̃⁰
    Eigen::Matrix<double, TNumNodes, TDim> slip_offset = Eigen::Matrix<double, TNumNodes, TDim>::Zero();  ///< S − s⁰/ω
    Eigen::Matrix<double, TNumNodes, 1> weighted_gap_offset =
        Eigen::Matrix<double, TNumNodes, 1>::Zero();  ///< Σ_c a^c g̃^c − a⁰ g̃⁰ (AREA_WEIGHTED_PAIR_GAP − a⁰ g̃⁰)

    /// Q̂_j(q) as a function of this pair's weighted gap g̃_j and area a_j. Weighted by ω_j in each pair, the pairs
    /// assemble ∂Q = Σ_c ∂(a^c g̃^c / A) exactly, the motion of the weights a^c / A included (with Q + g̃ − g̃⁰ it was
    /// missing: 1.1e-5 of the largest tangent entry on a non-matching slip test, docs/theory/mortar.md §7).
    template <class T>
    T TransmittedGap(int j, const T& pair_gap, const T& pair_area) const {
        if (!shared[j] || area_offset[j] == 0.0) return pair_gap + gap_offset[j];  // this pair alone: Q = g̃
        const T own = (pair_gap * pair_area + weighted_gap_offset[j]) / (pair_area + area_offset[j]);
        return (own - transmitted_gap[j]) / weight[j] + transmitted_gap[j];
    }
    Eigen::Matrix<double, TNumNodes, 1> transmitted_gap = Eigen::Matrix<double, TNumNodes, 1>::Zero();  ///< Q
    std::array<bool, TNumNodes> shared{};  ///< whether node j has a valid share (else the pair's own g̃, s)
    Eigen::Matrix<double, TNumNodes, 1> nodal_gap_offset = Eigen::Matrix<double, TNumNodes, 1>::Zero();  ///< G − g̃⁰
    Eigen::Matrix<double, TNumNodes, 1> area_offset = Eigen::Matrix<double, TNumNodes, 1>::Zero();       ///< A − a⁰
    Eigen::Matrix<double, TNumNodes, 1> squared_area_offset =
        Eigen::Matrix<double, TNumNodes, 1>::Zero();  ///< Σ_c (a^c)² − (a⁰)²
    /// η̂_j Ĝ_j, the gap a penalty node is pushed with (λ̄ = ε η G, docs/theory/mortar.md §7 "Nodal penalty"), as a
    /// function of this pair's weighted gap g̃_j and area a_j: Ĝ = G + g̃ − g̃⁰, η̂ = (Σ_c (a^c)² + a² − (a⁰)²) /
    /// (A + a − a⁰)². Its derivative is this pair's part of ∂(ηG), η's included; the other pairs' parts enter the
    /// tangent through the nodal coupling (nodal_gap_coupling.h). Without a valid share: the pair's own g̃ (η = 1).
    template <class T>
    T PenaltyGap(int j, const T& pair_gap, const T& pair_area) const {
        const T gap = pair_gap + nodal_gap_offset[j];
        if (!shared[j] || area_offset[j] == 0.0) return gap;  // this pair alone: η = 1
        const T area = pair_area + area_offset[j];
        return gap * (pair_area * pair_area + squared_area_offset[j]) / (area * area);
    }
    Eigen::Matrix<double, TNumNodes, TDim> weighted_slip_offset =
        Eigen::Matrix<double, TNumNodes, TDim>::Zero();  ///< Σ_c a^c s^c − a⁰ s⁰ (AREA_WEIGHTED_PAIR_SLIP − a⁰ s⁰)

    template <class T>
    Eigen::Matrix<T, TDim, 1> Slip(int j, const Eigen::Matrix<T, TDim, 1>& pair_slip) const {
        return pair_slip / weight[j] + slip_offset.row(j).transpose().template cast<T>();
    }
    /// T̂_j(q) = (Σ_c a^c s^c + a_j(q) s_j(q) − a_j⁰ s_j⁰) / (A_j + a_j(q) − a_j⁰): the slip the pairs' penalty stick rows
    /// transmit (Σ_c a^c s^c / A), with this pair's area and slip varying, in the numerator and in A = NODAL_AREA
    /// (docs/theory/mortar.md §7 "Nodal penalty"). Its derivative is this pair's part of ∂T; the other pairs' parts
    /// enter the tangent through the nodal coupling (nodal_gap_coupling.h). Without a valid share: the pair's own s.
    template <class T>
    Eigen::Matrix<T, TDim, 1> TransmittedSlip(int j, const T& pair_area,
                                              const Eigen::Matrix<T, TDim, 1>& pair_slip) const {
        if (!shared[j] || area_offset[j] == 0.0) return pair_slip;  // this pair alone: T = s
        return (pair_slip * pair_area + weighted_slip_offset.row(j).transpose().template cast<T>()) /
               (pair_area + area_offset[j]);
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
        map.transmitted_gap[j] = ContactUtilities::TransmittedWeightedGap(node);
        map.gap_offset[j] = map.transmitted_gap[j] - share.gap[j];
        map.weighted_gap_offset[j] = node.GetValue(AREA_WEIGHTED_PAIR_GAP) - share.area[j] * share.gap[j];
        map.shared[j] = true;
        map.nodal_gap_offset[j] = node.FastGetSolutionStepValue(WEIGHTED_GAP) - share.gap[j];
        map.area_offset[j] = total_area - share.area[j];
        map.squared_area_offset[j] = node.GetValue(SQUARED_PAIR_AREA) - share.area[j] * share.area[j];
        if (frictional) {
            map.slip_offset.row(j) = node.FastGetSolutionStepValue(WEIGHTED_SLIP).template head<TDim>().transpose() -
                                     share.slip.row(j) / map.weight[j];
            map.weighted_slip_offset.row(j) =
                node.GetValue(AREA_WEIGHTED_PAIR_SLIP).template head<TDim>().transpose() -
                share.slip.row(j) * share.area[j];
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
