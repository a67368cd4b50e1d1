// SPDX-License-Identifier: BSD-3-Clause
/// Helpers shared by the geometry tests: nodes from coordinates, sample points, distorted elements.
#pragma once

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "contact_app/kernel/geometries/geometry.h"
#include "contact_app/kernel/geometries/geometry_factory.h"

namespace contact_app::testing {

/// Nodes with ids first_id, first_id + 1, ... at @p coordinates.
inline Geometry::PointsArrayType MakeNodes(const std::vector<Array3>& coordinates, IndexType first_id = 1) {
    Geometry::PointsArrayType nodes;
    for (const Array3& x : coordinates)
        nodes.push_back(std::make_shared<Node>(first_id + nodes.size(), x[0], x[1], x[2]));
    return nodes;
}

inline Geometry::Pointer MakeGeometry(const std::string& name, const std::vector<Array3>& coordinates) {
    return CreateGeometry(name, MakeNodes(coordinates));
}

/// Interior local points of a family's reference element (not at nodes, not symmetric).
inline std::vector<Array3> SampleLocalPoints(GeometryFamily family) {
    switch (family) {
        case GeometryFamily::Point: return {Array3::Zero()};
        case GeometryFamily::Linear: return {Array3(-0.7, 0, 0), Array3(0.1, 0, 0), Array3(0.55, 0, 0)};
        case GeometryFamily::Triangle: return {Array3(0.2, 0.3, 0), Array3(0.6, 0.1, 0), Array3(0.05, 0.85, 0)};
        case GeometryFamily::Quadrilateral:
            return {Array3(-0.7, 0.2, 0), Array3(0.3, -0.4, 0), Array3(0.9, 0.85, 0)};
        case GeometryFamily::Tetrahedra:
            return {Array3(0.1, 0.2, 0.3), Array3(0.6, 0.1, 0.05), Array3(0.2, 0.2, 0.5)};
        case GeometryFamily::Hexahedra:
            return {Array3(-0.6, 0.3, 0.8), Array3(0.1, -0.9, -0.2), Array3(0.5, 0.5, -0.5)};
        case GeometryFamily::Prism:
            return {Array3(0.2, 0.3, 0.1), Array3(0.6, 0.1, 0.7), Array3(0.1, 0.8, 0.95)};
    }
    return {};
}

/// A local point just outside the reference element.
inline Array3 OutsideLocalPoint(GeometryFamily family) {
    switch (family) {
        case GeometryFamily::Linear: return Array3(1.3, 0, 0);
        case GeometryFamily::Triangle: return Array3(0.7, 0.6, 0);
        case GeometryFamily::Quadrilateral: return Array3(1.2, 0.3, 0);
        case GeometryFamily::Tetrahedra: return Array3(0.5, 0.4, 0.3);
        case GeometryFamily::Hexahedra: return Array3(0.2, -1.25, 0.3);
        case GeometryFamily::Prism: return Array3(0.2, 0.3, 1.2);
        default: return Array3(1, 0, 0);
    }
}

/// Node count encoded in a Kratos geometry name: the digits after the last "D" ("Tetrahedra3D10" → 10);
/// "Point3D" → 1.
inline std::size_t NodeCountFromName(const std::string& name) {
    const std::size_t last = name.find_last_not_of("0123456789");
    return last + 1 == name.size() ? 1 : std::stoul(name.substr(last + 1));
}

/// Node local coordinates of geometry type @p name, padded to Array3.
inline std::vector<Array3> ReferenceNodes(const std::string& name) {
    const Geometry::Pointer probe =
        MakeGeometry(name, std::vector<Array3>(NodeCountFromName(name), Array3::Zero()));
    Matrix local;
    probe->PointsLocalCoordinates(local);
    std::vector<Array3> nodes(local.rows(), Array3::Zero());
    for (Eigen::Index k = 0; k < local.rows(); ++k) nodes[k].head(local.cols()) = local.row(k).transpose();
    return nodes;
}

/// A mildly curved map ξ ↦ A(ξ + 0.08 s(ξ)) + b into the working space: straight-sided elements stay
/// straight (only their nodes move), quadratic ones get curved edges, quadrilaterals/hexahedra become
/// non-affine, surfaces in 3D get tilted (and quadrilaterals warped), lines in 3D leave the xy-plane.
inline Array3 DistortionMap(const Array3& xi, int working_dim) {
    const Array3 q =
        xi + 0.08 * Array3(std::sin(1.3 * xi[1] + 0.2 * xi[2]), std::sin(0.9 * xi[0] + 0.5 * xi[2] + 0.3),
                           std::sin(1.1 * xi[0] - 0.7 * xi[1]));
    if (working_dim == 2) {
        Eigen::Matrix2d A;
        A << 1.3, 0.4, -0.2, 0.9;
        Array3 x = Array3::Zero();
        x.head<2>() = A * q.head<2>() + Eigen::Vector2d(0.5, -1.0);
        return x;
    }
    Eigen::Matrix3d A;
    A << 1.2, 0.3, -0.1, 0.1, 0.9, 0.2, -0.2, 0.1, 1.1;
    return A * q + Array3(0.5, -1.0, 2.0);
}

/// Geometry @p name on the distorted images of its reference nodes (node ids 1..n).
inline Geometry::Pointer DistortedGeometry(const std::string& name) {
    const std::vector<Array3> reference = ReferenceNodes(name);
    const int working_dim = CreateGeometry(name, MakeNodes(reference))->WorkingSpaceDimension();
    std::vector<Array3> coordinates;
    for (const Array3& xi : reference) coordinates.push_back(DistortionMap(xi, working_dim));
    return MakeGeometry(name, coordinates);
}

}  // namespace contact_app::testing
