// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/geometries/reference_element.h"

#include <Eigen/Core>

namespace contact_app {
namespace {

using detail::Connectivity;

// -- Point3D: N = 1, no local coordinates; its one-point rule (weight 1, |J| = 1) evaluates at the node. --
void PointValues(Vector& rN, const Array3& /*local*/) { rN.setOnes(1); }
void PointGradients(Matrix& rDN, const Array3& /*local*/) { rDN.resize(1, 0); }
Matrix PointNodes() { return Matrix(1, 0); }
Connectivity NoFaces() { return {}; }

// -- Line2D3: nodes at ξ = −1, +1, 0 (end, end, middle), N = (ξ(ξ−1)/2, ξ(ξ+1)/2, 1−ξ²). --
void QuadraticLineValues(Vector& rN, const Array3& local) {
    const double xi = local[0];
    rN.resize(3);
    rN << 0.5 * xi * (xi - 1.0), 0.5 * xi * (xi + 1.0), 1.0 - xi * xi;
}
void QuadraticLineGradients(Matrix& rDN, const Array3& local) {
    const double xi = local[0];
    rDN.resize(3, 1);
    rDN << xi - 0.5, xi + 0.5, -2.0 * xi;
}
Matrix QuadraticLineNodes() {
    Matrix nodes(3, 1);
    nodes << -1.0, 1.0, 0.0;
    return nodes;
}

// -- Quadratic simplices: corner N = L(2L−1), mid-side N = 4 L_a L_b (L barycentric), corners then mid-sides. --
// Triangle2D6: mid-side nodes 4 (1-2), 5 (2-3), 6 (3-1).
const Connectivity kTriangleEdges{{0, 1}, {1, 2}, {2, 0}};
Vector TriangleBarycentric(const Array3& local) {
    return Eigen::Vector3d(1.0 - local[0] - local[1], local[0], local[1]);
}
Matrix TriangleBarycentricGradients() {
    Matrix result(3, 2);
    result << -1.0, -1.0, 1.0, 0.0, 0.0, 1.0;
    return result;
}
void QuadraticTriangleValues(Vector& rN, const Array3& local) {
    detail::QuadraticSimplexValues(rN, TriangleBarycentric(local), kTriangleEdges);
}
void QuadraticTriangleGradients(Matrix& rDN, const Array3& local) {
    detail::QuadraticSimplexGradients(rDN, TriangleBarycentric(local), TriangleBarycentricGradients(), kTriangleEdges);
}
Matrix QuadraticTriangleNodes() {
    Matrix nodes(6, 2);
    nodes << 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.5, 0.0, 0.5, 0.5, 0.0, 0.5;
    return nodes;
}
Connectivity QuadraticTriangleEdges() { return {{1, 2, 4}, {2, 0, 5}, {0, 1, 3}}; }

// Tetrahedra3D10: mid-side nodes 5 (1-2), 6 (2-3), 7 (3-1), 8 (1-4), 9 (2-4), 10 (3-4); faces are 6-node triangles.
const Connectivity kTetrahedronEdges{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
Vector TetrahedronBarycentric(const Array3& local) {
    return Eigen::Vector4d(1.0 - local[0] - local[1] - local[2], local[0], local[1], local[2]);
}
Matrix TetrahedronBarycentricGradients() {
    Matrix result(4, 3);
    result << -1.0, -1.0, -1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0;
    return result;
}

// -- Tetrahedra3D4 on the unit simplex: N = (1−ξ−η−ζ, ξ, η, ζ); positive volume when node 4 is on the side of
//    (x_2 − x_1) × (x_3 − x_1). --
void LinearTetrahedronValues(Vector& rN, const Array3& local) { rN = TetrahedronBarycentric(local); }
void LinearTetrahedronGradients(Matrix& rDN, const Array3& /*local*/) { rDN = TetrahedronBarycentricGradients(); }
Matrix LinearTetrahedronNodes() {
    Matrix nodes(4, 3);
    nodes << 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0;
    return nodes;
}
Connectivity LinearTetrahedronFaces() { return {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}; }

void QuadraticTetrahedronValues(Vector& rN, const Array3& local) {
    detail::QuadraticSimplexValues(rN, TetrahedronBarycentric(local), kTetrahedronEdges);
}
void QuadraticTetrahedronGradients(Matrix& rDN, const Array3& local) {
    detail::QuadraticSimplexGradients(rDN, TetrahedronBarycentric(local), TetrahedronBarycentricGradients(),
                                      kTetrahedronEdges);
}
Matrix QuadraticTetrahedronNodes() {
    Matrix nodes(10, 3);
    nodes.topRows(4) = LinearTetrahedronNodes();
    for (std::size_t e = 0; e < kTetrahedronEdges.size(); ++e)
        nodes.row(4 + static_cast<Eigen::Index>(e)) =
            0.5 * (nodes.row(static_cast<Eigen::Index>(kTetrahedronEdges[e][0])) +
                   nodes.row(static_cast<Eigen::Index>(kTetrahedronEdges[e][1])));
    return nodes;
}
Connectivity QuadraticTetrahedronFaces() {
    return {{1, 2, 3, 5, 9, 8}, {0, 3, 2, 7, 9, 6}, {0, 1, 3, 4, 8, 7}, {0, 2, 1, 6, 5, 4}};
}

// -- Hexahedra3D8 on [-1,1]³: bottom face 1-2-3-4 counter-clockwise at ζ = −1 (seen from +z), top face 5-8 above
//    it; N_k = (1+ξ_k ξ)(1+η_k η)(1+ζ_k ζ)/8. --
constexpr double kHexahedronNodes[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                           {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
void TrilinearHexahedronValues(Vector& rN, const Array3& local) {
    rN.resize(8);
    for (int k = 0; k < 8; ++k)
        rN[k] = 0.125 * (1.0 + kHexahedronNodes[k][0] * local[0]) * (1.0 + kHexahedronNodes[k][1] * local[1]) *
                (1.0 + kHexahedronNodes[k][2] * local[2]);
}
void TrilinearHexahedronGradients(Matrix& rDN, const Array3& local) {
    rDN.resize(8, 3);
    for (int k = 0; k < 8; ++k) {
        const Array3 f(1.0 + kHexahedronNodes[k][0] * local[0], 1.0 + kHexahedronNodes[k][1] * local[1],
                       1.0 + kHexahedronNodes[k][2] * local[2]);
        rDN(k, 0) = 0.125 * kHexahedronNodes[k][0] * f[1] * f[2];
        rDN(k, 1) = 0.125 * kHexahedronNodes[k][1] * f[0] * f[2];
        rDN(k, 2) = 0.125 * kHexahedronNodes[k][2] * f[0] * f[1];
    }
}
Matrix TrilinearHexahedronNodes() {
    Matrix nodes(8, 3);
    for (int k = 0; k < 8; ++k) nodes.row(k) << kHexahedronNodes[k][0], kHexahedronNodes[k][1], kHexahedronNodes[k][2];
    return nodes;
}
Connectivity TrilinearHexahedronFaces() {
    return {{0, 3, 2, 1}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}, {4, 5, 6, 7}};
}

// -- Prism3D6 = triangle(ξ,η) × ζ∈[0,1]: nodes 1-3 at ζ = 0 ((0,0), (1,0), (0,1)), nodes 4-6 above them at ζ = 1;
//    N = L_i(ξ,η)(1−ζ) and L_i(ξ,η)ζ. Faces: two triangles, three quadrilaterals. --
void LinearPrismValues(Vector& rN, const Array3& local) {
    const Array3 L(1.0 - local[0] - local[1], local[0], local[1]);
    rN.resize(6);
    rN << (1.0 - local[2]) * L, local[2] * L;
}
void LinearPrismGradients(Matrix& rDN, const Array3& local) {
    constexpr double kTriangleGradients[3][2] = {{-1.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}};  // ∂L_i/∂(ξ,η)
    const Array3 L(1.0 - local[0] - local[1], local[0], local[1]);
    const double bottom = 1.0 - local[2], top = local[2];
    rDN.resize(6, 3);
    for (int i = 0; i < 3; ++i) {
        rDN.row(i) << bottom * kTriangleGradients[i][0], bottom * kTriangleGradients[i][1], -L[i];
        rDN.row(i + 3) << top * kTriangleGradients[i][0], top * kTriangleGradients[i][1], L[i];
    }
}
Matrix LinearPrismNodes() {
    Matrix nodes(6, 3);
    nodes << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1;
    return nodes;
}
Connectivity LinearPrismFaces() { return {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}}; }

using namespace detail;  // the shape functions shared by the 2D and 3D variants (shape_functions.h)
const ShapeFunctionSet kPoint{PointValues, PointGradients, PointNodes, NoFaces};
const ShapeFunctionSet kLinearLine{LinearLineValues, LinearLineGradients, LinearLineNodes, LinearLineFaces};
const ShapeFunctionSet kQuadraticLine{QuadraticLineValues, QuadraticLineGradients, QuadraticLineNodes,
                                      LinearLineFaces};
const ShapeFunctionSet kLinearTriangle{LinearTriangleValues, LinearTriangleGradients, LinearTriangleNodes,
                                       LinearTriangleEdges};
const ShapeFunctionSet kQuadraticTriangle{QuadraticTriangleValues, QuadraticTriangleGradients,
                                          QuadraticTriangleNodes, QuadraticTriangleEdges};
const ShapeFunctionSet kBilinearQuadrilateral{BilinearQuadrilateralValues, BilinearQuadrilateralGradients,
                                              BilinearQuadrilateralNodes, BilinearQuadrilateralEdges};
const ShapeFunctionSet kLinearTetrahedron{LinearTetrahedronValues, LinearTetrahedronGradients,
                                          LinearTetrahedronNodes, LinearTetrahedronFaces};
const ShapeFunctionSet kQuadraticTetrahedron{QuadraticTetrahedronValues, QuadraticTetrahedronGradients,
                                             QuadraticTetrahedronNodes, QuadraticTetrahedronFaces};
const ShapeFunctionSet kTrilinearHexahedron{TrilinearHexahedronValues, TrilinearHexahedronGradients,
                                            TrilinearHexahedronNodes, TrilinearHexahedronFaces};
const ShapeFunctionSet kLinearPrism{LinearPrismValues, LinearPrismGradients, LinearPrismNodes, LinearPrismFaces};

}  // namespace

const std::vector<ReferenceElement>& ReferenceElements() {
    using F = GeometryFamily;
    // Measure orders are exact for the type's det J: a straight, evenly spaced Line2D3 (5); a Quadrilateral3D4,
    // which may be warped (5, exact when planar); a Triangle2D6 with curved edges (2, det J quadratic); a
    // Tetrahedra3D10 (3, det J cubic); a Hexahedra3D8 (2, degree <= 2 per direction). Normals: Line2D2 turns its
    // tangent clockwise (a counter-clockwise boundary has outward normals), Line3D2 takes J × e_z (undefined for a
    // line along z), Triangle3D3 follows its node order (x_1 − x_0) × (x_2 − x_0).
    // clang-format off
    static const std::vector<ReferenceElement> elements{
        // name               family         nodes  working  local  default  measure  shape functions
        {"Point3D",           F::Point,          1,       3,     0,       1,       1, kPoint},
        {"Line2D2",           F::Linear,         2,       2,     1,       1,       1, kLinearLine},
        {"Line3D2",           F::Linear,         2,       3,     1,       1,       1, kLinearLine},
        {"Line2D3",           F::Linear,         3,       2,     1,       2,       5, kQuadraticLine},
        {"Triangle2D3",       F::Triangle,       3,       2,     2,       1,       1, kLinearTriangle},
        {"Triangle3D3",       F::Triangle,       3,       3,     2,       1,       1, kLinearTriangle},
        {"Triangle2D6",       F::Triangle,       6,       2,     2,       2,       2, kQuadraticTriangle},
        {"Quadrilateral2D4",  F::Quadrilateral,  4,       2,     2,       2,       2, kBilinearQuadrilateral},
        {"Quadrilateral3D4",  F::Quadrilateral,  4,       3,     2,       2,       5, kBilinearQuadrilateral},
        {"Tetrahedra3D4",     F::Tetrahedra,     4,       3,     3,       1,       1, kLinearTetrahedron},
        {"Tetrahedra3D10",    F::Tetrahedra,    10,       3,     3,       2,       3, kQuadraticTetrahedron},
        {"Hexahedra3D8",      F::Hexahedra,      8,       3,     3,       2,       2, kTrilinearHexahedron},
        {"Prism3D6",          F::Prism,          6,       3,     3,       2,       2, kLinearPrism},
    };
    // clang-format on
    return elements;
}

const ReferenceElement* FindReferenceElement(const std::string& name) {
    for (const auto& element : ReferenceElements())
        if (name == element.name) return &element;
    return nullptr;
}

}  // namespace contact_app
