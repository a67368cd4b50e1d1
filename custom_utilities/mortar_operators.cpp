// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/mortar_operators.h"

#include <cmath>
#include <limits>

#include "custom_utilities/mortar_geometry_math.h"

namespace contact_app {
namespace {

using detail::Vec3;

/// Cell shape functions at the cell-reference point ζ (line: ζ ∈ [−1,1]; triangle: unit simplex).
template <int TDim>
Eigen::Matrix<double, TDim, 1> CellShapeFunctions(const Array3& zeta) {
    Eigen::Matrix<double, TDim, 1> n;
    if constexpr (TDim == 2) {
        n << 0.5 * (1.0 - zeta[0]), 0.5 * (1.0 + zeta[0]);
    } else {
        n << 1.0 - zeta[0] - zeta[1], zeta[0], zeta[1];
    }
    return n;
}

/// det J of the cell map in global coordinates: half length (2D, reference length 2), twice the area (3D).
template <int TDim, class T>
T CellDeterminant(const std::array<SpatialVector<T, TDim>, TDim>& x) {
    if constexpr (TDim == 2) {
        return 0.5 * detail::Norm<T>(x[1] - x[0]);
    } else {
        const Vec3<T> cross = (x[1] - x[0]).cross(x[2] - x[0]);
        return detail::Norm<T>(cross);
    }
}

template <int TDim, int TNS>
double FaceMeasure(const NodeCoordinates<double, TDim, TNS>& x) {
    if constexpr (TDim == 2) {
        return (x.row(1) - x.row(0)).norm();
    } else if constexpr (TNS == 3) {
        return 0.5 * Vec3<double>((x.row(1) - x.row(0)).transpose()).cross(Vec3<double>((x.row(2) - x.row(0)).transpose())).norm();
    } else {
        return 0.5 * Vec3<double>((x.row(2) - x.row(0)).transpose()).cross(Vec3<double>((x.row(3) - x.row(1)).transpose())).norm();
    }
}

}  // namespace

const std::vector<IntegrationPoint>& MortarCellGaussRule(int dim, int integration_order_contact) {
    const int order = integration_order_contact >= 1 && integration_order_contact <= 5 ? integration_order_contact : 2;
    return GaussRule(dim == 2 ? GeometryFamily::Linear : GeometryFamily::Triangle, order);
}

template <int TDim, int TNS, int TNM, class T>
template <class TNormal>
void MortarIntegrator<TDim, TNS, TNM, T>::ComputeGaussPoints(
    const typename Segmentation::SlaveCoordinates& slave, const SpatialVector<TNormal, TDim>& slave_normal,
    const typename Segmentation::MasterCoordinates& master, const NodeCoordinates<TNormal, TDim, TNS>& nodal_normals,
    const MortarCells<T, TDim>& cells, std::vector<GaussPoint>& points) const {
    points.clear();
    const auto& rule = MortarCellGaussRule(TDim, mSettings.integration_order);
    points.reserve(cells.size() * rule.size());
    const SpatialVector<T, TDim> n_slave = slave_normal.template cast<T>();
    const NodeCoordinates<T, TDim, TNS> normals = nodal_normals.template cast<T>();
    for (const auto& cell : cells) {
        if (mSegmentation.IsDegenerate(slave, cell)) continue;
        std::array<SpatialVector<T, TDim>, TDim> x;
        for (int v = 0; v < TDim; ++v) x[v] = detail::FacePoint<TNS, TDim, T, T>(slave, cell.local[v]);
        const T det_j = CellDeterminant<TDim, T>(x);
        for (const IntegrationPoint& ip : rule) {
            const Eigen::Matrix<double, TDim, 1> nc = CellShapeFunctions<TDim>(ip.local);
            Eigen::Matrix<T, TDim - 1, 1> xi = Eigen::Matrix<T, TDim - 1, 1>::Zero();
            if constexpr (TNS == 4) {  // bilinear slave: global point → local along the slave normal
                SpatialVector<T, TDim> g = SpatialVector<T, TDim>::Zero();
                for (int v = 0; v < TDim; ++v) g += nc[v] * x[v];
                if (!detail::ProjectAlongDirection<TNS, TDim, T>(slave, g, n_slave, xi)) continue;
            } else {  // the slave map is affine: interpolate the vertex local coordinates
                for (int v = 0; v < TDim; ++v) xi += nc[v] * cell.local[v];
            }
            GaussPoint point;
            point.N1 = detail::FaceShapeFunctions<TNS, T>(xi);
            point.x1 = slave.transpose() * point.N1;
            const SpatialVector<T, TDim> interpolated = normals.transpose() * point.N1;
            const T length = detail::Norm<T>(interpolated);
            if (!(Value(length) > 1.0e-300)) continue;
            point.normal = interpolated / length;
            Eigen::Matrix<T, TDim - 1, 1> eta;
            if (!detail::ProjectAlongDirection<TNM, TDim, T>(master, point.x1, point.normal, eta)) continue;
            point.eta = Values(eta);
            point.N2 = detail::FaceShapeFunctions<TNM, T>(eta);
            point.weight = ip.weight * det_j;
            if (mSettings.axisymmetric_thickness > 0.0)
                point.weight *= 2.0 * M_PI * point.x1[0] / mSettings.axisymmetric_thickness;
            points.push_back(point);
        }
    }
}

template <int TDim, int TNS, int TNM, class T>
bool MortarIntegrator<TDim, TNS, TNM, T>::CalculateAe(const SlaveMatrix& De, const SlaveMatrix& Me, SlaveMatrix& Ae) {
    constexpr double tolerance = std::numeric_limits<double>::epsilon();
    Ae.setIdentity();
    T norm_squared(0.0);
    for (int i = 0; i < TNS; ++i)
        for (int j = 0; j < TNS; ++j) norm_squared += Me(i, j) * Me(i, j);
    using std::sqrt;
    const T norm = sqrt(norm_squared);
    if (!(Value(norm) >= tolerance) || !std::isfinite(Value(norm))) return false;
    const SlaveMatrix normalised = Me / norm;
    const T det = normalised.determinant();
    if (!(std::abs(Value(det)) >= tolerance)) return false;
    Ae = De * normalised.inverse() / norm;
    return true;
}

template <int TDim, int TNS, int TNM, class T>
typename MortarIntegrator<TDim, TNS, TNM, T>::DualBasisType MortarIntegrator<TDim, TNS, TNM, T>::ComputeDualBasis(
    const std::vector<GaussPoint>& points) {
    SlaveMatrix De = SlaveMatrix::Zero(), Me = SlaveMatrix::Zero();
    for (const GaussPoint& p : points) {
        for (int i = 0; i < TNS; ++i) {
            const T wn = p.weight * p.N1[i];
            De(i, i) += wn;
            for (int j = 0; j < TNS; ++j) Me(i, j) += wn * p.N1[j];
        }
    }
    DualBasisType result;
    result.dual = CalculateAe(De, Me, result.Ae);
    return result;
}

template <int TDim, int TNS, int TNM, class T>
typename MortarIntegrator<TDim, TNS, TNM, T>::Operators MortarIntegrator<TDim, TNS, TNM, T>::ComputeOperators(
    const std::vector<GaussPoint>& points, const DualBasisType& dual) {
    Operators operators;
    for (const GaussPoint& p : points) {
        const Eigen::Matrix<T, TNS, 1> phi_w = (dual.dual ? Eigen::Matrix<T, TNS, 1>(dual.Ae * p.N1) : p.N1) * p.weight;
        operators.D += phi_w * p.N1.transpose();
        operators.M += phi_w * p.N2.transpose();
    }
    return operators;
}

namespace {

/// IntegrateMortarPair, keeping the Gauss points in @p points.
template <int TDim, int TNS, int TNM, class T, class TNormal>
MortarPairIntegration<T, TDim, TNS, TNM> IntegrateMortarPairAt(
    const MortarIntegrator<TDim, TNS, TNM, T>& integrator, const NodeCoordinates<T, TDim, TNS>& slave,
    const SpatialVector<TNormal, TDim>& slave_normal, const NodeCoordinates<T, TDim, TNM>& master,
    const NodeCoordinates<TNormal, TDim, TNS>& nodal_normals, bool dual_lm,
    std::vector<typename MortarIntegrator<TDim, TNS, TNM, T>::GaussPoint>& points) {
    MortarPairIntegration<T, TDim, TNS, TNM> result;
    const auto& segmentation = integrator.GetSegmentation();
    if (!segmentation.ComputeCells(slave, slave_normal, master, result.cells)) return result;
    result.area = segmentation.TotalArea(slave, result.cells);
    result.used = IsMortarPairUsed(Value(result.area), FaceMeasure<TDim, TNS>(Values(slave)));
    if (!result.used) return result;
    integrator.ComputeGaussPoints(slave, slave_normal, master, nodal_normals, result.cells, points);
    if (dual_lm) result.dual = integrator.ComputeDualBasis(points);
    result.operators = integrator.ComputeOperators(points, result.dual);
    return result;
}

}  // namespace

template <int TDim, int TNS, int TNM, class T, class TNormal>
MortarPairIntegration<T, TDim, TNS, TNM> IntegrateMortarPair(const MortarIntegrator<TDim, TNS, TNM, T>& integrator,
                                                           const NodeCoordinates<T, TDim, TNS>& slave,
                                                           const SpatialVector<TNormal, TDim>& slave_normal,
                                                           const NodeCoordinates<T, TDim, TNM>& master,
                                                           const NodeCoordinates<TNormal, TDim, TNS>& nodal_normals,
                                                           bool dual_lm,
                                                           std::vector<MortarGaussPoint<T, TDim, TNS, TNM>>* pPoints) {
    std::vector<typename MortarIntegrator<TDim, TNS, TNM, T>::GaussPoint> points;
    return IntegrateMortarPairAt(integrator, slave, slave_normal, master, nodal_normals, dual_lm,
                                 pPoints ? *pPoints : points);
}

template <int TDim, int TNS, int TNM, class T, class TNormal>
void MasterOperatorOverNormals(const std::vector<MortarGaussPoint<T, TDim, TNS, TNM>>& points,
                               const DualBasis<T, TNS>& dual, const NodeCoordinates<double, TDim, TNM>& master,
                               const NodeCoordinates<TNormal, TDim, TNS>& nodal_normals,
                               Eigen::Matrix<TNormal, TNS, TNM>& rM) {
    rM.setConstant(TNormal(0.0));
    const NodeCoordinates<TNormal, TDim, TNM> face = master.template cast<TNormal>();
    const Eigen::Matrix<double, TNS, TNS> Ae = Values(dual.Ae);
    for (const auto& p : points) {
        const Eigen::Matrix<double, TNS, 1> N1 = Values(p.N1);
        const SpatialVector<TNormal, TDim> interpolated = nodal_normals.transpose() * N1.template cast<TNormal>();
        const SpatialVector<TNormal, TDim> normal = interpolated / detail::Norm<TNormal>(interpolated);
        const SpatialVector<TNormal, TDim> x1 = Values(p.x1).template cast<TNormal>();
        Eigen::Matrix<TNormal, TDim - 1, 1> eta;
        // Succeeds: it starts from the solution the integration found for the same values.
        if (!detail::ProjectAlongDirection<TNM, TDim, TNormal>(face, x1, normal, eta, &p.eta)) continue;
        const Eigen::Matrix<double, TNS, 1> phi_w = (dual.dual ? Eigen::Matrix<double, TNS, 1>(Ae * N1) : N1) *
                                                    Value(p.weight);
        const Eigen::Matrix<TNormal, TNM, 1> n2 = detail::FaceShapeFunctions<TNM, TNormal>(eta);
        for (int j = 0; j < TNS; ++j)
            for (int l = 0; l < TNM; ++l) rM(j, l) += phi_w[j] * n2[l];
    }
}

template <int TDim, int TNS, int TNM, class TNormal>
MortarPairIntegration<double, TDim, TNS, TNM> IntegrateMortarPairOverNormals(
    const MortarIntegrator<TDim, TNS, TNM, double>& integrator, const NodeCoordinates<double, TDim, TNS>& slave,
    const SpatialVector<double, TDim>& slave_normal, const NodeCoordinates<double, TDim, TNM>& master,
    const NodeCoordinates<TNormal, TDim, TNS>& nodal_normals, bool dual_lm, Eigen::Matrix<TNormal, TNS, TNM>& rM) {
    std::vector<typename MortarIntegrator<TDim, TNS, TNM, double>::GaussPoint> points;
    const NodeCoordinates<double, TDim, TNS> normal_values = Values(nodal_normals);
    const auto pair = IntegrateMortarPairAt(integrator, slave, slave_normal, master, normal_values, dual_lm, points);
    MasterOperatorOverNormals<TDim, TNS, TNM>(points, pair.dual, master, nodal_normals, rM);
    return pair;
}

// -- Explicit instantiations: the registered pairs × {double, Dual<d(n_s+n_m)>} × normal scalar, the pair with M over
// the nodal normals in Dual<d(n_s+n_m)> (tests), and M over them in Dual<d n_s> on the main pass's points (the normal
// pass of the conditions) --
#define CONTACT_APP_INSTANTIATE_INTEGRATION_N(D, NS, NM, T, TN)                                                \
    template void MortarIntegrator<D, NS, NM, T>::ComputeGaussPoints<TN>(                                     \
        const NodeCoordinates<T, D, NS>&, const SpatialVector<TN, D>&, const NodeCoordinates<T, D, NM>&,      \
        const NodeCoordinates<TN, D, NS>&, const MortarCells<T, D>&, std::vector<GaussPoint>&) const;        \
    template MortarPairIntegration<T, D, NS, NM> IntegrateMortarPair<D, NS, NM, T, TN>(                       \
        const MortarIntegrator<D, NS, NM, T>&, const NodeCoordinates<T, D, NS>&, const SpatialVector<TN, D>&, \
        const NodeCoordinates<T, D, NM>&, const NodeCoordinates<TN, D, NS>&, bool,                            \
        std::vector<MortarGaussPoint<T, D, NS, NM>>*);
#define CONTACT_APP_INSTANTIATE_INTEGRATION(A, D, NS, NM)                                                      \
    template class MortarIntegrator<D, NS, NM, double>;                                                        \
    template class MortarIntegrator<D, NS, NM, Dual<D*(NS + NM)>>;                                             \
    CONTACT_APP_INSTANTIATE_INTEGRATION_N(D, NS, NM, double, double)                                           \
    CONTACT_APP_INSTANTIATE_INTEGRATION_N(D, NS, NM, Dual<D*(NS + NM)>, double)                                \
    CONTACT_APP_INSTANTIATE_INTEGRATION_N(D, NS, NM, Dual<D*(NS + NM)>, Dual<D*(NS + NM)>)                     \
    template MortarPairIntegration<double, D, NS, NM> IntegrateMortarPairOverNormals<D, NS, NM, Dual<D*(NS + NM)>>( \
        const MortarIntegrator<D, NS, NM, double>&, const NodeCoordinates<double, D, NS>&,                      \
        const SpatialVector<double, D>&, const NodeCoordinates<double, D, NM>&,                                \
        const NodeCoordinates<Dual<D*(NS + NM)>, D, NS>&, bool, Eigen::Matrix<Dual<D*(NS + NM)>, NS, NM>&);      \
    template void MasterOperatorOverNormals<D, NS, NM, Dual<D*(NS + NM)>, Dual<D * NS>>(                       \
        const std::vector<MortarGaussPoint<Dual<D*(NS + NM)>, D, NS, NM>>&, const DualBasis<Dual<D*(NS + NM)>, NS>&, \
        const NodeCoordinates<double, D, NM>&, const NodeCoordinates<Dual<D * NS>, D, NS>&,                      \
        Eigen::Matrix<Dual<D * NS>, NS, NM>&);
CONTACT_APP_FOR_EACH_MORTAR_PAIR(CONTACT_APP_INSTANTIATE_INTEGRATION, ~)
#undef CONTACT_APP_INSTANTIATE_INTEGRATION
#undef CONTACT_APP_INSTANTIATE_INTEGRATION_N

}  // namespace contact_app
