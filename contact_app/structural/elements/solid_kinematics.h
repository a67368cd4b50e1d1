// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>

#include "contact_app/structural/elements/solid_voigt.h"

namespace contact_app {

/// Kinematics of one integration point: scratch data on the stack of the local-system loop.
/// @tparam TStrainSize 3 (plane [xx, yy, xy]), 4 (axisymmetric [rr, zz, θθ, rz]) or 6 (3D).
template <int TDim, int TNumNodes, int TStrainSize>
struct SolidKinematics {
    static constexpr int kDofs = TDim * TNumNodes;
    /// F is 3×3 for axisymmetric elements (F(2,2) = hoop stretch), TDim × TDim otherwise.
    static constexpr int kFSize = TStrainSize == 4 ? 3 : TDim;
    using FMatrix = Eigen::Matrix<double, kFSize, kFSize>;
    using StrainVector = Eigen::Matrix<double, TStrainSize, 1>;

    Eigen::Matrix<double, TNumNodes, 1> N;
    Eigen::Matrix<double, TNumNodes, TDim> DN_DX;  ///< gradients B and K_g are built from
    Eigen::Matrix<double, TNumNodes, 1> hoop;      ///< axisymmetric ∂F(2,2)/∂u_r,i = N_i / R (else unused)
    FMatrix F;                                     ///< deformation gradient handed to the law
    double detF = 1.0;
    Eigen::Matrix<double, TStrainSize, kDofs> B;  ///< δstrain = B δu, engineering shear
    StrainVector strain;                          ///< small strain (SD) or Green–Lagrange strain, Voigt
    double weight = 0.0;       ///< stiffness/residual weight: w_g det J × (t in 2D | 2πR axisymmetric)
    double body_weight = 0.0;  ///< body-force weight: the same measure of the reference volume
};

/// @brief Fills rKinematics.B, δE = B δu, from rKinematics.F (identity: the linear B), DN_DX and, for strain
///        size 4, hoop. Row (I, J): F_aI N_i,I (I = J), F_aI N_i,J + F_aJ N_i,I (shear); hoop row F(2,2)·hoop_i
///        on the radial DoF.
template <int TDim, int TNumNodes, int TStrainSize>
void FillStrainDisplacementMatrix(SolidKinematics<TDim, TNumNodes, TStrainSize>& rKinematics) {
    constexpr auto pairs = VoigtPairs<TStrainSize>();
    auto& B = rKinematics.B;
    const auto& F = rKinematics.F;
    const auto& DN = rKinematics.DN_DX;
    B.setZero();
    for (int r = 0; r < TStrainSize; ++r) {
        const int I = pairs[r][0];
        const int J = pairs[r][1];
        for (int i = 0; i < TNumNodes; ++i) {
            if (I == J && I >= TDim) {
                B(r, i * TDim) = F(2, 2) * rKinematics.hoop[i];
            } else if (I == J) {
                for (int a = 0; a < TDim; ++a) B(r, i * TDim + a) = F(a, I) * DN(i, I);
            } else {
                for (int a = 0; a < TDim; ++a) B(r, i * TDim + a) = F(a, I) * DN(i, J) + F(a, J) * DN(i, I);
            }
        }
    }
}

/// @brief ½(FᵀF − I) in Voigt (engineering shear).
template <int TStrainSize, int TSize>
Eigen::Matrix<double, TStrainSize, 1> GreenLagrangeStrain(const Eigen::Matrix<double, TSize, TSize>& F) {
    const Eigen::Matrix<double, TSize, TSize> E =
        0.5 * (F.transpose() * F - Eigen::Matrix<double, TSize, TSize>::Identity());
    return SymmetricTensorToStrainVoigt<TStrainSize>(E);
}

/// @brief I + ε (half shears off the diagonal): the "equivalent F" of the small-displacement elements.
template <int TSize, int TStrainSize>
Eigen::Matrix<double, TSize, TSize> EquivalentDeformationGradient(const Eigen::Matrix<double, TStrainSize, 1>& strain) {
    return Eigen::Matrix<double, TSize, TSize>::Identity() + StrainVoigtToSymmetricTensor<TSize>(strain);
}

}  // namespace contact_app
