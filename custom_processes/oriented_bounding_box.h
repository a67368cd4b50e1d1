// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>

#include "contact_app/kernel/geometries/geometry.h"

namespace contact_app {

/// Oriented bounding box of a contact face (the narrow-phase filter of the *_with_obb searches, Kratos
/// OrientedBoundingBox<TDim>): axes = the face's in-plane tangents and its unit normal at the centre; the
/// in-plane half-lengths cover the face nodes, the normal half-length is the nodes' out-of-plane spread plus
/// @p thickness (so a flat face gives a slab of total thickness 2·thickness). In 2D the third axis is e_z
/// with zero half-length and is never tested. Intersection by the separating axis theorem.
class OrientedBoundingBox {
public:
    /// @param[in] face a line (2D) or a surface (3D) face
    /// @param[in] thickness half-thickness added along the normal (≥ 0)
    /// @throws InputError for a degenerate face (zero normal)
    OrientedBoundingBox(const Geometry& face, double thickness);
    /// @brief A box from its centre, orthonormal axes and half-lengths (tests, debugging).
    /// @param[in] dim 2 (axes 0,1 in the xy plane) or 3
    /// @param[in] center centre of the box
    /// @param[in] axes three orthonormal axes (in 2D the third is e_z and is never tested)
    /// @param[in] half_lengths half-length along each axis (≥ 0; in 2D the third is set to 0)
    OrientedBoundingBox(int dim, const Array3& center, const std::array<Array3, 3>& axes, const Array3& half_lengths);

    /// @brief Separating axis theorem: true unless some axis separates the boxes strictly. 2D: the 4 box axes;
    ///        3D: the 6 box axes and the 9 (non-degenerate) cross products.
    bool HasIntersection(const OrientedBoundingBox& other) const;
    /// @brief Grows the box by @p length on one side: along the axis closest to @p direction, towards it
    ///        (the slave box swept behind the face, into its own body, where a penetrated master lies).
    /// @param[in] direction any non-zero vector; @param[in] length ≥ 0, in model units
    void ExtendAlong(const Array3& direction, double length);

    int Dimension() const { return mDim; }
    const Array3& Center() const { return mCenter; }
    const std::array<Array3, 3>& Axes() const { return mAxes; }
    const Array3& HalfLengths() const { return mHalf; }

private:
    /// Whether the projections of the two boxes on @p axis are disjoint.
    bool SeparatedAlong(const OrientedBoundingBox& other, const Array3& axis) const;
    double ProjectedRadius(const Array3& axis) const;

    int mDim = 3;
    Array3 mCenter = Array3::Zero();
    std::array<Array3, 3> mAxes;
    Array3 mHalf = Array3::Zero();
};

}  // namespace contact_app
