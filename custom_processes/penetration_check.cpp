// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/penetration_check.h"

#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "contact_app/kernel/variables.h"

namespace contact_app {

std::optional<double> ProjectAlong(const Array3& x, const Array3& d, const Condition& master) {
    const Geometry& face = master.GetGeometry();
    constexpr double tolerance = 1e-6;
    if (face.WorkingSpaceDimension() == 2) {
        const Array3 a = face[0].Coordinates(), e = face[1].Coordinates() - a;
        const double det = -d[0] * e[1] + e[0] * d[1];
        if (std::abs(det) <= 1e-14 * e.norm() * d.norm()) return std::nullopt;
        const Array3 r = a - x;  // t d − s e = r
        const double t = (-r[0] * e[1] + e[0] * r[1]) / det;
        const double s = (d[0] * r[1] - d[1] * r[0]) / det;
        if (s < -tolerance || s > 1.0 + tolerance) return std::nullopt;
        return t;
    }
    const Array3 normal = master.GetValue(NORMAL);
    const double denominator = d.dot(normal);
    if (std::abs(denominator) <= 1e-12) return std::nullopt;
    const double t = (face.Center() - x).dot(normal) / denominator;
    const Array3 p = x + t * d;
    const std::size_t n = face.PointsNumber();
    for (std::size_t k = 0; k < n; ++k) {
        const Array3& a = face[k].Coordinates();
        const Array3 edge = face[(k + 1) % n].Coordinates() - a;
        if (edge.cross(p - a).dot(normal) < -tolerance * edge.squaredNorm()) return std::nullopt;
    }
    return t;
}

std::vector<PenetratingNode> FindPenetratingNodes(
    const std::vector<Node*>& nodes, const std::vector<Condition*>& masters, const SearchTree& tree,
    double max_master_radius, const std::function<bool(const Node&, const Condition&)>& same_body) {
    std::vector<PenetratingNode> result;
    if (masters.empty() || !(max_master_radius > 0.0)) return result;
    Array3 lo = Array3::Constant(std::numeric_limits<double>::max()), hi = -lo;
    for (const Condition* master : masters) {
        lo = lo.cwiseMin(master->GetGeometry().Center());
        hi = hi.cwiseMax(master->GetGeometry().Center());
    }
    const auto other_body = [&](const Node& node, std::size_t index) {
        return !same_body || !same_body(node, *masters[index]);
    };
    std::vector<std::size_t> found;
    for (Node* node : nodes) {
        const Array3& x = node->Coordinates();
        // A centre of another body first (radius doubled until every centre is inside), then every face whose
        // closest point can be nearer than that centre.
        const double everything = (x.cwiseMax(hi) - x.cwiseMin(lo)).norm();
        double radius = max_master_radius;
        bool any = false;
        while (!any) {
            tree.SearchInRadius(x, radius, found);
            for (const std::size_t index : found) any = any || other_body(*node, index);
            if (radius > everything) break;
            radius *= 2.0;
        }
        if (!any) continue;
        tree.SearchInRadius(x, radius + 2.0 * max_master_radius, found);
        Condition* nearest = nullptr;
        double nearest_t = std::numeric_limits<double>::infinity();
        for (const std::size_t index : found) {
            if (!other_body(*node, index)) continue;
            Condition& master = *masters[index];
            const auto t = ProjectAlong(x, -master.GetValue(NORMAL), master);  // open side positive
            if (t && std::abs(*t) < std::abs(nearest_t)) {
                nearest_t = *t;
                nearest = &master;
            }
        }
        if (nearest == nullptr || !(nearest_t < 0.0)) continue;
        const Array3& normal = node->FastGetSolutionStepValue(NORMAL);
        if (normal.dot(nearest->GetValue(NORMAL)) > 0.0) continue;  // a face of the same orientation: not inside
        result.push_back({node, nearest, -nearest_t});
    }
    return result;
}

}  // namespace contact_app
