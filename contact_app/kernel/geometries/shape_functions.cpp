// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/geometries/shape_functions.h"

namespace contact_app::detail {
namespace {

constexpr double kQuadrilateralNodes[4][2] = {{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}};

}  // namespace

void LinearLineValues(Vector& rN, const Array3& local) {
    rN.resize(2);
    rN << 0.5 * (1.0 - local[0]), 0.5 * (1.0 + local[0]);
}

void LinearLineGradients(Matrix& rDN, const Array3& /*local*/) {
    rDN.resize(2, 1);
    rDN << -0.5, 0.5;
}

Matrix LinearLineNodes() {
    Matrix result(2, 1);
    result << -1.0, 1.0;
    return result;
}

Connectivity LinearLineFaces() { return {{0}, {1}}; }

void LinearTriangleValues(Vector& rN, const Array3& local) {
    rN.resize(3);
    rN << 1.0 - local[0] - local[1], local[0], local[1];
}

void LinearTriangleGradients(Matrix& rDN, const Array3& /*local*/) {
    rDN.resize(3, 2);
    rDN << -1.0, -1.0, 1.0, 0.0, 0.0, 1.0;
}

Matrix LinearTriangleNodes() {
    Matrix result(3, 2);
    result << 0.0, 0.0, 1.0, 0.0, 0.0, 1.0;
    return result;
}

Connectivity LinearTriangleEdges() { return {{1, 2}, {2, 0}, {0, 1}}; }

void BilinearQuadrilateralValues(Vector& rN, const Array3& local) {
    const auto& nodes = kQuadrilateralNodes;
    rN.resize(4);
    for (int k = 0; k < 4; ++k) rN[k] = 0.25 * (1.0 + nodes[k][0] * local[0]) * (1.0 + nodes[k][1] * local[1]);
}

void BilinearQuadrilateralGradients(Matrix& rDN, const Array3& local) {
    const auto& nodes = kQuadrilateralNodes;
    rDN.resize(4, 2);
    for (int k = 0; k < 4; ++k) {
        rDN(k, 0) = 0.25 * nodes[k][0] * (1.0 + nodes[k][1] * local[1]);
        rDN(k, 1) = 0.25 * nodes[k][1] * (1.0 + nodes[k][0] * local[0]);
    }
}

Matrix BilinearQuadrilateralNodes() {
    Matrix result(4, 2);
    result << -1.0, -1.0, 1.0, -1.0, 1.0, 1.0, -1.0, 1.0;
    return result;
}

Connectivity BilinearQuadrilateralEdges() { return {{0, 1}, {1, 2}, {2, 3}, {3, 0}}; }

void QuadraticSimplexValues(Vector& rN, const Vector& barycentric, const Connectivity& edges) {
    const Eigen::Index corners = barycentric.size();
    rN.resize(corners + static_cast<Eigen::Index>(edges.size()));
    for (Eigen::Index k = 0; k < corners; ++k) rN[k] = barycentric[k] * (2.0 * barycentric[k] - 1.0);
    for (std::size_t e = 0; e < edges.size(); ++e)
        rN[corners + static_cast<Eigen::Index>(e)] = 4.0 * barycentric[edges[e][0]] * barycentric[edges[e][1]];
}

void QuadraticSimplexGradients(Matrix& rDN, const Vector& barycentric, const Matrix& barycentric_gradients,
                               const Connectivity& edges) {
    const Eigen::Index corners = barycentric.size();
    rDN.resize(corners + static_cast<Eigen::Index>(edges.size()), barycentric_gradients.cols());
    for (Eigen::Index k = 0; k < corners; ++k)
        rDN.row(k) = (4.0 * barycentric[k] - 1.0) * barycentric_gradients.row(k);
    for (std::size_t e = 0; e < edges.size(); ++e) {
        const auto a = static_cast<Eigen::Index>(edges[e][0]), b = static_cast<Eigen::Index>(edges[e][1]);
        rDN.row(corners + static_cast<Eigen::Index>(e)) = 4.0 * (barycentric[b] * barycentric_gradients.row(a) +
                                                                 barycentric[a] * barycentric_gradients.row(b));
    }
}

}  // namespace contact_app::detail
