// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/mortar_normals.h"

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/face_checks.h"
#include "contact_app/kernel/model_part.h"
#include "contact_app/kernel/variables.h"
#include "custom_utilities/mortar_geometry_math.h"

namespace contact_app {

void ComputeNodesMeanNormalModelPart(ModelPart& model_part, bool compute_conditions) {
    CONTACT_CHECK(model_part.HasNodalSolutionStepVariable(NORMAL), InputError, "model part \"",
                  model_part.FullName(), "\" has no historical NORMAL\n  expected: NORMAL among the nodal ",
                  "solution-step variables\n  fix: call AddNodalSolutionStepVariable(NORMAL) before reading the mesh");
    for (const auto& node : model_part.Nodes()) node->FastGetSolutionStepValue(NORMAL) = Array3::Zero();
    Matrix local_nodes;
    for (const auto& condition : model_part.Conditions()) {
        Geometry& geometry = condition->GetGeometry();
        if (geometry.NumberOfGeometryParts() > 0) continue;  // paired conditions carry no own normal
        if (geometry.LocalSpaceDimension() != geometry.WorkingSpaceDimension() - 1) continue;
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
