// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/exact_mortar_segmentation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

#include "custom_utilities/mortar_geometry_math.h"

namespace contact_app {
namespace {

using detail::Vec2;
using detail::Vec3;
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
// Inside tests use 1e3·ε·ZERO_TOLERANCE_FACTOR (Kratos: ε in 3D, 1e3·ε in 2D): one tolerance for both, so a
// vertex lying on an edge is found by the inside test or by the clipping, whichever rounds favourably.
constexpr double kInsideTolerance = 1.0e3 * kEpsilon;
constexpr double kClipTolerance = 1.0e-12;      // on the edge parameters (Kratos 1e-15)
constexpr double kDuplicateTolerance = 1.0e-12;  // relative to the slave size (Kratos: 1e-15 absolute)
constexpr double kCentroidTolerance = 1.0e-6;    // cell centroid inside both faces (concavity guard)

/// Polygon vertices with their PointBelongs tags; duplicates (within a relative distance) are skipped.
template <class T, int TCapacity>
struct TaggedPolygon {
    std::array<Vec2<T>, TCapacity> points;
    std::array<int, TCapacity> tags{};
    int size = 0;
    double duplicate_distance = 0.0;
    void Add(const Vec2<T>& p, int tag) {
        const Vec2<double> pv = Values(p);
        for (int k = 0; k < size; ++k)
            if ((Values(points[k]) - pv).norm() <= duplicate_distance) return;
        if (size < TCapacity) {
            points[size] = p;
            tags[size++] = tag;
        }
    }
};

/// Edge–edge intersection of segments o1→o2 (slave) and d1→d2 (master) in the plane (Kratos Clipping2D).
template <class T>
bool ClipEdges(const Vec2<T>& o1, const Vec2<T>& o2, const Vec2<T>& d1, const Vec2<T>& d2, Vec2<T>& point) {
    const Vec2<T> a = o2 - o1, b = d2 - d1, c = o1 - d1;
    const T den = detail::Cross2<T>(a, b);
    const double a_len = Values(a).norm(), b_len = Values(b).norm();
    if (!(std::abs(Value(den)) > 1.0e-14 * a_len * b_len)) return false;  // parallel (or zero-length) edges
    const T t = detail::Cross2<T>(b, c) / den;
    const double s = Value(detail::Cross2<T>(a, c)) / Value(den);
    const double tv = Value(t);
    if (tv < -kClipTolerance || tv > 1.0 + kClipTolerance || s < -kClipTolerance || s > 1.0 + kClipTolerance)
        return false;
    point = o1 + t * a;
    return true;
}

/// Indices of the polygon points sorted by angle around their (value) centroid: the convex order.
template <class T, int TCapacity>
std::array<int, TCapacity> ConvexOrder(const TaggedPolygon<T, TCapacity>& polygon) {
    Vec2<double> centroid = Vec2<double>::Zero();
    for (int k = 0; k < polygon.size; ++k) centroid += Values(polygon.points[k]);
    centroid /= polygon.size;
    std::array<double, TCapacity> angle{};
    std::array<int, TCapacity> order{};
    for (int k = 0; k < polygon.size; ++k) {
        const Vec2<double> d = Values(polygon.points[k]) - centroid;
        angle[k] = std::atan2(d[1], d[0]);
        order[k] = k;
    }
    std::sort(order.begin(), order.begin() + polygon.size, [&](int a, int b) { return angle[a] < angle[b]; });
    return order;
}

template <class T, int TCapacity, class TOrder>
double ShoelaceArea(const TaggedPolygon<T, TCapacity>& polygon, const TOrder& order) {
    double area = 0.0;
    for (int k = 0; k < polygon.size; ++k) {
        const Vec2<double> a = Values(polygon.points[order[k]]);
        const Vec2<double> b = Values(polygon.points[order[(k + 1) % polygon.size]]);
        area += 0.5 * (a[0] * b[1] - a[1] * b[0]);
    }
    return std::abs(area);
}

template <int TNumNodes>
bool InsideFace(const std::array<Vec2<double>, TNumNodes>& face, const Vec2<double>& p, double tol) {
    Vec2<double> xi;
    return detail::InverseMapValue<TNumNodes>(face, p, xi) && detail::IsInsideFace<TNumNodes>(xi, tol);
}

// -- 3D: project, clip, order, triangulate --
template <int TNS, int TNM, class T>
bool Segment3D(const NodeCoordinates<T, 3, TNS>& slave, const detail::PlaneFrame<T>& frame,
               const NodeCoordinates<T, 3, TNM>& master, const SegmentationSettings& settings,
               MortarCells<T, 3>& cells) {
    constexpr int kBase = TNS + TNM;
    constexpr int kCapacity = TNS + TNM + TNS * TNM + 1;
    std::array<Vec2<T>, TNS> qs;
    std::array<Vec2<T>, TNM> qm;
    for (int i = 0; i < TNS; ++i) qs[i] = frame.Project(slave.row(i).transpose());
    for (int j = 0; j < TNM; ++j) {
        if (!(Value(frame.Distance(master.row(j).transpose())) <= settings.distance_threshold)) return false;
        qm[j] = frame.Project(master.row(j).transpose());
    }
    const auto vs = detail::PlaneValues(qs);
    const auto vm = detail::PlaneValues(qm);
    double size = 0.0;
    for (int i = 0; i < TNS; ++i) size = std::max(size, (vs[(i + 1) % TNS] - vs[i]).norm());
    if (!(size > 0.0) || !std::isfinite(size)) return false;

    TaggedPolygon<T, kCapacity> polygon;
    polygon.duplicate_distance = kDuplicateTolerance * size;
    const double tol = kInsideTolerance * settings.zero_tolerance_factor;
    for (int j = 0; j < TNM; ++j)
        if (InsideFace<TNS>(vs, vm[j], tol)) polygon.Add(qm[j], TNS + j);
    for (int i = 0; i < TNS; ++i)
        if (InsideFace<TNM>(vm, vs[i], tol)) polygon.Add(qs[i], i);
    for (int i = 0; i < TNS; ++i) {
        for (int j = 0; j < TNM; ++j) {
            const int i1 = (i + 1) % TNS, j1 = (j + 1) % TNM;
            Vec2<T> point;
            if (ClipEdges<T>(qs[i], qs[i1], qm[j], qm[j1], point))
                polygon.Add(point, kBase + 10 * i + 100 * i1 + 1000 * j + 10000 * j1);
        }
    }
    if (polygon.size < 3) return false;
    const auto order = ConvexOrder(polygon);
    if (!(ShoelaceArea(polygon, order) > 1.0e-12 * size * size)) return false;  // touching faces

    // Vertex list in convex order (+ centroid when tessellating), in slave local coordinates.
    const int n = polygon.size;
    std::array<Vec2<T>, kCapacity + 1> local;
    std::array<Vec2<T>, kCapacity + 1> plane;
    std::array<int, kCapacity + 1> tag{};
    for (int k = 0; k < n; ++k) {
        plane[k] = polygon.points[order[k]];
        tag[k] = polygon.tags[order[k]];
    }
    if (settings.consider_tessellation) {
        // The polygon's area centroid, a continuous function of its vertices: a vertex that appears next to another
        // (a master node crossing a slave edge) splits one cell and leaves the rest as they were. The vertex average
        // jumped there, moving every cell, and with a rule that is not exact for the integrand D and M jumped too
        // (docs/theory/mortar.md §1).
        T twice_area = T(0.0);
        Vec2<T> moment = Vec2<T>::Zero();
        for (int k = 0; k < n; ++k) {
            const Vec2<T> p = plane[k] - plane[0], q = plane[(k + 1) % n] - plane[0];
            const T cross = p[0] * q[1] - q[0] * p[1];
            twice_area += cross;
            moment += cross * (p + q);
        }
        plane[n] = plane[0] + moment / (3.0 * twice_area);
        tag[n] = kBase;
    }
    const int n_points = settings.consider_tessellation ? n + 1 : n;
    for (int k = 0; k < n_points; ++k)
        if (!detail::InverseMap<TNS, T>(qs, plane[k], local[k])) return false;

    const int n_cells = settings.consider_tessellation ? n : n - 2;
    for (int e = 0; e < n_cells; ++e) {
        const std::array<int, 3> v = settings.consider_tessellation ? std::array<int, 3>{n, e, (e + 1) % n}
                                                                    : std::array<int, 3>{0, e + 1, e + 2};
        const Vec2<double> centroid = (Values(plane[v[0]]) + Values(plane[v[1]]) + Values(plane[v[2]])) / 3.0;
        if (!InsideFace<TNS>(vs, centroid, kCentroidTolerance) || !InsideFace<TNM>(vm, centroid, kCentroidTolerance))
            continue;  // only possible for a concave (non-convex quadrilateral) face
        MortarCell<T, 3> cell;
        for (int a = 0; a < 3; ++a) {
            cell.local[a] = local[v[a]];
            cell.belong[a] = tag[v[a]];
        }
        cells.push_back(cell);
    }
    return !cells.empty();
}

// -- 2D: interval intersection on the slave line --
template <class T>
bool Segment2D(const NodeCoordinates<T, 2, 2>& slave, const SpatialVector<T, 2>& normal,
               const NodeCoordinates<T, 2, 2>& master, const SegmentationSettings& settings, MortarCells<T, 2>& cells) {
    const T length = detail::Norm<T>(normal);
    if (!(Value(length) > 1.0e-300) || !std::isfinite(Value(length))) return false;
    const SpatialVector<T, 2> n = normal / length;
    const SpatialVector<T, 2> center = 0.5 * (slave.row(0) + slave.row(1)).transpose();
    std::array<T, 2> xi;
    for (int j = 0; j < 2; ++j) {
        const SpatialVector<T, 2> x = master.row(j).transpose();
        if (!(Value((x - center).dot(n)) <= settings.distance_threshold)) return false;
        Eigen::Matrix<T, 1, 1> eta;
        if (!detail::ProjectAlongDirection<2, 2, T>(slave, x, n, eta)) return false;
        xi[j] = eta[0];
    }
    const int j_lo = xi[0] <= xi[1] ? 0 : 1;
    const int j_hi = 1 - j_lo;
    MortarCell<T, 2> cell;
    cell.local[0][0] = xi[j_lo] > -1.0 ? xi[j_lo] : T(-1.0);
    cell.belong[0] = xi[j_lo] > -1.0 ? 2 + j_lo : 0;
    cell.local[1][0] = xi[j_hi] < 1.0 ? xi[j_hi] : T(1.0);
    cell.belong[1] = xi[j_hi] < 1.0 ? 2 + j_hi : 1;
    const double weight = Value(cell.local[1][0] - cell.local[0][0]);
    if (!(weight > kInsideTolerance * settings.zero_tolerance_factor)) return false;
    cells.push_back(cell);
    return true;
}

template <int TDim, int TNS, class T>
SpatialVector<T, TDim> CellVertex(const NodeCoordinates<T, TDim, TNS>& slave, const MortarCell<T, TDim>& cell, int v) {
    return detail::FacePoint<TNS, TDim, T, T>(slave, cell.local[v]);
}

}  // namespace

template <int TDim, int TNS, int TNM, class T>
template <class TNormal>
bool ExactMortarSegmentation<TDim, TNS, TNM, T>::ComputeCells(const SlaveCoordinates& slave,
                                                              const SpatialVector<TNormal, TDim>& slave_normal,
                                                              const MasterCoordinates& master,
                                                              MortarCells<T, TDim>& cells) const {
    cells.clear();
    if (!Values(slave).allFinite() || !Values(master).allFinite()) return false;
    const SpatialVector<T, TDim> normal = slave_normal.template cast<T>();
    if constexpr (TDim == 2) {
        return Segment2D<T>(slave, normal, master, mSettings, cells);
    } else {
        detail::PlaneFrame<T> frame;
        if (!frame.Build(Vec3<T>(slave.colwise().mean().transpose()), normal)) return false;
        return Segment3D<TNS, TNM, T>(slave, frame, master, mSettings, cells);
    }
}

template <int TDim, int TNS, int TNM, class T>
bool ExactMortarSegmentation<TDim, TNS, TNM, T>::IsDegenerate(const SlaveCoordinates& slave, const Cell& cell) const {
    if constexpr (TDim == 2) {
        const double slave_length = (Values(slave).row(1) - Values(slave).row(0)).norm();
        const double length = Values(CellVertex<2, TNS, T>(slave, cell, 1) - CellVertex<2, TNS, T>(slave, cell, 0)).norm();
        return !(length >= 1.0e-12 * slave_length);
    } else {
        std::array<Vec3<double>, 3> x;
        for (int v = 0; v < 3; ++v) x[v] = Values(CellVertex<3, TNS, T>(slave, cell, v));
        const double a = (x[1] - x[0]).norm(), b = (x[2] - x[1]).norm(), c = (x[0] - x[2]).norm();
        const double radicand = (a + b + c) * (-a + b + c) * (a - b + c) * (a + b - c);
        const double heron = radicand > 0.0 ? 0.25 * std::sqrt(radicand) : 0.0;
        const double longest = std::max({a, b, c});
        return !(heron > 1.0e-12 * longest * longest);
    }
}

template <int TDim, int TNS, int TNM, class T>
T ExactMortarSegmentation<TDim, TNS, TNM, T>::TotalArea(const SlaveCoordinates& slave,
                                                        const MortarCells<T, TDim>& cells) const {
    T area(0.0);
    for (const Cell& cell : cells) {
        if (IsDegenerate(slave, cell)) continue;
        if constexpr (TDim == 2) {
            area += detail::Norm<T>(CellVertex<2, TNS, T>(slave, cell, 1) - CellVertex<2, TNS, T>(slave, cell, 0));
        } else {
            const Vec3<T> x0 = CellVertex<3, TNS, T>(slave, cell, 0);
            const Vec3<T> cross = (CellVertex<3, TNS, T>(slave, cell, 1) - x0).cross(CellVertex<3, TNS, T>(slave, cell, 2) - x0);
            area += 0.5 * detail::Norm<T>(cross);
        }
    }
    return area;
}

bool IsMortarPairUsed(double integration_area, double slave_area) {
    return slave_area > 0.0 && integration_area / slave_area > 1.0e-5;
}

bool DecodeEdgeIntersectionTag(int tag, int base_tag, int& s0, int& s1, int& m0, int& m1) {
    if (tag <= base_tag) return false;
    const int r = tag - base_tag;
    m1 = r / 10000;
    m0 = (r % 10000) / 1000;
    s1 = (r % 1000) / 100;
    s0 = (r % 100) / 10;
    return true;
}

// -- Explicit instantiations: the registered pairs × {double, Dual<d(n_s+n_m)>} --
#define CONTACT_APP_INSTANTIATE_SEGMENTATION(A, D, NS, NM)                                                     \
    template class ExactMortarSegmentation<D, NS, NM, double>;                                                 \
    template class ExactMortarSegmentation<D, NS, NM, Dual<D*(NS + NM)>>;                                      \
    template bool ExactMortarSegmentation<D, NS, NM, double>::ComputeCells<double>(                           \
        const SlaveCoordinates&, const SpatialVector<double, D>&, const MasterCoordinates&,                     \
        MortarCells<double, D>&) const;                                                                        \
    template bool ExactMortarSegmentation<D, NS, NM, Dual<D*(NS + NM)>>::ComputeCells<double>(                \
        const SlaveCoordinates&, const SpatialVector<double, D>&, const MasterCoordinates&,                     \
        MortarCells<Dual<D*(NS + NM)>, D>&) const;                                                             \
    template bool ExactMortarSegmentation<D, NS, NM, Dual<D*(NS + NM)>>::ComputeCells<Dual<D*(NS + NM)>>(    \
        const SlaveCoordinates&, const SpatialVector<Dual<D*(NS + NM)>, D>&, const MasterCoordinates&,          \
        MortarCells<Dual<D*(NS + NM)>, D>&) const;
CONTACT_APP_FOR_EACH_MORTAR_PAIR(CONTACT_APP_INSTANTIATE_SEGMENTATION, ~)
#undef CONTACT_APP_INSTANTIATE_SEGMENTATION

}  // namespace contact_app
