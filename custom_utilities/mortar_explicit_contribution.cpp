// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/mortar_explicit_contribution.h"

#include <utility>

#include "custom_utilities/mortar_geometry_math.h"

namespace contact_app {

template <int TDim, int TNS, int TNM, class T, class TNormal>
Eigen::Matrix<T, TNS, 1> WeightedGap(const MortarOperators<T, TNS, TNM>& operators, const NodeCoordinates<T, TDim, TNS>& x1,
                                     const NodeCoordinates<T, TDim, TNM>& x2,
                                     const NodeCoordinates<TNormal, TDim, TNS>& normals) {
    const NodeCoordinates<T, TDim, TNS> residual = operators.D * x1 - operators.M * x2;
    const NodeCoordinates<T, TDim, TNS> n = normals.template cast<T>();
    Eigen::Matrix<T, TNS, 1> gap;
    for (int i = 0; i < TNS; ++i) gap[i] = -n.row(i).dot(residual.row(i));
    return gap;
}

template <int TDim, int TNS, int TNM, class T, class TNormal>
NodeCoordinates<T, TDim, TNS> WeightedSlip(const MortarOperators<T, TNS, TNM>& operators,
                                           const MortarOperators<double, TNS, TNM>& previous,
                                           const NodeCoordinates<T, TDim, TNS>& x1, const NodeCoordinates<T, TDim, TNM>& x2,
                                           const NodeCoordinates<double, TDim, TNS>& x1_previous,
                                           const NodeCoordinates<double, TDim, TNM>& x2_previous,
                                           const NodeCoordinates<TNormal, TDim, TNS>& normals, double delta_time,
                                           bool objective) {
    NodeCoordinates<T, TDim, TNS> rate;
    if (objective) {
        rate = (operators.D - previous.D.template cast<T>()) * x1 - (operators.M - previous.M.template cast<T>()) * x2;
    } else {
        rate = -(operators.D * (x1 - x1_previous.template cast<T>()) - operators.M * (x2 - x2_previous.template cast<T>()));
    }
    rate /= delta_time;
    const NodeCoordinates<T, TDim, TNS> n = normals.template cast<T>();
    NodeCoordinates<T, TDim, TNS> slip;
    for (int i = 0; i < TNS; ++i) {
        const T normal_part = n.row(i).dot(rate.row(i));
        slip.row(i) = delta_time * (rate.row(i) - normal_part * n.row(i));
    }
    return slip;
}

namespace {

/// What every explicit pass writes (isolation, dual basis, weighted gap, nodal area), and the pair it integrated.
template <int TDim, int TNS, int TNM, class T, class TNormal>
auto ExplicitGapPart(const MortarIntegrator<TDim, TNS, TNM, T>& integrator, const NodeCoordinates<T, TDim, TNS>& x1,
                     const SpatialVector<TNormal, TDim>& slave_normal, const NodeCoordinates<T, TDim, TNM>& x2,
                     const NodeCoordinates<TNormal, TDim, TNS>& normals, const ExplicitContributionOptions& options) {
    ExplicitMortarContribution<T, TDim, TNS> result;
    auto pair = IntegrateMortarPair(integrator, x1, slave_normal, x2, normals, options.dual_lm);
    if (pair.used) {
        result.isolated = false;
        result.dual = pair.dual.dual;
        result.weighted_gap = WeightedGap<TDim, TNS, TNM, T, TNormal>(pair.operators, x1, x2, normals);
        if (options.compute_nodal_area) result.nodal_area = pair.operators.D.rowwise().sum();
    }
    return std::make_pair(std::move(result), std::move(pair));
}

}  // namespace

template <int TDim, int TNS, int TNM, class T, class TNormal>
ExplicitMortarContribution<T, TDim, TNS> ComputeExplicitMortarContribution(
    const MortarIntegrator<TDim, TNS, TNM, T>& integrator, const NodeCoordinates<T, TDim, TNS>& x1,
    const SpatialVector<TNormal, TDim>& slave_normal, const NodeCoordinates<T, TDim, TNM>& x2,
    const NodeCoordinates<TNormal, TDim, TNS>& normals, const ExplicitContributionOptions& options) {
    return ExplicitGapPart(integrator, x1, slave_normal, x2, normals, options).first;
}

template <int TDim, int TNS, int TNM, class T, class TNormal>
ExplicitMortarContribution<T, TDim, TNS> ComputeExplicitFrictionalMortarContribution(
    const MortarIntegrator<TDim, TNS, TNM, T>& integrator, const NodeCoordinates<T, TDim, TNS>& x1,
    const SpatialVector<TNormal, TDim>& slave_normal, const NodeCoordinates<T, TDim, TNM>& x2,
    const NodeCoordinates<TNormal, TDim, TNS>& normals, const MortarOperators<double, TNS, TNM>& previous,
    const NodeCoordinates<double, TDim, TNS>& x1_previous, const NodeCoordinates<double, TDim, TNM>& x2_previous,
    double delta_time, bool objective, const ExplicitContributionOptions& options) {
    auto [result, pair] = ExplicitGapPart(integrator, x1, slave_normal, x2, normals, options);
    if (pair.used)
        result.weighted_slip = WeightedSlip<TDim, TNS, TNM, T, TNormal>(pair.operators, previous, x1, x2, x1_previous,
                                                                       x2_previous, normals, delta_time, objective);
    return result;
}

template <int TDim, int TNS, int TNM>
MortarOperators<double, TNS, TNM> ComputePreviousMortarOperators(const MortarIntegrator<TDim, TNS, TNM, double>& integrator,
                                                                 const NodeCoordinates<double, TDim, TNS>& x1,
                                                                 const SpatialVector<double, TDim>& slave_normal,
                                                                 const NodeCoordinates<double, TDim, TNM>& x2,
                                                                 const NodeCoordinates<double, TDim, TNS>& normals,
                                                                 bool& dual) {
    const auto pair = IntegrateMortarPair(integrator, x1, slave_normal, x2, normals, true);
    dual = pair.used && pair.dual.dual;
    return pair.used ? pair.operators : MortarOperators<double, TNS, TNM>{};
}

#define CONTACT_APP_INSTANTIATE_EXPLICIT_N(D, NS, NM, T, TN)                                                     \
    template Eigen::Matrix<T, NS, 1> WeightedGap<D, NS, NM, T, TN>(                                            \
        const MortarOperators<T, NS, NM>&, const NodeCoordinates<T, D, NS>&, const NodeCoordinates<T, D, NM>&,  \
        const NodeCoordinates<TN, D, NS>&);                                                                    \
    template NodeCoordinates<T, D, NS> WeightedSlip<D, NS, NM, T, TN>(                                         \
        const MortarOperators<T, NS, NM>&, const MortarOperators<double, NS, NM>&,                             \
        const NodeCoordinates<T, D, NS>&, const NodeCoordinates<T, D, NM>&, const NodeCoordinates<double, D, NS>&, \
        const NodeCoordinates<double, D, NM>&, const NodeCoordinates<TN, D, NS>&, double, bool);               \
    template ExplicitMortarContribution<T, D, NS> ComputeExplicitMortarContribution<D, NS, NM, T, TN>(         \
        const MortarIntegrator<D, NS, NM, T>&, const NodeCoordinates<T, D, NS>&, const SpatialVector<TN, D>&,  \
        const NodeCoordinates<T, D, NM>&, const NodeCoordinates<TN, D, NS>&, const ExplicitContributionOptions&); \
    template ExplicitMortarContribution<T, D, NS> ComputeExplicitFrictionalMortarContribution<D, NS, NM, T, TN>( \
        const MortarIntegrator<D, NS, NM, T>&, const NodeCoordinates<T, D, NS>&, const SpatialVector<TN, D>&,  \
        const NodeCoordinates<T, D, NM>&, const NodeCoordinates<TN, D, NS>&, const MortarOperators<double, NS, NM>&, \
        const NodeCoordinates<double, D, NS>&, const NodeCoordinates<double, D, NM>&, double, bool,            \
        const ExplicitContributionOptions&);
#define CONTACT_APP_INSTANTIATE_EXPLICIT(A, D, NS, NM)                                                          \
    CONTACT_APP_INSTANTIATE_EXPLICIT_N(D, NS, NM, double, double)                                              \
    CONTACT_APP_INSTANTIATE_EXPLICIT_N(D, NS, NM, Dual<D*(NS + NM)>, double)                                   \
    CONTACT_APP_INSTANTIATE_EXPLICIT_N(D, NS, NM, Dual<D*(NS + NM)>, Dual<D*(NS + NM)>)                        \
    template MortarOperators<double, NS, NM> ComputePreviousMortarOperators<D, NS, NM>(                        \
        const MortarIntegrator<D, NS, NM, double>&, const NodeCoordinates<double, D, NS>&,                     \
        const SpatialVector<double, D>&, const NodeCoordinates<double, D, NM>&,                                \
        const NodeCoordinates<double, D, NS>&, bool&);
CONTACT_APP_FOR_EACH_MORTAR_PAIR(CONTACT_APP_INSTANTIATE_EXPLICIT, ~)
#undef CONTACT_APP_INSTANTIATE_EXPLICIT
#undef CONTACT_APP_INSTANTIATE_EXPLICIT_N

}  // namespace contact_app
