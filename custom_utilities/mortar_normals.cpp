// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/mortar_normals.h"

#include <algorithm>

#include "automatic_differentiation/ad_helpers.h"

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/face_checks.h"
#include "contact_app/kernel/model_part.h"
#include "contact_app/kernel/variables.h"
#include "custom_utilities/mortar_geometry_math.h"

namespace contact_app {
namespace {

/// The faces whose normals the mean nodal normal sums: not a paired condition, local dimension d − 1.
bool ContributesToMeanNormal(const Geometry& geometry) {
    return geometry.NumberOfGeometryParts() == 0 &&
           geometry.LocalSpaceDimension() == geometry.WorkingSpaceDimension() - 1;
}

}  // namespace

void ComputeNodesMeanNormalModelPart(ModelPart& model_part, bool compute_conditions) {
    CONTACT_CHECK(model_part.HasNodalSolutionStepVariable(NORMAL), InputError, "model part \"",
                  model_part.FullName(), "\" has no historical NORMAL\n  expected: NORMAL among the nodal ",
                  "solution-step variables\n  fix: call AddNodalSolutionStepVariable(NORMAL) before reading the mesh");
    for (const auto& node : model_part.Nodes()) node->FastGetSolutionStepValue(NORMAL) = Array3::Zero();
    Matrix local_nodes;
    for (const auto& condition : model_part.Conditions()) {
        Geometry& geometry = condition->GetGeometry();
        if (!ContributesToMeanNormal(geometry)) continue;  // paired conditions carry no own normal
        geometry.PointsLocalCoordinates(local_nodes);
        Array3 center = Array3::Zero();
        for (Eigen::Index k = 0; k < local_nodes.rows(); ++k) center.head(local_nodes.cols()) += local_nodes.row(k).transpose();
        center /= static_cast<double>(local_nodes.rows());
        if (compute_conditions) condition->SetValue(NORMAL, ConditionUnitNormal(*condition, model_part, center));
        for (std::size_t k = 0; k < geometry.size(); ++k) {
            Array3 local = Array3::Zero();
            local.head(local_nodes.cols()) = local_nodes.row(static_cast<Eigen::Index>(k)).transpose();
            geometry[k].FastGetSolutionStepValue(NORMAL) += ConditionUnitNormal(*condition, model_part, local);
        }
    }
    for (const auto& node : model_part.Nodes()) {
        Array3& normal = node->FastGetSolutionStepValue(NORMAL);
        const double norm = normal.norm();
        if (norm > 0.0) {
            normal /= norm;
        } else {
            CONTACT_CHECK(!node->Is(INTERFACE), InputError, "node ", node->Id(), " of model part \"",
                          model_part.FullName(), "\" is flagged INTERFACE but its mean normal is zero\n",
                          "  expected: at least one surface condition of the interface through the node, with ",
                          "a consistent orientation\n  fix: check the contact model part's conditions and their ",
                          "node ordering (opposite faces cancel)");
        }
    }
}

template <int TDim, int TNN, class T>
SpatialVector<T, TDim> FaceUnitNormal(const NodeCoordinates<T, TDim, TNN>& x, const Eigen::Matrix<double, TDim - 1, 1>& local) {
    const Eigen::Matrix<T, TDim, TDim - 1> jac =
        x.transpose() * detail::FaceShapeGradients<TNN, double>(local).template cast<T>();
    SpatialVector<T, TDim> normal;
    if constexpr (TDim == 2) {
        normal << jac(1, 0), -jac(0, 0);
    } else {
        normal = detail::Vec3<T>(jac.col(0)).cross(detail::Vec3<T>(jac.col(1)));
    }
    const T length = detail::Norm<T>(normal);
    if (!(Value(length) > 0.0)) return SpatialVector<T, TDim>::Zero();
    return normal / length;
}

template <int TDim, int TNN, class T>
SpatialVector<T, TDim> FaceCenterUnitNormal(const NodeCoordinates<T, TDim, TNN>& x) {
    return FaceUnitNormal<TDim, TNN, T>(x, detail::FaceCentroid<TNN>());
}

template <int TDim, int TNN, class T>
NodeCoordinates<T, TDim, TNN> FaceNodalUnitNormals(const NodeCoordinates<T, TDim, TNN>& x) {
    static const std::array<std::array<double, 2>, 4> kQuad{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
    static const std::array<std::array<double, 2>, 3> kTriangle{{{0, 0}, {1, 0}, {0, 1}}};
    NodeCoordinates<T, TDim, TNN> normals;
    for (int k = 0; k < TNN; ++k) {
        Eigen::Matrix<double, TDim - 1, 1> local;
        if constexpr (TNN == 2) {
            local[0] = k == 0 ? -1.0 : 1.0;
        } else if constexpr (TNN == 3) {
            local << kTriangle[k][0], kTriangle[k][1];
        } else {
            local << kQuad[k][0], kQuad[k][1];
        }
        normals.row(k) = FaceUnitNormal<TDim, TNN, T>(x, local).transpose();
    }
    return normals;
}

namespace {

/// Adds face @p face's unit normal at its node @p local to @p rSum and its derivative (d × d·NN, node-major) to the
/// columns of @p rDerivative that @p rNodes assigns to the face's nodes (appending new nodes).
template <int TDim, int TNN>
void AddFaceNormalAtNode(const Geometry& face, int local, std::vector<const Node*>& rNodes,
                         SpatialVector<double, TDim>& rSum, Matrix& rDerivative) {
    NodeCoordinates<double, TDim, TNN> x;
    for (int k = 0; k < TNN; ++k) x.row(k) = face[k].Coordinates().template head<TDim>().transpose();
    using Scalar = Dual<TDim * TNN>;
    const NodeCoordinates<Scalar, TDim, TNN> normals = FaceNodalUnitNormals<TDim, TNN, Scalar>(Seed<TDim * TNN>(x, 0));
    for (int k = 0; k < TNN; ++k) {
        const Node* node = &face[k];
        auto found = std::find(rNodes.begin(), rNodes.end(), node);
        const auto column = static_cast<Eigen::Index>(TDim * (found - rNodes.begin()));
        if (found == rNodes.end()) {
            rNodes.push_back(node);
            rDerivative.conservativeResize(TDim, column + TDim);
            rDerivative.rightCols(TDim).setZero();
        }
        for (int r = 0; r < TDim; ++r)
            rDerivative.block(r, column, 1, TDim) += normals(local, r).Derivatives().template segment<TDim>(TDim * k).transpose();
    }
    for (int r = 0; r < TDim; ++r) rSum[r] += normals(local, r).Value();
}

template <int TDim>
bool MeanNormalDerivative(const std::vector<const Geometry*>& faces, const Node& node, std::vector<const Node*>& rNodes,
                          Matrix& rJacobian) {
    SpatialVector<double, TDim> sum = SpatialVector<double, TDim>::Zero();
    Matrix derivative(TDim, 0);
    for (const Geometry* face : faces) {
        int local = 0;
        while (&(*face)[local] != &node) ++local;
        if constexpr (TDim == 2) {
            AddFaceNormalAtNode<2, 2>(*face, local, rNodes, sum, derivative);
        } else if (face->size() == 3) {
            AddFaceNormalAtNode<3, 3>(*face, local, rNodes, sum, derivative);
        } else {
            AddFaceNormalAtNode<3, 4>(*face, local, rNodes, sum, derivative);
        }
    }
    const double length = sum.norm();
    if (!(length > 0.0)) return false;
    const SpatialVector<double, TDim> n = sum / length;
    const Eigen::Matrix<double, TDim, TDim> projector =
        (Eigen::Matrix<double, TDim, TDim>::Identity() - n * n.transpose()) / length;
    rJacobian = projector * derivative;
    return true;
}

}  // namespace

MeanNormalDerivatives::MeanNormalDerivatives(const ModelPart& model_part) {
    for (const auto& condition : model_part.Conditions()) {
        const Geometry& geometry = condition->GetGeometry();
        if (!ContributesToMeanNormal(geometry)) continue;
        const bool linear_face = geometry.WorkingSpaceDimension() == 2 ? geometry.size() == 2
                                                                       : geometry.size() == 3 || geometry.size() == 4;
        CONTACT_CHECK(linear_face, InputError, "condition ", condition->Id(), " of model part \"", model_part.FullName(),
                      "\" is a ", geometry.size(), "-node face in ", geometry.WorkingSpaceDimension(),
                      "D\n  expected: a 2-node line (2D), a 3-node triangle or a 4-node quadrilateral (3D)",
                      "\n  fix: use linear faces on the contact surface");
        for (std::size_t k = 0; k < geometry.size(); ++k) mFaces[geometry[k].Id()].push_back(&geometry);
    }
}

bool MeanNormalDerivatives::Compute(const Node& node, std::vector<const Node*>& rNodes, Matrix& rJacobian) const {
    rNodes.clear();
    const auto found = mFaces.find(node.Id());
    if (found == mFaces.end()) return false;
    return found->second.front()->WorkingSpaceDimension() == 2
               ? MeanNormalDerivative<2>(found->second, node, rNodes, rJacobian)
               : MeanNormalDerivative<3>(found->second, node, rNodes, rJacobian);
}

#define CONTACT_APP_INSTANTIATE_NORMALS(D, NN, T)                                                                \
    template SpatialVector<T, D> FaceUnitNormal<D, NN, T>(const NodeCoordinates<T, D, NN>&,                      \
                                                          const Eigen::Matrix<double, D - 1, 1>&);             \
    template SpatialVector<T, D> FaceCenterUnitNormal<D, NN, T>(const NodeCoordinates<T, D, NN>&);             \
    template NodeCoordinates<T, D, NN> FaceNodalUnitNormals<D, NN, T>(const NodeCoordinates<T, D, NN>&);
// double per face; the slave face with the AD scalar of each pair, Dual<d(n_s + n_m)>.
#define CONTACT_APP_INSTANTIATE_FACE_NORMALS(A, D, NN) CONTACT_APP_INSTANTIATE_NORMALS(D, NN, double)
#define CONTACT_APP_INSTANTIATE_PAIR_NORMALS(A, D, NS, NM) CONTACT_APP_INSTANTIATE_NORMALS(D, NS, Dual<D*(NS + NM)>)
CONTACT_APP_FOR_EACH_MORTAR_FACE(CONTACT_APP_INSTANTIATE_FACE_NORMALS, ~)
CONTACT_APP_FOR_EACH_MORTAR_PAIR(CONTACT_APP_INSTANTIATE_PAIR_NORMALS, ~)
#undef CONTACT_APP_INSTANTIATE_PAIR_NORMALS
#undef CONTACT_APP_INSTANTIATE_FACE_NORMALS
#undef CONTACT_APP_INSTANTIATE_NORMALS

}  // namespace contact_app
