// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <unordered_map>
#include <vector>

#include "contact_app/kernel/types.h"
#include "custom_utilities/mortar_types.h"

namespace contact_app {

class Geometry;
class ModelPart;
class Node;

/// @brief Mean nodal normals of a model part (Kratos MortarUtilities::ComputeNodesMeanNormalModelPart):
///        historical NORMAL of every node is reset; each condition whose local dimension is its working
///        dimension − 1 (paired/coupling conditions are skipped) gets its unit normal at the centre as the
///        non-historical condition NORMAL (if @p compute_conditions) and adds to each of its nodes its unit
///        normal at that node (unweighted); finally the nodal sums are normalised.
/// @param[in,out] model_part its nodes must store NORMAL as a historical variable
/// @param[in] compute_conditions also write the condition NORMAL values
/// @throws InputError if NORMAL is not a historical variable, or an INTERFACE node ends with a zero normal
void ComputeNodesMeanNormalModelPart(ModelPart& model_part, bool compute_conditions = true);

/// @brief Derivative of the mean nodal NORMAL of ComputeNodesMeanNormalModelPart with respect to the current coordinates
///        of the nodes it reads (docs/theory/mortar.md §7 "Normals that follow the iterate"):
///        n = s/|s|, s = Σ_f ν_f (the unit normal of each face f through the node, at the node), so
///        ∂n/∂x_k = (I − n nᵀ)/|s| Σ_f ∂ν_f/∂x_k over the nodes k of those faces.
class MeanNormalDerivatives {
public:
    /// The faces of @p model_part that ComputeNodesMeanNormalModelPart sums (not paired, local dimension d − 1), by node.
    explicit MeanNormalDerivatives(const ModelPart& model_part);
    /// @param[in] node a node of the model part
    /// @param[out] rNodes the nodes of the faces through @p node, each once
    /// @param[out] rJacobian d × d·rNodes.size(): column d k + c is ∂n/∂(component c of rNodes[k])
    /// @return false if no face holds the node or their normals cancel
    bool Compute(const Node& node, std::vector<const Node*>& rNodes, Matrix& rJacobian) const;

private:
    std::unordered_map<IndexType, std::vector<const Geometry*>> mFaces;
};

/// @brief Unit normal of a linear face at local point @p local, templated on the scalar (NV variants
///        differentiate it). Line2D2: (t_y, −t_x)/|t| with t = dx/dξ; surfaces: (J₀ × J₁)/|J₀ × J₁|, the
///        kernel's Geometry::UnitNormal convention. Zero vector for a degenerate face (never NaN).
/// @param[in] x n × d node coordinates; @param[in] local (d−1) local coordinates
template <int TDim, int TNumNodes, class T>
SpatialVector<T, TDim> FaceUnitNormal(const NodeCoordinates<T, TDim, TNumNodes>& x,
                                      const Eigen::Matrix<double, TDim - 1, 1>& local);

/// @brief FaceUnitNormal at the reference centre (the condition NORMAL, docs/theory/mortar.md §5).
template <int TDim, int TNumNodes, class T>
SpatialVector<T, TDim> FaceCenterUnitNormal(const NodeCoordinates<T, TDim, TNumNodes>& x);

/// @brief FaceUnitNormal of this face at each of its nodes (row i = node i): the NV linearisation of the
///        nodal normals restricted to the face's own geometry (docs/theory/mortar.md §5, with the exact
///        derivative (δa − n(n·δa))/|a| instead of the coded one [BUG?]).
template <int TDim, int TNumNodes, class T>
NodeCoordinates<T, TDim, TNumNodes> FaceNodalUnitNormals(const NodeCoordinates<T, TDim, TNumNodes>& x);

}  // namespace contact_app
