// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/kernel/geometries/geometry.h"
#include "custom_utilities/mortar_types.h"

namespace contact_app {

/// @brief Current node coordinates X0 + u (historical DISPLACEMENT; the node's coordinates when it has none) of a
///        kernel geometry as the n × d matrix the mortar utilities take; independent of whether the mesh is moved.
/// @throws InputError if the geometry does not have @p TNumNodes nodes
/// @param[in] geometry the face whose nodes are read, in its node order
/// @param[out] mesh_follows if given: false unless the mesh coordinates equal X0 + u at every node (to round-off)
template <int TDim, int TNumNodes>
NodeCoordinates<double, TDim, TNumNodes> CurrentCoordinates(const Geometry& geometry, bool* mesh_follows = nullptr);

/// @brief The coordinates the mesh holds (Coordinates()): X0 + u when the strategy moves the mesh, X0 when it does not
///        (move_mesh_flag false). The mortar operators and normals live on these.
template <int TDim, int TNumNodes>
NodeCoordinates<double, TDim, TNumNodes> MeshCoordinates(const Geometry& geometry);

/// @brief Start-of-step coordinates X0 + u(@p step) (historical DISPLACEMENT at buffer @p step).
/// @throws InputError if the node count is wrong or DISPLACEMENT is not historical / step is out of the buffer
template <int TDim, int TNumNodes>
NodeCoordinates<double, TDim, TNumNodes> CoordinatesAtStep(const Geometry& geometry, std::size_t step);

/// @brief Historical nodal NORMAL (buffer 0) of the geometry's nodes, n × d.
/// @throws InputError if the node count is wrong or NORMAL is not a historical variable
template <int TDim, int TNumNodes>
NodeCoordinates<double, TDim, TNumNodes> NodalNormals(const Geometry& geometry);

/// @brief First TDim components of a kernel Array3.
template <int TDim>
SpatialVector<double, TDim> ToSpatialVector(const Array3& value) {
    return value.head<TDim>();
}

}  // namespace contact_app
