// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>
#include <string>
#include <tuple>
#include <vector>

#include <Eigen/Core>

#include "automatic_differentiation/dual.h"
#include "contact_app/kernel/serializer.h"

namespace contact_app {

/// The registered mortar pairs, the one list to extend with a pair: X(A, TDim, TNumNodes (slave), TNumNodesMaster)
/// for 2D2N, 3D3N, 3D4N, 3D3N4N, 3D4N3N (A is passed through to X, e.g. a class template or `~`). Every per-pair
/// explicit instantiation (segmentation, operators, explicit contributions, normals, the condition families) and
/// the registered condition names (custom_conditions/contact_condition_registration.cpp) expand it.
#define CONTACT_APP_FOR_EACH_MORTAR_PAIR(X, A) X(A, 2, 2, 2) X(A, 3, 3, 3) X(A, 3, 4, 4) X(A, 3, 3, 4) X(A, 3, 4, 3)
/// The faces of those pairs, X(A, TDim, TNumNodes): per-face instantiations (adapters, double-valued normals).
#define CONTACT_APP_FOR_EACH_MORTAR_FACE(X, A) X(A, 2, 2) X(A, 3, 3) X(A, 3, 4)
/// Explicit instantiation of TClass<TDim, TNumNodes, TNumNodesMaster> for every registered pair.
#define CONTACT_APP_INSTANTIATE_PAIR_(TClass, D, NS, NM) template class TClass<D, NS, NM>;
#define CONTACT_APP_INSTANTIATE_FOR_EACH_MORTAR_PAIR(TClass) \
    CONTACT_APP_FOR_EACH_MORTAR_PAIR(CONTACT_APP_INSTANTIATE_PAIR_, TClass)

/// Compile-time description of a registered mortar pair <TDim, TNumNodes (slave), TNumNodesMaster>
/// (CONTACT_APP_FOR_EACH_MORTAR_PAIR).
/// DOF index convention (as Kratos' DerivativeData): q = node·TDim + component, slave nodes first.
template <int TDim, int TNumNodes, int TNumNodesMaster>
struct MortarPairTraits {
    static constexpr int Dim = TDim;
    static constexpr int NumSlave = TNumNodes;
    static constexpr int NumMaster = TNumNodesMaster;
    static constexpr int LocalDim = TDim - 1;
    /// Number of coordinate DOFs of the pair, d·(n_s + n_m).
    static constexpr int NumDofs = TDim * (TNumNodes + TNumNodesMaster);
    /// PointBelongs base value B = n_s + n_m (generic intersection); edge hashes are B + 10·s0 + ….
    static constexpr int BaseTag = TNumNodes + TNumNodesMaster;
    /// The AD scalar holding ∂/∂(all pair coordinates).
    using ADScalar = Dual<NumDofs>;
};

namespace detail {
template <class TTuple>
struct DropFirstType;
template <class TFirst, class... TRest>
struct DropFirstType<std::tuple<TFirst, TRest...>> {
    using type = std::tuple<TRest...>;
};
}  // namespace detail

#define CONTACT_APP_MORTAR_PAIR_TRAITS_(A, D, NS, NM) , MortarPairTraits<D, NS, NM>
/// std::tuple of the MortarPairTraits of every registered pair, for compile-time loops over the pairs.
using RegisteredMortarPairs =
    detail::DropFirstType<std::tuple<void CONTACT_APP_FOR_EACH_MORTAR_PAIR(CONTACT_APP_MORTAR_PAIR_TRAITS_, ~)>>::type;
#undef CONTACT_APP_MORTAR_PAIR_TRAITS_

/// Node coordinates of one side: row i = node i (TDim columns).
template <class T, int TDim, int TNumNodes>
using NodeCoordinates = Eigen::Matrix<T, TNumNodes, TDim>;
/// One TDim-vector (a condition normal, a point).
template <class T, int TDim>
using SpatialVector = Eigen::Matrix<T, TDim, 1>;

/// One integration cell: TDim vertices in slave local coordinates (ξ in 2D, (ξ, η) in 3D) and, per vertex,
/// its PointBelongs tag (docs/theory/mortar.md §1): v < n_s slave node v; n_s ≤ v < B master node v−n_s;
/// B generic intersection (tessellation centroid); v > B edge–edge intersection B + 10·s0 + 100·s1 +
/// 1000·m0 + 10000·m1.
template <class T, int TDim>
struct MortarCell {
    std::array<Eigen::Matrix<T, TDim - 1, 1>, TDim> local;
    std::array<int, TDim> belong{};
};

template <class T, int TDim>
using MortarCells = std::vector<MortarCell<T, TDim>>;

/// Segmentation options (ProcessInfo DISTANCE_THRESHOLD, ZERO_TOLERANCE_FACTOR; Properties
/// CONSIDER_TESSELLATION). Defaults are the Kratos ones except consider_tessellation.
struct SegmentationSettings {
    /// A master node farther than this in front of the slave (along the slave normal) → no cells.
    double distance_threshold = 1.0e24;
    /// Multiplies the tolerance of the inside tests.
    double zero_tolerance_factor = 1.0;
    /// Triangulate the clipped polygon around its area centroid (n cells, continuous in the vertices) instead of a
    /// fan from its first vertex (n−2 cells, the reference's default, which jumps when the first vertex changes):
    /// true by default, docs/theory/mortar.md §1.
    bool consider_tessellation = true;
};

/// Integration options (Properties INTEGRATION_ORDER_CONTACT; axisymmetric THICKNESS).
struct MortarIntegrationSettings {
    /// INTEGRATION_ORDER_CONTACT: 1..5 → Gauss order 1..5 on every cell, any other value → 2.
    int integration_order = 2;
    /// > 0: axisymmetric, every weight is multiplied by 2π r / thickness (r = x-coordinate of the point).
    double axisymmetric_thickness = 0.0;
};

/// Mortar operators of one pair: D (n_s × n_s), M (n_s × n_m), D_jk = ∫ Φ_j N1_k, M_jl = ∫ Φ_j N2_l.
template <class T, int TNumNodes, int TNumNodesMaster>
struct MortarOperators {
    Eigen::Matrix<T, TNumNodes, TNumNodes> D = Eigen::Matrix<T, TNumNodes, TNumNodes>::Zero();
    Eigen::Matrix<T, TNumNodes, TNumNodesMaster> M = Eigen::Matrix<T, TNumNodes, TNumNodesMaster>::Zero();
    void Initialize() {
        D.setZero();
        M.setZero();
    }
    /// Restart (double operators): D and M under the tags "<prefix>D" and "<prefix>M".
    void Save(Serializer& serializer, const std::string& prefix) const {
        serializer.Save((prefix + "D").c_str(), D);
        serializer.Save((prefix + "M").c_str(), M);
    }
    void Load(Serializer& serializer, const std::string& prefix) {
        serializer.Load((prefix + "D").c_str(), D);
        serializer.Load((prefix + "M").c_str(), M);
    }
};

/// Dual basis coefficients Φ = Ae·N1 and whether the inversion succeeded (false → Ae = I, standard LM).
template <class T, int TNumNodes>
struct DualBasis {
    Eigen::Matrix<T, TNumNodes, TNumNodes> Ae = Eigen::Matrix<T, TNumNodes, TNumNodes>::Identity();
    bool dual = false;
};

}  // namespace contact_app
