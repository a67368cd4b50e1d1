// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// The part of a penalty pair's tangent that a pair-wise assembly cannot hold (docs/theory/mortar.md §7 "Nodal
/// penalty"). A penalty pair c pushes slave node j with ε X_j, X_j = η_j G_j: G_j = Σ_d g̃^d_j the node's weighted gap
/// over all its pairs and η_j = Σ_d (a^d_j)² / (Σ_d a^d_j)² (both differentiated), so its residual depends on
/// the unknowns of every other pair d of the node:
///   ∂RHS^c/∂q_d = b^c_j (∂X_j/∂q_d)ᵀ,   b^c_j = ∂RHS^c/∂X_j.
/// A slipping node of the frictional family also takes its direction from the transmitted slip
/// T_j = Σ_d a^d_j s^d_j / A_j (A_j = NODAL_AREA = Σ_d a^d_j differentiated too), which adds
///   ∂RHS^c/∂q_d = B^c_j ∂T_j/∂q_d,   B^c_j = ∂RHS^c/∂T_j (n_dof × d),   ∂T_j/∂q_d = (∂(a^d_j s^d_j) − T_j ∂a^d_j)/∂q_d / A_j.
/// The pair's own local tangent holds the d = c blocks; NodalPenaltyCoupling (custom_strategies/) adds the others.
#include <array>

#include <Eigen/Core>

#include "contact_app/kernel/condition.h"

namespace contact_app {

/// b^c_j and ∂X_j/∂q_c of one pair at one slave node, and at a slipping node B^c_j and ∂T_j/∂q_c, in the pair's local
/// DoF order (its EquationIdVector).
struct NodalGapCouplingTerms {
    Vector force_per_gap;   ///< b = ∂RHS/∂X_j (RHS the force on the bodies)
    Vector gap_gradient;    ///< ∂X_j/∂q in this pair's unknowns (η ∂g̃_j/∂q + G ∂η/∂a_j ∂a_j/∂q)
    bool slipping = false;  ///< whether the two slip terms below are set
    Matrix force_per_slip;  ///< B = ∂RHS/∂T_j (n_dof × d)
    Matrix slip_gradient;   ///< ∂T_j/∂q in this pair's unknowns (d × n_dof): (∂(a_j s_j) − T ∂a_j)/∂q / A_j
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
    std::array<bool, TNumNodes> slipping{};  ///< set with coupled, for a slipping node of the frictional family
    std::array<Eigen::Matrix<double, TMatrixSize, TDim>, TNumNodes> force_per_slip{};
    std::array<Eigen::Matrix<double, TDim, TMatrixSize>, TNumNodes> slip_gradient{};

    void Clear() {
        coupled.fill(false);
        slipping.fill(false);
    }
    bool Get(int j, NodalGapCouplingTerms& rTerms) const {
        if (!coupled[j]) return false;
        rTerms.force_per_gap = force_per_gap[j];
        rTerms.gap_gradient = gap_gradient[j];
        rTerms.slipping = slipping[j];
        if (slipping[j]) {
            rTerms.force_per_slip = force_per_slip[j];
            rTerms.slip_gradient = slip_gradient[j];
        }
        return true;
    }
};

}  // namespace contact_app
