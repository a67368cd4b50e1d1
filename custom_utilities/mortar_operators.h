// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "contact_app/kernel/geometries/quadrature.h"
#include "custom_utilities/exact_mortar_segmentation.h"
#include "custom_utilities/mortar_types.h"

namespace contact_app {

/// Kinematics at one mortar integration point (Kratos MortarKinematicVariables).
template <class T, int TDim, int TNumNodes, int TNumNodesMaster>
struct MortarGaussPoint {
    Eigen::Matrix<T, TNumNodes, 1> N1;        ///< slave shape functions at the point
    Eigen::Matrix<T, TNumNodesMaster, 1> N2;  ///< master shape functions at the projected point
    SpatialVector<T, TDim> x1;                ///< point on the slave face
    SpatialVector<T, TDim> normal;            ///< unit GP normal, normalised Σ N1_i n_i
    T weight;                                 ///< w_gp · det J_cell · (2π r / t if axisymmetric)
    Eigen::Matrix<double, TDim - 1, 1> eta;   ///< master local coordinates of the projected point (values; N2 = N(η))
};

/// @brief Gauss rule on one integration cell from INTEGRATION_ORDER_CONTACT (GetIntegrationMethod table):
///        orders 1..5 → GAUSS_1..5 (line 1..5 points, triangle 1,3,4,6,7 points), any other value → 2.
/// @param[in] dim 2 (line cells) or 3 (triangle cells)
/// @param[in] integration_order_contact the INTEGRATION_ORDER_CONTACT value of the condition's properties
const std::vector<IntegrationPoint>& MortarCellGaussRule(int dim, int integration_order_contact);

/// Integration of the mortar operators and of the dual basis over the cells of one pair
/// (Popp eq. 3.31/3.32 and 3.65):  D_jk = Σ w Φ_j N1_k,  M_jl = Σ w Φ_j N2_l,
/// De = Σ w diag(N1), Me = Σ w N1 N1ᵀ, Ae = De Me⁻¹ (safeguarded). Cells come from
/// ExactMortarSegmentation; each Gauss point of a cell is mapped to the slave (local coordinates), then
/// projected on the master along the GP normal (normalised Σ N1_i n_i of the nodal normals n_i).
/// Templated on the scalar: with Dual coordinates every output carries its exact derivatives.
/// See docs/theory/mortar.md §2–3.
template <int TDim, int TNumNodes, int TNumNodesMaster, class TScalar = double>
class MortarIntegrator {
public:
    using Segmentation = ExactMortarSegmentation<TDim, TNumNodes, TNumNodesMaster, TScalar>;
    using GaussPoint = MortarGaussPoint<TScalar, TDim, TNumNodes, TNumNodesMaster>;
    using Operators = MortarOperators<TScalar, TNumNodes, TNumNodesMaster>;
    using DualBasisType = DualBasis<TScalar, TNumNodes>;
    using SlaveMatrix = Eigen::Matrix<TScalar, TNumNodes, TNumNodes>;

    explicit MortarIntegrator(MortarIntegrationSettings settings = {}, SegmentationSettings segmentation = {})
        : mSettings(settings), mSegmentation(segmentation) {}

    /// @brief Kinematics at every Gauss point of every non-degenerate cell.
    /// @param[in] slave n_s × d current slave coordinates
    /// @param[in] master n_m × d current master coordinates
    /// @param[in] slave_normal d-vector, slave condition normal (the segmentation direction)
    /// @param[in] nodal_normals n_s × d unit nodal NORMAL of the slave nodes
    /// @param[in] cells cells from ComputeCells on the same data
    /// @param[out] points cleared, then filled; points whose master projection fails are skipped
    template <class TNormal>
    void ComputeGaussPoints(const typename Segmentation::SlaveCoordinates& slave,
                            const SpatialVector<TNormal, TDim>& slave_normal,
                            const typename Segmentation::MasterCoordinates& master,
                            const NodeCoordinates<TNormal, TDim, TNumNodes>& nodal_normals,
                            const MortarCells<TScalar, TDim>& cells, std::vector<GaussPoint>& points) const;

    /// @brief Ae = De·Me⁻¹ over the points (Kratos CalculateAe safeguard: ‖Me‖_F < ε or
    ///        |det(Me/‖Me‖_F)| < ε → Ae = I, dual = false).
    static DualBasisType ComputeDualBasis(const std::vector<GaussPoint>& points);
    /// @brief D and M with Φ = Ae·N1 (pass DualBasis{} for standard multipliers).
    static Operators ComputeOperators(const std::vector<GaussPoint>& points, const DualBasisType& dual);
    /// @brief Safeguarded Ae = De·Me⁻¹. @return false (and Ae = I) when Me is (numerically) singular
    static bool CalculateAe(const SlaveMatrix& De, const SlaveMatrix& Me, SlaveMatrix& Ae);

    const Segmentation& GetSegmentation() const { return mSegmentation; }
    const MortarIntegrationSettings& Settings() const { return mSettings; }

private:
    MortarIntegrationSettings mSettings;
    Segmentation mSegmentation;
};

/// Everything a condition needs from one pair: the isolation decision, the dual basis and D, M.
template <class T, int TDim, int TNumNodes, int TNumNodesMaster>
struct MortarPairIntegration {
    bool used = false;  ///< cells found and overlap / slave area > 1e−5 (otherwise ISOLATED)
    T area = T(0.0);    ///< total cell area (length in 2D)
    MortarCells<T, TDim> cells;
    DualBasis<T, TNumNodes> dual;
    MortarOperators<T, TNumNodes, TNumNodesMaster> operators;
};

/// @brief Segmentation + isolation rule + (optional) dual basis + D, M for one pair (condition steps 2–4).
/// The slave measure of the 1e−5 rule is the face length (2D), area (triangle) or ½|d₁×d₂| (quadrilateral).
/// @param[in] integrator the pair's mortar integrator (segmentation and integration settings)
/// @param[in] slave n_s × d current slave coordinates
/// @param[in] slave_normal d-vector, slave condition normal (the segmentation direction)
/// @param[in] master n_m × d current master coordinates
/// @param[in] nodal_normals n_s × d unit nodal NORMAL of the slave nodes
/// @param[in] dual_lm request dual multipliers (falls back to standard ones when Ae fails)
/// @param[out] pPoints if not null, receives the Gauss points (for MasterOperatorOverNormals)
template <int TDim, int TNumNodes, int TNumNodesMaster, class T, class TNormal>
MortarPairIntegration<T, TDim, TNumNodes, TNumNodesMaster> IntegrateMortarPair(
    const MortarIntegrator<TDim, TNumNodes, TNumNodesMaster, T>& integrator,
    const NodeCoordinates<T, TDim, TNumNodes>& slave, const SpatialVector<TNormal, TDim>& slave_normal,
    const NodeCoordinates<T, TDim, TNumNodesMaster>& master,
    const NodeCoordinates<TNormal, TDim, TNumNodes>& nodal_normals, bool dual_lm,
    std::vector<MortarGaussPoint<T, TDim, TNumNodes, TNumNodesMaster>>* pPoints = nullptr);

/// @brief M as a function of the slave nodal normals alone, the coordinates held, on the Gauss points of a pair
/// already integrated (their values are read, whatever their scalar): M_jl = Σ w Φ_j N2_l(η) with x2(η) − s ν = x1 and
/// ν = Σ N1_i n_i / |Σ N1_i n_i|. The cells, w, N1, the dual basis and D read only the slave face and its face-centre
/// normal; only the projection onto the master is repeated in TNormal, from each point's η (one Newton iteration): a
/// fraction of the cost of integrating the pair again (docs/theory/mortar.md §7 "Normals that follow the iterate").
/// @param[in] points the pair's Gauss points (IntegrateMortarPair with pPoints)
/// @param[in] dual the pair's dual basis (its values are read)
/// @param[in] master n_m × d current master coordinates
/// @param[in] nodal_normals n_s × d unit nodal NORMAL of the slave nodes, with the derivatives wanted (their values those
///            the points were integrated with)
/// @param[out] rM M in TNormal
template <int TDim, int TNumNodes, int TNumNodesMaster, class T, class TNormal>
void MasterOperatorOverNormals(const std::vector<MortarGaussPoint<T, TDim, TNumNodes, TNumNodesMaster>>& points,
                              const DualBasis<T, TNumNodes>& dual,
                              const NodeCoordinates<double, TDim, TNumNodesMaster>& master,
                              const NodeCoordinates<TNormal, TDim, TNumNodes>& nodal_normals,
                              Eigen::Matrix<TNormal, TNumNodes, TNumNodesMaster>& rM);

/// @brief IntegrateMortarPair in double, and M as a function of the slave nodal normals alone, the coordinates held:
/// M_jl = Σ w Φ_j N2_l(η) with x2(η) − s ν = x1 and ν = Σ N1_i n_i / |Σ N1_i n_i|. The cells, w, N1, the dual basis and
/// D read only the slave face and its face-centre normal; only the projection onto the master is repeated in TNormal, a
/// fraction of the cost of integrating the pair with the normals seeded (docs/theory/mortar.md §7 "Normals that follow
/// the iterate").
/// @param[in] integrator the pair's mortar integrator in double
/// @param[in] slave n_s × d current slave coordinates
/// @param[in] slave_normal d-vector, slave condition normal (the segmentation direction)
/// @param[in] master n_m × d current master coordinates
/// @param[in] nodal_normals n_s × d unit nodal NORMAL of the slave nodes, with the derivatives wanted
/// @param[in] dual_lm request dual multipliers (falls back to standard ones when Ae fails)
/// @param[out] rM M in TNormal (zero when the pair is not used)
/// @return the pair in double, as IntegrateMortarPair
template <int TDim, int TNumNodes, int TNumNodesMaster, class TNormal>
MortarPairIntegration<double, TDim, TNumNodes, TNumNodesMaster> IntegrateMortarPairOverNormals(
    const MortarIntegrator<TDim, TNumNodes, TNumNodesMaster, double>& integrator,
    const NodeCoordinates<double, TDim, TNumNodes>& slave, const SpatialVector<double, TDim>& slave_normal,
    const NodeCoordinates<double, TDim, TNumNodesMaster>& master,
    const NodeCoordinates<TNormal, TDim, TNumNodes>& nodal_normals, bool dual_lm,
    Eigen::Matrix<TNormal, TNumNodes, TNumNodesMaster>& rM);

}  // namespace contact_app
