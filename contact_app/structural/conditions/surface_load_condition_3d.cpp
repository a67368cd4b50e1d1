// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/structural/conditions/surface_load_condition_3d.h"

#include <memory>

#include <Eigen/Geometry>

#include "contact_app/kernel/variables.h"

namespace contact_app {

namespace {

/// [a]× with [a]× b = a × b.
Eigen::Matrix3d CrossMatrix(const Eigen::Vector3d& a) {
    Eigen::Matrix3d result;
    result << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
    return result;
}

}  // namespace

SurfaceLoadCondition3D::Pointer SurfaceLoadCondition3D::Create(IndexType new_id, Geometry::Pointer geometry,
                                                               Properties::Pointer properties) const {
    return std::make_shared<SurfaceLoadCondition3D>(new_id, std::move(geometry), std::move(properties));
}

void SurfaceLoadCondition3D::CalculateAll(Matrix* pLhs, Vector* pRhs, const ProcessInfo&) const {
    const Geometry& geometry = GetGeometry();
    const Eigen::Index n = static_cast<Eigen::Index>(geometry.size());
    const Eigen::Vector3d condition_load = GetValue(SURFACE_LOAD);
    const auto nodal_loads = NodalLoads(SURFACE_LOAD, false);
    const auto nodal_pressures = NodalPressures();

    Vector N;
    Matrix DN;
    for (const IntegrationPoint& point : geometry.IntegrationPoints(geometry.DefaultIntegrationOrder() + 1)) {
        geometry.ShapeFunctionsValues(N, point.local);
        geometry.ShapeFunctionsLocalGradients(DN, point.local);
        Eigen::Vector3d t_xi = Eigen::Vector3d::Zero(), t_eta = Eigen::Vector3d::Zero();
        Eigen::Vector3d load = condition_load;
        double pressure = 0.0;
        for (Eigen::Index k = 0; k < n; ++k) {
            t_xi += DN(k, 0) * geometry[k].Coordinates();
            t_eta += DN(k, 1) * geometry[k].Coordinates();
            load += N[k] * nodal_loads[k];
            pressure += N[k] * nodal_pressures[k];
        }
        const Eigen::Vector3d normal = t_xi.cross(t_eta);  // |normal| = det J
        const double area = normal.norm();
        if (pRhs != nullptr) {
            const Eigen::Vector3d force = area * load + pressure * normal;
            for (Eigen::Index i = 0; i < n; ++i) pRhs->segment<3>(3 * i) += point.weight * N[i] * force;
        }
        if (pLhs == nullptr) continue;
        // docs/theory/structural.md §8 D1: Kratos scales the pressure stiffness by det J and omits the SURFACE_LOAD
        // term;
        // this is the exact −∂f/∂u (changes only Newton convergence, not the converged state).
        const Eigen::Matrix3d dforce_dnormal = load * (normal / area).transpose() + pressure * Eigen::Matrix3d::Identity();
        const Eigen::Matrix3d cross_xi = CrossMatrix(t_xi), cross_eta = CrossMatrix(t_eta);
        for (Eigen::Index j = 0; j < n; ++j) {
            const Eigen::Matrix3d dnormal = DN(j, 1) * cross_xi - DN(j, 0) * cross_eta;  // ∂a/∂x_j
            const Eigen::Matrix3d dforce = dforce_dnormal * dnormal;
            for (Eigen::Index i = 0; i < n; ++i) pLhs->block<3, 3>(3 * i, 3 * j) -= point.weight * N[i] * dforce;
        }
    }
}

}  // namespace contact_app
