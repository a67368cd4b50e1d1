// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// The part of a penalty pair's tangent that a pair-wise assembly cannot hold (docs/theory/mortar.md §7 "Nodal
/// penalty"). A penalty pair c pushes slave node j with ε X_j, X_j = η_j G_j: G_j = Σ_d g̃^d_j the node's weighted gap
/// over all its pairs and η_j = Σ_d (a^d_j)² / (Σ_d a^d_j)² (both differentiated), so its residual depends on
/// the unknowns of every other pair d of the node:
///   ∂RHS^c/∂q_d = b^c_j (∂X_j/∂q_d)ᵀ,   b^c_j = ∂RHS^c/∂X_j.
/// An active node of the frictional family also reads the transmitted slip T_j = Σ_d a^d_j s^d_j / A_j (A_j = NODAL_AREA
/// = Σ_d a^d_j differentiated too; the stick traction κε(e + T_j), the slip direction of the trial), which adds
///   ∂RHS^c/∂q_d = B^c_j ∂T_j/∂q_d,   B^c_j = ∂RHS^c/∂T_j (n_dof × d),   ∂T_j/∂q_d = (∂(a^d_j s^d_j) − T_j ∂a^d_j)/∂q_d / A_j.
/// The pair's own local tangent holds the d = c blocks; NodalPenaltyCoupling (custom_strategies/) adds the others.
/// When the nodal normals follow the iterate (nodal_normal_coupling.h) g̃^d_j and s^d_j also move with the normals n_m of
/// pair d's slave nodes m, so the pair records ∂X_j/∂n_m and ∂T_j/∂n_m too, and NodalNormalCoupling adds
/// b^c_j (∂X_j/∂n_m)ᵀ ∂n_m/∂x + B^c_j ∂T_j/∂n_m ∂n_m/∂x for d ≠ c.
#include <array>

#include <Eigen/Core>

#include "contact_app/kernel/condition.h"

namespace contact_app {

/// b^c_j and ∂X_j/∂q_c of one pair at one slave node, and where it reads T_j B^c_j and ∂T_j/∂q_c, in the pair's local
/// DoF order (its EquationIdVector).
struct NodalGapCouplingTerms {
    Vector force_per_gap;   ///< b = ∂RHS/∂X_j (RHS the force on the bodies)
    Vector gap_gradient;    ///< ∂X_j/∂q in this pair's unknowns (η ∂g̃_j/∂q + G ∂η/∂a_j ∂a_j/∂q)
    bool reads_slip = false;  ///< whether the two slip terms below are set (an active node of the frictional family)
    Matrix force_per_slip;  ///< B = ∂RHS/∂T_j (n_dof × d)
    Matrix slip_gradient;   ///< ∂T_j/∂q in this pair's unknowns (d × n_dof): (∂(a_j s_j) − T ∂a_j)/∂q / A_j
    /// Normals that follow the iterate: ∂X_j/∂n_m over the pair's slave nodes m (d n_s; empty when the normals are held)
    Vector gap_normal_gradient;
    Matrix slip_normal_gradient;  ///< and ∂T_j/∂n_m (d × d n_s) where it reads T_j
};

/// A pair condition whose residual reads the nodal penalty gap X = η G of its slave nodes (and the transmitted slip T).
class NodalGapCouplingSource {
public:
    virtual ~NodalGapCouplingSource() = default;
    /// The coupling terms of slave node @p j (local index) recorded by the pair's last tangent evaluation
    /// (CalculateLocalSystem / CalculateLeftHandSide; the builder runs its contributors after the entities); false when
    /// the node added nothing through X (inactive, or the pair isolated).
    virtual bool GetNodalGapCoupling(int j, NodalGapCouplingTerms& rTerms) const = 0;
};

/// What a penalty pair records of its slave nodes while its tangent is differentiated (filled by the residual of the
/// AD pass, read by GetNodalGapCoupling).
template <int TDim, int TNumNodes, int TMatrixSize>
struct NodalGapCouplingRecord {
    std::array<bool, TNumNodes> coupled{};
    std::array<Eigen::Matrix<double, TMatrixSize, 1>, TNumNodes> force_per_gap{};
    std::array<Eigen::Matrix<double, TMatrixSize, 1>, TNumNodes> gap_gradient{};
    std::array<bool, TNumNodes> reads_slip{};  ///< set with coupled, for an active node of the frictional family
    std::array<Eigen::Matrix<double, TMatrixSize, TDim>, TNumNodes> force_per_slip{};
    std::array<Eigen::Matrix<double, TDim, TMatrixSize>, TNumNodes> slip_gradient{};
    bool normals_recorded = false;  ///< the normal gradients below belong to this evaluation
    std::array<Eigen::Matrix<double, TDim * TNumNodes, 1>, TNumNodes> gap_normal_gradient{};
    std::array<Eigen::Matrix<double, TDim, TDim * TNumNodes>, TNumNodes> slip_normal_gradient{};

    void Clear() {
        coupled.fill(false);
        reads_slip.fill(false);
        normals_recorded = false;
    }
    /// ∂X_j of the running AD pass: in the unknowns q (the main pass, TMatrixSize derivatives) or in the slave nodal
    /// normals (the normal pass, d n_s derivatives, which runs first).
    template <class TGradient>
    void SetGapGradient(int j, const TGradient& gradient) {
        if constexpr (TGradient::RowsAtCompileTime == TMatrixSize)
            gap_gradient[j] = gradient;
        else
            gap_normal_gradient[j] = gradient;
    }
    /// Row @p c of ∂T_j of the running AD pass, as SetGapGradient.
    template <class TGradient>
    void SetSlipGradientRow(int j, int c, const TGradient& gradient) {
        if constexpr (TGradient::RowsAtCompileTime == TMatrixSize)
            slip_gradient[j].row(c) = gradient.transpose();
        else
            slip_normal_gradient[j].row(c) = gradient.transpose();
    }
    bool Get(int j, NodalGapCouplingTerms& rTerms) const {
        if (!coupled[j]) return false;
        rTerms.force_per_gap = force_per_gap[j];
        rTerms.gap_gradient = gap_gradient[j];
        rTerms.reads_slip = reads_slip[j];
        if (reads_slip[j]) {
            rTerms.force_per_slip = force_per_slip[j];
            rTerms.slip_gradient = slip_gradient[j];
        }
        rTerms.gap_normal_gradient.resize(0);
        rTerms.slip_normal_gradient.resize(0, 0);
        if (normals_recorded) {
            rTerms.gap_normal_gradient = gap_normal_gradient[j];
            if (reads_slip[j]) rTerms.slip_normal_gradient = slip_normal_gradient[j];
        }
        return true;
    }
};

}  // namespace contact_app
