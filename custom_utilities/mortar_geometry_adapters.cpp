// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/mortar_geometry_adapters.h"

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/variables.h"

namespace contact_app {
namespace {

void CheckNodeCount(const Geometry& geometry, int expected) {
    CONTACT_CHECK(static_cast<int>(geometry.PointsNumber()) == expected, InputError, "geometry ", geometry.Name(),
                  " with nodes ", geometry.NodeIdsString(), " has ", geometry.PointsNumber(),
                  " nodes\n  expected: ", expected, " nodes for this mortar pair\n  fix: pair a condition of the ",
                  "matching face type (Line2D2, Triangle3D3 or Quadrilateral3D4)");
}

}  // namespace

template <int TDim, int TNN>
NodeCoordinates<double, TDim, TNN> CurrentCoordinates(const Geometry& geometry, bool* mesh_follows) {
    CheckNodeCount(geometry, TNN);
    NodeCoordinates<double, TDim, TNN> x;
    bool follows = true;
    for (int k = 0; k < TNN; ++k) {
        const Node& node = geometry[k];
        // X0 + u even when the mesh is not moved (move_mesh_flag false): the contact kinematics follow the
        // displacement, as the reference's X1 + u1 split does.
        if (node.SolutionStepsDataHas(DISPLACEMENT)) {
            const Array3 position = node.InitialCoordinates() + node.FastGetSolutionStepValue(DISPLACEMENT);
            follows = follows && (node.Coordinates() - position).squaredNorm() <=
                                     1e-24 * (1.0 + position.squaredNorm());
            x.row(k) = position.head<TDim>().transpose();
        } else {
            x.row(k) = node.Coordinates().head<TDim>().transpose();
        }
    }
    if (mesh_follows != nullptr) *mesh_follows = follows;
    return x;
}

template <int TDim, int TNN>
NodeCoordinates<double, TDim, TNN> MeshCoordinates(const Geometry& geometry) {
    CheckNodeCount(geometry, TNN);
    NodeCoordinates<double, TDim, TNN> x;
    for (int k = 0; k < TNN; ++k) x.row(k) = geometry[k].Coordinates().head<TDim>().transpose();
    return x;
}

template <int TDim, int TNN>
NodeCoordinates<double, TDim, TNN> CoordinatesAtStep(const Geometry& geometry, std::size_t step) {
    CheckNodeCount(geometry, TNN);
    NodeCoordinates<double, TDim, TNN> x;
    for (int k = 0; k < TNN; ++k) {
        const Array3 position = geometry[k].InitialCoordinates() + geometry[k].GetSolutionStepValue(DISPLACEMENT, step);
        x.row(k) = position.head<TDim>().transpose();
    }
    return x;
}

template <int TDim, int TNN>
NodeCoordinates<double, TDim, TNN> NodalNormals(const Geometry& geometry) {
    CheckNodeCount(geometry, TNN);
    NodeCoordinates<double, TDim, TNN> n;
    for (int k = 0; k < TNN; ++k) n.row(k) = geometry[k].GetSolutionStepValue(NORMAL).head<TDim>().transpose();
    return n;
}

#define CONTACT_APP_INSTANTIATE_ADAPTERS(A, D, NN)                                                       \
    template NodeCoordinates<double, D, NN> CurrentCoordinates<D, NN>(const Geometry&, bool*);           \
    template NodeCoordinates<double, D, NN> MeshCoordinates<D, NN>(const Geometry&);                     \
    template NodeCoordinates<double, D, NN> CoordinatesAtStep<D, NN>(const Geometry&, std::size_t);     \
    template NodeCoordinates<double, D, NN> NodalNormals<D, NN>(const Geometry&);
CONTACT_APP_FOR_EACH_MORTAR_FACE(CONTACT_APP_INSTANTIATE_ADAPTERS, ~)
#undef CONTACT_APP_INSTANTIATE_ADAPTERS

}  // namespace contact_app
