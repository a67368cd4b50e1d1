// SPDX-License-Identifier: BSD-3-Clause
/// Voigt maps of the solid elements (docs/theory/structural.md §1): plane [xx, yy, xy], axisymmetric
/// [rr, zz, θθ, rz], 3D [xx, yy, zz, xy, yz, xz]; strains carry engineering shear γ = 2ε, stresses do not.
#pragma once

#include <array>
#include <cmath>

#include <Eigen/Core>

namespace contact_app {

/// Tensor index pair (I, J) of each Voigt row for strain size 3, 4 or 6.
template <int TStrainSize>
constexpr std::array<std::array<int, 2>, TStrainSize> VoigtPairs() {
    static_assert(TStrainSize == 3 || TStrainSize == 4 || TStrainSize == 6, "strain size 3, 4 or 6");
    if constexpr (TStrainSize == 3)
        return {{{0, 0}, {1, 1}, {0, 1}}};
    else if constexpr (TStrainSize == 4)
        return {{{0, 0}, {1, 1}, {2, 2}, {0, 1}}};
    else
        return {{{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}}};
}

/// Symmetric TSize × TSize tensor of a Voigt vector; @p shear_factor 1 for stresses, ½ for strains.
template <int TSize, int TStrainSize>
Eigen::Matrix<double, TSize, TSize> VoigtToTensor(const Eigen::Matrix<double, TStrainSize, 1>& voigt,
                                                  double shear_factor) {
    constexpr auto pairs = VoigtPairs<TStrainSize>();
    Eigen::Matrix<double, TSize, TSize> tensor = Eigen::Matrix<double, TSize, TSize>::Zero();
    for (int r = 0; r < TStrainSize; ++r) {
        const double value = pairs[r][0] == pairs[r][1] ? voigt[r] : shear_factor * voigt[r];
        tensor(pairs[r][0], pairs[r][1]) = value;
        tensor(pairs[r][1], pairs[r][0]) = value;
    }
    return tensor;
}

/// Stress tensor of a Voigt stress vector (plain shear).
template <int TSize, int TStrainSize>
Eigen::Matrix<double, TSize, TSize> VoigtToSymmetricTensor(const Eigen::Matrix<double, TStrainSize, 1>& stress) {
    return VoigtToTensor<TSize>(stress, 1.0);
}

/// Strain tensor of a Voigt strain vector (engineering shear halved).
template <int TSize, int TStrainSize>
Eigen::Matrix<double, TSize, TSize> StrainVoigtToSymmetricTensor(const Eigen::Matrix<double, TStrainSize, 1>& strain) {
    return VoigtToTensor<TSize>(strain, 0.5);
}

/// Voigt strain (engineering shear doubled) of a symmetric strain tensor.
template <int TStrainSize, class TTensor>
Eigen::Matrix<double, TStrainSize, 1> SymmetricTensorToStrainVoigt(const TTensor& tensor) {
    constexpr auto pairs = VoigtPairs<TStrainSize>();
    Eigen::Matrix<double, TStrainSize, 1> voigt;
    for (int r = 0; r < TStrainSize; ++r)
        voigt[r] = (pairs[r][0] == pairs[r][1] ? 1.0 : 2.0) * tensor(pairs[r][0], pairs[r][1]);
    return voigt;
}

/// von Mises stress √(3/2 s:s) of a 2×2 (σ_zz = 0) or 3×3 stress tensor, s its deviator.
template <class TTensor>
double VonMisesStress(const TTensor& sigma) {
    Eigen::Matrix3d full = Eigen::Matrix3d::Zero();
    full.topLeftCorner(sigma.rows(), sigma.cols()) = sigma;
    const Eigen::Matrix3d deviator = full - (full.trace() / 3.0) * Eigen::Matrix3d::Identity();
    return std::sqrt(1.5 * deviator.cwiseAbs2().sum());
}

}  // namespace contact_app
