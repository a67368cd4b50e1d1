// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "automatic_differentiation/ad_helpers.h"
#include "custom_utilities/mortar_shape_functions.h"
#include "custom_utilities/mortar_types.h"

namespace contact_app::detail {

// Small scalar-generic geometry kernels shared by the segmentation and the integration. Nonlinear solves
// (bilinear inverse maps, projections on quadrilaterals) iterate on values, then take one Newton step in
// the AD scalar from the converged point: the value is unchanged and, by the implicit-function theorem,
// the derivative is exact.

template <class T>
using Vec2 = Eigen::Matrix<T, 2, 1>;
template <class T>
using Vec3 = Eigen::Matrix<T, 3, 1>;

template <class T, class TDerived>
T Norm(const Eigen::MatrixBase<TDerived>& v) {
    using std::sqrt;
    return sqrt(v.dot(v));
}

template <class T>
T Cross2(const Vec2<T>& a, const Vec2<T>& b) { return a[0] * b[1] - a[1] * b[0]; }

/// x(ξ) = Σ N_k(ξ) X_k on a face with nodes X (rows).
template <int TNumNodes, int TDim, class T, class TLocal>
SpatialVector<T, TDim> FacePoint(const NodeCoordinates<T, TDim, TNumNodes>& nodes,
                                 const Eigen::Matrix<TLocal, FaceLocalDim<TNumNodes>, 1>& xi) {
    const auto shape = FaceShapeFunctions<TNumNodes, TLocal>(xi);
    SpatialVector<T, TDim> x = SpatialVector<T, TDim>::Zero();
    for (int k = 0; k < TNumNodes; ++k) x += shape[k] * nodes.row(k).transpose();
    return x;
}

/// Orthonormal frame (c; t1, t2, n) of the reference plane of a 3D slave.
template <class T>
struct PlaneFrame {
    Vec3<T> center, normal, t1, t2;
    /// @return false if the normal is (numerically) zero or not finite
    template <class TN>
    bool Build(const Vec3<T>& c, const Vec3<TN>& n_in) {
        center = c;
        normal = n_in.template cast<T>();
        const T length = Norm<T>(normal);
        if (!(Value(length) > 1.0e-300) || !std::isfinite(Value(length))) return false;
        normal /= length;
        int axis = 0;  // the axis least aligned with n gives a well-conditioned in-plane direction
        for (int k = 1; k < 3; ++k)
            if (std::abs(Value(normal[k])) < std::abs(Value(normal[axis]))) axis = k;
        Vec3<T> a = Vec3<T>::Zero();
        a[axis] = 1.0;
        t1 = a - normal * normal[axis];
        t1 /= Norm<T>(t1);
        t2 = normal.cross(t1);
        return true;
    }
    Vec2<T> Project(const Vec3<T>& x) const {
        const Vec3<T> d = x - center;
        return Vec2<T>(d.dot(t1), d.dot(t2));
    }
    T Distance(const Vec3<T>& x) const { return (x - center).dot(normal); }
};

/// Values of an array of plane points.
template <class T, std::size_t TN>
std::array<Vec2<double>, TN> PlaneValues(const std::array<Vec2<T>, TN>& points) {
    std::array<Vec2<double>, TN> result;
    for (std::size_t k = 0; k < TN; ++k) result[k] = Values(points[k]);
    return result;
}

/// ξ with Σ N_k(ξ) q_k = p for a triangle/quadrilateral in the plane (values only).
/// @return false if the map is singular or Newton does not converge
template <int TNumNodes>
bool InverseMapValue(const std::array<Vec2<double>, TNumNodes>& q, const Vec2<double>& p, Vec2<double>& xi) {
    xi = FaceCentroid<TNumNodes>();
    double scale = 0.0;
    for (const auto& v : q) scale = std::max(scale, (v - q[0]).norm());
    if (!(scale > 0.0) || !std::isfinite(scale)) return false;
    for (int iteration = 0; iteration < 30; ++iteration) {
        const auto shape = FaceShapeFunctions<TNumNodes, double>(xi);
        const auto grad = FaceShapeGradients<TNumNodes, double>(xi);
        Vec2<double> r = q[0] - p;  // relative to q[0], as ProjectAlongDirection: no round-off of ε|p|
        Eigen::Matrix2d jac = Eigen::Matrix2d::Zero();
        for (int k = 0; k < TNumNodes; ++k) {
            r += shape[k] * (q[k] - q[0]);
            jac += (q[k] - q[0]) * grad.row(k);
        }
        const double det = jac.determinant();
        if (!(std::abs(det) > 1.0e-14 * scale * scale)) return false;
        const Vec2<double> step = -jac.inverse() * r;
        xi += step;
        if (!xi.allFinite() || xi.cwiseAbs().maxCoeff() > 1.0e6) return false;
        if (step.norm() < 1.0e-12 || TNumNodes == 3) return true;
    }
    return false;
}

/// As InverseMapValue, in the scalar T (one Newton step in T from the converged value).
template <int TNumNodes, class T>
bool InverseMap(const std::array<Vec2<T>, TNumNodes>& q, const Vec2<T>& p, Vec2<T>& xi) {
    Vec2<double> xi0;
    if (!InverseMapValue<TNumNodes>(PlaneValues(q), Values(p), xi0)) return false;
    const auto shape = FaceShapeFunctions<TNumNodes, double>(xi0);
    const auto grad = FaceShapeGradients<TNumNodes, double>(xi0);
    Vec2<T> r = -p;
    Eigen::Matrix2d jac = Eigen::Matrix2d::Zero();
    for (int k = 0; k < TNumNodes; ++k) {
        r += shape[k] * q[k];
        jac += Values(q[k]) * grad.row(k);
    }
    // As in ProjectAlongDirection: the residual is at round-off, so J in double gives the exact derivatives.
    const Eigen::Matrix2d inverse = jac.inverse();
    for (int i = 0; i < 2; ++i) xi[i] = xi0[i] - (inverse(i, 0) * r[0] + inverse(i, 1) * r[1]);
    return true;
}

/// Local coordinates η of the point where the ray x + s·dir meets the face (Line2D2 in 2D, triangle or
/// bilinear quadrilateral in 3D): solves x_face(η) − s·dir = x. Values first, then one step in T.
/// @param[in] face the face's node coordinates
/// @param[in] x the point the ray starts from
/// @param[in] dir the ray's direction (need not be unit)
/// @param[out] eta the local coordinates, with the derivatives of the inputs
/// @param[in] pStart the solution η of a projection already solved for the same values (Newton then only takes the
///            step in T; null: Newton from the face centroid)
/// @return false if the ray is parallel to the face or Newton fails
template <int TNumNodes, int TDim, class T>
bool ProjectAlongDirection(const NodeCoordinates<T, TDim, TNumNodes>& face, const SpatialVector<T, TDim>& x,
                           const SpatialVector<T, TDim>& dir, Eigen::Matrix<T, TDim - 1, 1>& eta,
                           const Eigen::Matrix<double, TDim - 1, 1>* pStart = nullptr) {
    using Square = Eigen::Matrix<double, TDim, TDim>;
    // Newton on coordinates relative to the face's first node: in absolute ones the residual carries round-off of
    // ε|x|, and where |x| is large against the face (a model away from the origin) the steps stalled above the
    // tolerance, so points were dropped at random between nearly equal iterates (docs/theory/mortar.md §2).
    const SpatialVector<double, TDim> origin = Values(face).row(0).transpose();
    const NodeCoordinates<double, TDim, TNumNodes> fv = Values(face).rowwise() - origin.transpose();
    const SpatialVector<double, TDim> xv = Values(x) - origin, dv = Values(dir);
    const double scale = fv.rowwise().norm().maxCoeff();
    if (!(scale > 0.0) || !std::isfinite(scale) || !(dv.norm() > 0.0)) return false;
    SpatialVector<double, TDim> u = SpatialVector<double, TDim>::Zero();
    u.template head<TDim - 1>() = pStart ? *pStart : FaceCentroid<TNumNodes>();
    if (pStart) {  // the ray parameter of the face point at the known solution
        const SpatialVector<double, TDim> offset = fv.transpose() * FaceShapeFunctions<TNumNodes, double>(*pStart) - xv;
        u[TDim - 1] = offset.dot(dv) / dv.squaredNorm();
    }
    bool converged = pStart != nullptr;
    for (int iteration = 0; iteration < 30 && !converged; ++iteration) {
        const Eigen::Matrix<double, TDim - 1, 1> e = u.template head<TDim - 1>();
        Square jac;
        jac.template leftCols<TDim - 1>() = fv.transpose() * FaceShapeGradients<TNumNodes, double>(e);
        jac.col(TDim - 1) = -dv;
        const SpatialVector<double, TDim> r = fv.transpose() * FaceShapeFunctions<TNumNodes, double>(e) - u[TDim - 1] * dv - xv;
        const double det = jac.determinant();
        if (!(std::abs(det) > 1.0e-12 * std::pow(scale, TDim - 1) * dv.norm())) return false;
        const SpatialVector<double, TDim> step = -jac.inverse() * r;
        u += step;
        if (!u.allFinite() || u.template head<TDim - 1>().cwiseAbs().maxCoeff() > 1.0e6) return false;
        // Quadratic convergence: a step of 1e-12 leaves an error far below round-off, and the step in T below refines.
        converged = TNumNodes <= TDim || step.norm() < 1.0e-12 * (1.0 + u.norm());
    }
    if (!converged) return false;
    const Eigen::Matrix<double, TDim - 1, 1> e0 = u.template head<TDim - 1>();
    // The step in T: the residual's value is at round-off, so the step carries the exact derivatives −J⁻¹ ∂r (implicit
    // function theorem) with J in double; inverting J in T would add only (∂J⁻¹) r, which is round-off.
    Square jac;
    jac.template leftCols<TDim - 1>() = Values(face).transpose() * FaceShapeGradients<TNumNodes, double>(e0);
    jac.col(TDim - 1) = -dv;
    const Square inverse = jac.inverse();
    const SpatialVector<T, TDim> r =
        face.transpose() * FaceShapeFunctions<TNumNodes, double>(e0).template cast<T>() - u[TDim - 1] * dir - x;
    for (int i = 0; i < TDim - 1; ++i) {
        T step = inverse(i, 0) * r[0];
        for (int k = 1; k < TDim; ++k) step += inverse(i, k) * r[k];
        eta[i] = u[i] - step;
    }
    return true;
}

}  // namespace contact_app::detail
