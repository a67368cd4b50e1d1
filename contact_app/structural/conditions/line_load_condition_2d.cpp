// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/structural/conditions/line_load_condition_2d.h"

#include <memory>

#include "contact_app/kernel/variables.h"

namespace contact_app {

LineLoadCondition2D::Pointer LineLoadCondition2D::Create(IndexType new_id, Geometry::Pointer geometry,
                                                         Properties::Pointer properties) const {
    return std::make_shared<LineLoadCondition2D>(new_id, std::move(geometry), std::move(properties));
}

double LineLoadCondition2D::CircumferenceFactor(const Vector& N, Vector& rDerivative) const {
    rDerivative = Vector::Zero(N.size());
    return 1.0;
}

void LineLoadCondition2D::CalculateAll(Matrix* pLhs, Vector* pRhs, const ProcessInfo&) const {
    const Geometry& geometry = GetGeometry();
    const Eigen::Index n = static_cast<Eigen::Index>(geometry.size());
    const Eigen::Vector2d condition_load = GetValue(LINE_LOAD).head<2>();
    const auto nodal_loads = NodalLoads(LINE_LOAD, true);
    const auto nodal_pressures = NodalPressures();
    Eigen::Matrix2d rotation;  // n = R t
    rotation << 0.0, 1.0, -1.0, 0.0;

    Vector N, c_derivative;
    Matrix DN;
    for (const IntegrationPoint& point : geometry.IntegrationPoints(geometry.DefaultIntegrationOrder() + 1)) {
        geometry.ShapeFunctionsValues(N, point.local);
        geometry.ShapeFunctionsLocalGradients(DN, point.local);
        Eigen::Vector2d tangent = Eigen::Vector2d::Zero();
        Eigen::Vector2d load = condition_load;
        double pressure = 0.0;
        for (Eigen::Index k = 0; k < n; ++k) {
            tangent += DN(k, 0) * geometry[k].Coordinates().head<2>();
            load += N[k] * nodal_loads[k].head<2>();
            pressure += N[k] * nodal_pressures[k];
        }
        const double length = tangent.norm();  // det J
        const double factor = CircumferenceFactor(N, c_derivative);
        const Eigen::Vector2d force = length * load - pressure * (rotation * tangent);  // per unit ξ, before c
        if (pRhs != nullptr)
            for (Eigen::Index i = 0; i < n; ++i) pRhs->segment<2>(2 * i) += point.weight * factor * N[i] * force;
        if (pLhs == nullptr) continue;
        // docs/theory/structural.md §8 D1: Kratos scales the pressure stiffness by det J·THICKNESS and drops the
        // LINE_LOAD
        // term; this is the exact −∂f/∂u (changes only Newton convergence, not the converged state).
        const Eigen::Matrix2d load_by_tangent = load * (tangent / length).transpose();
        for (Eigen::Index j = 0; j < n; ++j) {
            Eigen::Matrix2d dforce = DN(j, 0) * (load_by_tangent - pressure * rotation);
            Eigen::Matrix2d dterm = factor * dforce;
            dterm.col(0) += c_derivative[j] * force;
            for (Eigen::Index i = 0; i < n; ++i) pLhs->block<2, 2>(2 * i, 2 * j) -= point.weight * N[i] * dterm;
        }
    }
}

}  // namespace contact_app
