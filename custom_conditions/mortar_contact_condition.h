// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>

#include "automatic_differentiation/dual.h"
#include "contact_app/kernel/exceptions.h"
#include "custom_conditions/nodal_normal_coupling.h"
#include "custom_conditions/pair_nodal_share.h"
#include "custom_conditions/paired_condition.h"
#include "custom_utilities/mortar_operators.h"

namespace contact_app {

/// Formulation families (Kratos FrictionalCase).
enum class FrictionalCase {
    FRICTIONLESS = 0,
    FRICTIONLESS_COMPONENTS = 1,
    FRICTIONAL = 2,
    FRICTIONLESS_PENALTY = 3,
    FRICTIONAL_PENALTY = 4
};

/// Local system size of a family (docs/registered_conditions.md §2).
constexpr int MortarMatrixSize(int dim, int num_slave, FrictionalCase family, int num_master) {
    switch (family) {
        case FrictionalCase::FRICTIONLESS: return dim * (num_slave + num_master) + num_slave;
        case FrictionalCase::FRICTIONLESS_COMPONENTS:
        case FrictionalCase::FRICTIONAL: return dim * (2 * num_slave + num_master);
        default: return dim * (num_slave + num_master);
    }
}

/// Everything a family residual needs from one pair, in the scalar T (double or Dual<MatrixSize>):
/// current coordinates, nodal normals, D and M, and the local unknowns q = [u2, u1, λ] (values).
template <class T, int TDim, int TNumNodes, int TNumNodesMaster, int TMatrixSize>
struct MortarPairState {
    NodeCoordinates<T, TDim, TNumNodes> x1;
    NodeCoordinates<T, TDim, TNumNodesMaster> x2;
    NodeCoordinates<T, TDim, TNumNodes> normals;
    MortarOperators<T, TNumNodes, TNumNodesMaster> operators;
    /// Multiplier block of q (last TMatrixSize − d(n_s + n_m) entries).
    Eigen::Matrix<T, TMatrixSize - TDim * (TNumNodes + TNumNodesMaster), 1> multipliers;
};

/// Common flow of the mortar contact conditions (Kratos MortarContactCondition): isolation, exact
/// segmentation, dual basis Ae, cell and Gauss loops (custom_utilities/mortar_operators.h), then the family
/// residual RHS(q) (the force on the bodies, docs/theory/contact_residuals.md §1). The RHS alone is evaluated in
/// double;
/// the LHS = −∂RHS/∂q is the AD derivative of the same residual over q = [master u, slave u, λ], the normals
/// held constant unless TNormalVariation. When the criteria recompute the normals every iteration (CONSIDER_NORMAL_VARIATION
/// ≠ 0, moving mesh) a non-NV penalty pair differentiates its face-centre NORMAL exactly and records ∂RHS/∂n of the
/// nodal normals for NodalNormalCoupling (nodal_normal_coupling.h). Reads INTEGRATION_ORDER_CONTACT, CONSIDER_TESSELLATION, THICKNESS
/// (axisymmetric) from the Properties and DISTANCE_THRESHOLD, ZERO_TOLERANCE_FACTOR from the ProcessInfo.
/// Not registered itself: DoFs, state encoding and residual come from the families.
template <int TDim, int TNumNodes, FrictionalCase TFrictional, bool TNormalVariation, int TNumNodesMaster = TNumNodes>
class MortarContactCondition : public PairedCondition, public NodalNormalCouplingSource {
public:
    static constexpr int NumCoordinateDofs = TDim * (TNumNodes + TNumNodesMaster);
    static constexpr int MatrixSize = MortarMatrixSize(TDim, TNumNodes, TFrictional, TNumNodesMaster);
    static constexpr int NumMultipliers = MatrixSize - NumCoordinateDofs;
    using ADScalar = Dual<MatrixSize>;
    /// The AD scalar of the normal pass (RecordForcePerNormal): derivatives in the slave nodal normals only.
    using NormalScalar = Dual<TDim * TNumNodes>;
    using MultiplierVector = Eigen::Matrix<double, NumMultipliers, 1>;
    template <class T>
    using State = MortarPairState<T, TDim, TNumNodes, TNumNodesMaster, MatrixSize>;
    template <class T>
    using LocalVector = Eigen::Matrix<T, MatrixSize, 1>;

    using PairedCondition::PairedCondition;

    /// Resets ISOLATED and the nodal share (the search rebuilt the pair).
    void Initialize(const ProcessInfo& rCurrentProcessInfo) override;
    /// @throws InternalError (families implement it)
    void GetDofList(DofsVectorType& rElementalDofList, const ProcessInfo& rCurrentProcessInfo) const override;
    /// Integer state of the slave nodes (family encoding). @throws InternalError in the base
    virtual int GetActiveInactiveValue() const;
    /// @throws InputError: unpaired, or a slave node lacks DISPLACEMENT / WEIGHTED_GAP / NORMAL (historical)
    ///         or the DISPLACEMENT DoFs
    int Check(const ProcessInfo& rCurrentProcessInfo) const override;

    /// Paired-condition state plus the pair's nodal share.
    void Save(Serializer& rSerializer) const override;
    void Load(Serializer& rSerializer) override;

    virtual bool IsAxisymmetric() const { return false; }
    /// False: a family that differentiates the normals the criteria move opts in (PenaltyMortarContactCondition); the ALM
    /// families hold them (docs/theory/mortar.md §7 "Normals that follow the iterate").
    bool CouplesNodalNormals(const ProcessInfo&) const override { return false; }
    bool GetNodalNormalCoupling(int j, Matrix& rForcePerNormal) const override;
    /// What this pair added to the nodal sums at the last explicit pass (pair_nodal_share.h).
    const PairNodalShare<TDim, TNumNodes>& NodalShare() const { return mNodalShare; }
    /// Written by the families' explicit pass (AddExplicitContribution).
    PairNodalShare<TDim, TNumNodes>& MutableNodalShare() { return mNodalShare; }
    /// Mortar integration and segmentation settings from the Properties and the ProcessInfo.
    MortarIntegrationSettings IntegrationSettings() const;
    /// The segmentation settings of this pair's passes (pair_settings::PairSegmentationSettings: the distance rule
    /// decided on the start-of-step configuration, docs/theory/mortar.md §1 "The distance rule").
    SegmentationSettings SegmentationSettingsFrom(const ProcessInfo& rCurrentProcessInfo) const;

protected:
    /// @param[out] pLhs MatrixSize², −∂RHS/∂q (null: the RHS alone, a double evaluation without derivative work)
    /// @param[out] pRhs MatrixSize (null: computed by the tangent pass all the same, then dropped)
    /// @param[in] rCurrentProcessInfo the family's factors (SCALE_FACTOR, TANGENT_FACTOR, ...) and the
    ///            segmentation tolerances (DISTANCE_THRESHOLD, ZERO_TOLERANCE_FACTOR)
    void CalculateConditionSystem(Matrix* pLhs, Vector* pRhs, const ProcessInfo& rCurrentProcessInfo) override;
    /// The multiplier values of the slave nodes (the λ block of q): empty for a family without multipliers,
    /// otherwise @throws InternalError in the base
    virtual MultiplierVector MultiplierValues() const;
    /// Adds the family RHS(q) to @p rhs (zeroed by the caller). @throws InternalError in the base
    virtual void AddResidual(const State<double>& state, const ProcessInfo& rCurrentProcessInfo,
                             LocalVector<double>& rhs) const;
    virtual void AddResidual(const State<ADScalar>& state, const ProcessInfo& rCurrentProcessInfo,
                             LocalVector<ADScalar>& rhs) const;
    /// The residual over the slave nodal normals (the normal pass of a family that CouplesNodalNormals).
    /// @throws InternalError in the base and in a family that does not couple them
    virtual void AddResidual(const State<NormalScalar>& state, const ProcessInfo& rCurrentProcessInfo,
                             LocalVector<NormalScalar>& rhs) const;
    /// Called once per evaluation after the pair is integrated, before AddResidual, with the values of D and M
    /// (non-const: the frictional families choose the objective / non-objective slip here and record it in
    /// MODIFIED). The default does nothing.
    virtual void InitializeResidual(const MortarOperators<double, TNumNodes, TNumNodesMaster>& operators,
                                    const ProcessInfo& rCurrentProcessInfo) {}
    /// Called after the AD pass over the nodal normals (RecordForcePerNormal), before the main one: a family that
    /// records coupling terms in its AD residual marks their normal derivatives as this evaluation's. The default does
    /// nothing.
    virtual void AfterNormalPass() {}

private:
    /// Written by the families' explicit pass, read by their residuals through MakeNodalInterfaceMap.
    PairNodalShare<TDim, TNumNodes> mNodalShare;

    /// ∂RHS/∂n of the slave nodes' normals (MatrixSize × d n_s) of the last tangent evaluation; empty when not recorded.
    Matrix mForcePerNormal;

    /// The second AD pass of a tangent evaluation whose nodal normals follow the iterate: the residual with the normals
    /// seeded (coordinates and multipliers constant; M the only operator that reads them) into mForcePerNormal.
    void RecordForcePerNormal(
        const NodeCoordinates<double, TDim, TNumNodes>& x1, const NodeCoordinates<double, TDim, TNumNodesMaster>& x2,
        const NodeCoordinates<double, TDim, TNumNodes>& normals, const MultiplierVector& lambda,
        const MortarPairIntegration<Dual<NumCoordinateDofs>, TDim, TNumNodes, TNumNodesMaster>& pair,
        const std::vector<MortarGaussPoint<Dual<NumCoordinateDofs>, TDim, TNumNodes, TNumNodesMaster>>& points,
        const ProcessInfo& rCurrentProcessInfo);
    /// The InternalError raised by the methods only the families implement.
    InternalError NotInBase(const char* method) const;
};

/// Explicit instantiations of the contact family of friction policy FrictionalCase::CASE (MortarContactFamilyCondition,
/// mortar_contact_family_condition_impl.h) for every registered pair (CONTACT_APP_FOR_EACH_MORTAR_PAIR) × NV; the
/// family's .cpp ends with it, after its AddFamilyResidual.
#define CONTACT_APP_INSTANTIATE_NV_PAIR_(CASE, D, NS, NM)                                  \
    template class MortarContactFamilyCondition<D, NS, FrictionalCase::CASE, false, NM>; \
    template class MortarContactFamilyCondition<D, NS, FrictionalCase::CASE, true, NM>;
#define CONTACT_APP_INSTANTIATE_CONTACT_FAMILY(CASE) \
    CONTACT_APP_FOR_EACH_MORTAR_PAIR(CONTACT_APP_INSTANTIATE_NV_PAIR_, CASE)
/// Explicit instantiations of the 2D axisymmetric variant of that family (MortarContactAxisymCondition of its 2D2N
/// pair, mortar_contact_axisym_condition.h) × NV.
#define CONTACT_APP_INSTANTIATE_AXISYM_FAMILY(CASE)                                                              \
    template class MortarContactAxisymCondition<MortarContactFamilyCondition<2, 2, FrictionalCase::CASE, false, 2>>; \
    template class MortarContactAxisymCondition<MortarContactFamilyCondition<2, 2, FrictionalCase::CASE, true, 2>>;
/// Explicit instantiations of a family base TBase<TDim, TNumNodes, FrictionalCase, TNormalVariation, TNumNodesMaster>
/// (MortarContactCondition, MortarContactFamilyCondition) for the five contact families × every registered pair × NV.
#define CONTACT_APP_INSTANTIATE_FAMILY_BASE_NV_(TBase, FAMILY, D, NS, NM) \
    template class TBase<D, NS, FrictionalCase::FAMILY, false, NM>;      \
    template class TBase<D, NS, FrictionalCase::FAMILY, true, NM>;
#define CONTACT_APP_INSTANTIATE_FAMILY_BASE_(TBase, D, NS, NM)                            \
    CONTACT_APP_INSTANTIATE_FAMILY_BASE_NV_(TBase, FRICTIONLESS, D, NS, NM)            \
    CONTACT_APP_INSTANTIATE_FAMILY_BASE_NV_(TBase, FRICTIONLESS_COMPONENTS, D, NS, NM) \
    CONTACT_APP_INSTANTIATE_FAMILY_BASE_NV_(TBase, FRICTIONLESS_PENALTY, D, NS, NM)    \
    CONTACT_APP_INSTANTIATE_FAMILY_BASE_NV_(TBase, FRICTIONAL, D, NS, NM)              \
    CONTACT_APP_INSTANTIATE_FAMILY_BASE_NV_(TBase, FRICTIONAL_PENALTY, D, NS, NM)
#define CONTACT_APP_INSTANTIATE_FAMILY_BASE(TBase) \
    CONTACT_APP_FOR_EACH_MORTAR_PAIR(CONTACT_APP_INSTANTIATE_FAMILY_BASE_, TBase)

}  // namespace contact_app
