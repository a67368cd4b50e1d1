// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/oriented_bounding_box.h"

#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "contact_app/kernel/exceptions.h"

namespace contact_app {

OrientedBoundingBox::OrientedBoundingBox(const Geometry& face, double thickness) {
    mDim = face.WorkingSpaceDimension();
    Matrix local_nodes;
    face.PointsLocalCoordinates(local_nodes);
    Array3 local_centre = Array3::Zero();
    for (Eigen::Index i = 0; i < local_nodes.rows(); ++i)
        for (Eigen::Index j = 0; j < local_nodes.cols(); ++j) local_centre[j] += local_nodes(i, j) / local_nodes.rows();
    const Array3 normal = face.UnitNormal(local_centre);
    Array3 tangent = face[1].Coordinates() - face[0].Coordinates();
    tangent -= tangent.dot(normal) * normal;
    CONTACT_CHECK(tangent.norm() > 0.0, InputError, "OrientedBoundingBox: degenerate face with nodes ",
                  face.NodeIdsString(), "\n  fix: check the contact mesh for collapsed faces");
    tangent.normalize();
    if (mDim == 2) {
        mAxes = {tangent, normal, Array3(0.0, 0.0, 1.0)};
    } else {
        mAxes = {tangent, normal.cross(tangent).normalized(), normal};
    }
    const int normal_axis = mDim == 2 ? 1 : 2;
    Array3 lo = Array3::Constant(std::numeric_limits<double>::max());
    Array3 hi = -lo;
    for (std::size_t i = 0; i < face.PointsNumber(); ++i)
        for (int k = 0; k < mDim; ++k) {
            const double s = face[i].Coordinates().dot(mAxes[k]);
            lo[k] = std::min(lo[k], s);
            hi[k] = std::max(hi[k], s);
        }
    mCenter = Array3::Zero();
    for (int k = 0; k < mDim; ++k) {
        mHalf[k] = 0.5 * (hi[k] - lo[k]);
        mCenter += 0.5 * (hi[k] + lo[k]) * mAxes[k];
    }
    if (mDim == 2) mCenter[2] = face[0].Coordinates()[2];
    mHalf[normal_axis] += thickness;
}

OrientedBoundingBox::OrientedBoundingBox(int dim, const Array3& center, const std::array<Array3, 3>& axes,
                                         const Array3& half_lengths)
    : mDim(dim), mCenter(center), mAxes(axes), mHalf(half_lengths) {
    if (mDim == 2) mHalf[2] = 0.0;
}

void OrientedBoundingBox::ExtendAlong(const Array3& direction, double length) {
    int axis = 0;
    for (int k = 1; k < mDim; ++k)
        if (std::abs(mAxes[k].dot(direction)) > std::abs(mAxes[axis].dot(direction))) axis = k;
    const double sign = mAxes[axis].dot(direction) < 0.0 ? -1.0 : 1.0;
    mCenter += 0.5 * length * sign * mAxes[axis];
    mHalf[axis] += 0.5 * length;
}

double OrientedBoundingBox::ProjectedRadius(const Array3& axis) const {
    double radius = 0.0;
    for (int k = 0; k < mDim; ++k) radius += mHalf[k] * std::abs(mAxes[k].dot(axis));
    return radius;
}

bool OrientedBoundingBox::SeparatedAlong(const OrientedBoundingBox& other, const Array3& axis) const {
    const double distance = std::abs((other.mCenter - mCenter).dot(axis));
    return distance > ProjectedRadius(axis) + other.ProjectedRadius(axis);
}

bool OrientedBoundingBox::HasIntersection(const OrientedBoundingBox& other) const {
    const int dim = std::max(mDim, other.mDim);
    for (int k = 0; k < mDim; ++k)
        if (SeparatedAlong(other, mAxes[k])) return false;
    for (int k = 0; k < other.mDim; ++k)
        if (SeparatedAlong(other, other.mAxes[k])) return false;
    if (dim == 2) return true;
    // Edge-edge axes; a (nearly) zero cross product means parallel edges, already covered by the face axes.
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const Array3 axis = mAxes[i].cross(other.mAxes[j]);
            const double norm = axis.norm();
            if (norm < 1e-12) continue;
            if (SeparatedAlong(other, axis / norm)) return false;
        }
    return true;
}

}  // namespace contact_app
