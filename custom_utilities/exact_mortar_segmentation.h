// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "custom_utilities/mortar_types.h"

namespace contact_app {

/// Exact mortar segmentation of one slave/master pair (Kratos ExactMortarIntegrationUtility, Popp §3.3):
/// the master is projected along the slave normal n_s onto the plane (slave centre, n_s), clipped against
/// the slave (inside nodes + edge–edge intersections, each tagged with its PointBelongs value), ordered
/// around its centroid and triangulated into TDim-vertex cells stored in slave local coordinates.
/// Everything is templated on the scalar, so Dual coordinates give ∂(cells)/∂(coordinates) for free;
/// the normal has its own scalar type (double when the linearisation holds it constant).
/// Robust by construction: touching, parallel, coincident or inverted faces give either valid cells or an
/// empty result (never a NaN). Theory: docs/theory/mortar.md §1.
/// @tparam TDim 2 (Line2D2 pairs) or 3; @tparam TNumNodes slave nodes; @tparam TNumNodesMaster master nodes
/// @tparam TScalar double or Dual<N>
template <int TDim, int TNumNodes, int TNumNodesMaster, class TScalar = double>
class ExactMortarSegmentation {
public:
    using SlaveCoordinates = NodeCoordinates<TScalar, TDim, TNumNodes>;
    using MasterCoordinates = NodeCoordinates<TScalar, TDim, TNumNodesMaster>;
    using Cell = MortarCell<TScalar, TDim>;

    explicit ExactMortarSegmentation(SegmentationSettings settings = {}) : mSettings(settings) {}

    /// @brief Integration cells of the pair.
    /// @param[in] slave n_s × d current slave coordinates
    /// @param[in] slave_normal d-vector, outward unit normal of the slave face (condition NORMAL); need not
    ///            be exactly unit
    /// @param[in] master n_m × d current master coordinates
    /// @param[out] cells cleared, then filled (slave local coordinates + belong tags)
    /// @return true iff at least one cell was produced
    template <class TNormal>
    bool ComputeCells(const SlaveCoordinates& slave, const SpatialVector<TNormal, TDim>& slave_normal,
                      const MasterCoordinates& master, MortarCells<TScalar, TDim>& cells) const;

    /// @brief Whether a cell is degenerate: global length < 1e−12·(slave length) in 2D (Kratos LengthCheck),
    ///        Heron area < 1e−12·(longest edge)² in 3D (HeronCheck). Degenerate cells are skipped everywhere.
    bool IsDegenerate(const SlaveCoordinates& slave, const Cell& cell) const;

    /// @brief Sum of the global measures (length / area) of the non-degenerate cells.
    TScalar TotalArea(const SlaveCoordinates& slave, const MortarCells<TScalar, TDim>& cells) const;

    const SegmentationSettings& Settings() const { return mSettings; }

private:
    SegmentationSettings mSettings;
};

/// @brief Kratos rule deciding whether a pair contributes: overlap area / slave area > 1e−5
///        (otherwise the condition is flagged ISOLATED and contributes nothing).
bool IsMortarPairUsed(double integration_area, double slave_area);

/// @brief Decodes an edge–edge PointBelongs tag v > B into (s0, s1, m0, m1). @return false if v ≤ B
bool DecodeEdgeIntersectionTag(int tag, int base_tag, int& s0, int& s1, int& m0, int& m1);

}  // namespace contact_app
