// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/mortar_contact_condition.h"

#include <type_traits>

#include "automatic_differentiation/ad_helpers.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "custom_conditions/mortar_pair_settings.h"
#include "custom_utilities/mortar_geometry_adapters.h"
#include "custom_utilities/mortar_normals.h"

namespace contact_app {
namespace {

/// Moves ∂/∂(pair coordinates, slave first) into ∂/∂q with q = [master u, slave u, λ].
template <int TMatrixSize, int TSlaveDofs, int TMasterDofs>
Dual<TMatrixSize> ToLocalDofs(const Dual<TSlaveDofs + TMasterDofs>& x) {
    typename Dual<TMatrixSize>::Gradient gradient = Dual<TMatrixSize>::Gradient::Zero();
    gradient.template segment<TSlaveDofs>(TMasterDofs) = x.Derivatives().template head<TSlaveDofs>();
    gradient.template segment<TMasterDofs>(0) = x.Derivatives().template tail<TMasterDofs>();
    return Dual<TMatrixSize>(x.Value(), gradient);
}

template <int TMatrixSize, int TSlaveDofs, int TMasterDofs, int R, int C>
Eigen::Matrix<Dual<TMatrixSize>, R, C> ToLocalDofs(const Eigen::Matrix<Dual<TSlaveDofs + TMasterDofs>, R, C>& m) {
    Eigen::Matrix<Dual<TMatrixSize>, R, C> result;
    for (int r = 0; r < R; ++r)
        for (int c = 0; c < C; ++c) result(r, c) = ToLocalDofs<TMatrixSize, TSlaveDofs, TMasterDofs>(m(r, c));
    return result;
}

/// Same derivatives, value replaced: the NV normals keep the nodal NORMAL the search computed (mean over the
/// adjacent faces) and take the derivative of this face's own normals (docs/theory/mortar.md §5).
template <int N, int R, int C>
Eigen::Matrix<Dual<N>, R, C> WithValues(const Eigen::Matrix<Dual<N>, R, C>& m, const Eigen::Matrix<double, R, C>& v) {
    Eigen::Matrix<Dual<N>, R, C> result;
    for (int r = 0; r < R; ++r)
        for (int c = 0; c < C; ++c) result(r, c) = Dual<N>(v(r, c), m(r, c).Derivatives());
    return result;
}

const Variable<double>* const kDisplacementComponents[] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};

}  // namespace

#define MORTAR_TEMPLATE template <int TDim, int TNS, FrictionalCase TF, bool TNV, int TNM>
#define MORTAR_CLASS MortarContactCondition<TDim, TNS, TF, TNV, TNM>

MORTAR_TEMPLATE
void MORTAR_CLASS::Initialize(const ProcessInfo& rCurrentProcessInfo) {
    PairedCondition::Initialize(rCurrentProcessInfo);
    Set(ISOLATED, false);
    mNodalShare = PairNodalShare<TDim, TNS>{};
}

MORTAR_TEMPLATE
void MORTAR_CLASS::Save(Serializer& rSerializer) const {
    PairedCondition::Save(rSerializer);
    mNodalShare.Save(rSerializer);
}

MORTAR_TEMPLATE
void MORTAR_CLASS::Load(Serializer& rSerializer) {
    PairedCondition::Load(rSerializer);
    mNodalShare.Load(rSerializer);
}

MORTAR_TEMPLATE
InternalError MORTAR_CLASS::NotInBase(const char* method) const {
    return InternalError(detail::Concat("MortarContactCondition::", method, " called on condition ", Id(),
                                        ": the base class has no formulation family (this is a bug in contact_app;",
                                        " please report it with the registered condition name)"));
}

MORTAR_TEMPLATE
void MORTAR_CLASS::GetDofList(DofsVectorType&, const ProcessInfo&) const {
    throw NotInBase("GetDofList");
}

MORTAR_TEMPLATE
int MORTAR_CLASS::GetActiveInactiveValue() const {
    throw NotInBase("GetActiveInactiveValue");
}

MORTAR_TEMPLATE
typename MORTAR_CLASS::MultiplierVector MORTAR_CLASS::MultiplierValues() const {
    if constexpr (NumMultipliers == 0)
        return MultiplierVector();  // displacement-only families (penalty)
    else
        throw NotInBase("MultiplierValues");
}

MORTAR_TEMPLATE
void MORTAR_CLASS::AddResidual(const State<double>&, const ProcessInfo&, LocalVector<double>&) const {
    throw NotInBase("AddResidual");
}

MORTAR_TEMPLATE
void MORTAR_CLASS::AddResidual(const State<ADScalar>&, const ProcessInfo&, LocalVector<ADScalar>&) const {
    throw NotInBase("AddResidual");
}

MORTAR_TEMPLATE
void MORTAR_CLASS::AddResidual(const State<NormalScalar>&, const ProcessInfo&, LocalVector<NormalScalar>&) const {
    throw NotInBase("AddResidual over the nodal normals");
}

MORTAR_TEMPLATE
int MORTAR_CLASS::Check(const ProcessInfo& rCurrentProcessInfo) const {
    PairedCondition::Check(rCurrentProcessInfo);
    const Geometry& slave = GetParentGeometry();
    CONTACT_CHECK(static_cast<int>(slave.size()) == TNS && static_cast<int>(GetPairedGeometry().size()) == TNM,
                  InputError, "condition ", Id(), " pairs a ", slave.size(), "-node slave with a ",
                  GetPairedGeometry().size(), "-node master\n  expected: ", TNS, " and ", TNM,
                  " nodes\n  fix: use the condition name whose suffix matches the two faces");
    for (std::size_t i = 0; i < slave.size(); ++i) {
        const Node& node = slave[i];
        for (const VariableData* variable :
             {static_cast<const VariableData*>(&DISPLACEMENT), static_cast<const VariableData*>(&WEIGHTED_GAP),
              static_cast<const VariableData*>(&NORMAL)})
            CONTACT_CHECK(node.SolutionStepsDataHas(*variable), InputError, "condition ", Id(), ": slave node ",
                          node.Id(), " does not store ", variable->Name(), " as a historical variable",
                          "\n  fix: add it to the model part's solution-step variables (the contact solver does)");
        for (int k = 0; k < TDim; ++k)
            CONTACT_CHECK(node.HasDofFor(*kDisplacementComponents[k]), InputError, "condition ", Id(), ": slave node ",
                          node.Id(), " has no ", kDisplacementComponents[k]->Name(), " DoF",
                          "\n  fix: add the DISPLACEMENT DoFs to the slave nodes");
    }
    return 0;
}

MORTAR_TEMPLATE
MortarIntegrationSettings MORTAR_CLASS::IntegrationSettings() const {
    const auto& properties = pGetProperties();
    MortarIntegrationSettings settings = pair_settings::IntegrationSettingsFrom(properties);
    if (IsAxisymmetric()) {
        const double thickness = properties ? properties->GetValue(THICKNESS) : 0.0;
        CONTACT_CHECK(
            thickness > 0.0, InputError, "axisymmetric contact condition ", Id(),
            " needs a positive THICKNESS in its properties (got ", thickness, ")",
            "\n  fix: set THICKNESS on the pair properties (the thickness the axisymmetric solids divide by)");
        settings.axisymmetric_thickness = thickness;
    }
    return settings;
}

MORTAR_TEMPLATE
SegmentationSettings MORTAR_CLASS::SegmentationSettingsFrom(const ProcessInfo& rCurrentProcessInfo) const {
    return pair_settings::PairSegmentationSettings<TDim, TNS, TNM>(rCurrentProcessInfo, pGetProperties(),
                                                                   GetParentGeometry(), GetPairedGeometry());
}

MORTAR_TEMPLATE
bool MORTAR_CLASS::GetNodalNormalCoupling(int j, Matrix& rForcePerNormal) const {
    if (mForcePerNormal.size() == 0) return false;
    rForcePerNormal = mForcePerNormal.middleCols(j * TDim, TDim);
    return true;
}

MORTAR_TEMPLATE
void MORTAR_CLASS::RecordForcePerNormal(
    const NodeCoordinates<double, TDim, TNS>& x1, const NodeCoordinates<double, TDim, TNM>& x2,
    const NodeCoordinates<double, TDim, TNS>& normals, const MultiplierVector& lambda,
    const MortarPairIntegration<Dual<NumCoordinateDofs>, TDim, TNS, TNM>& pair,
    const std::vector<MortarGaussPoint<Dual<NumCoordinateDofs>, TDim, TNS, TNM>>& points,
    const ProcessInfo& rCurrentProcessInfo) {
    // A Dual over the d n_s normal components alone: the coordinates and multipliers are constants of this pass. Of
    // the pair's operators only M reads the nodal normals (through the projection onto the master): it is projected
    // again from the main pass's Gauss points, whose other values (D, the dual basis, the weights) do not depend on
    // them.
    const auto seeded = Seed<TDim * TNS>(normals, 0);
    Eigen::Matrix<NormalScalar, TNS, TNM> master_operator;
    MasterOperatorOverNormals<TDim, TNS, TNM>(points, pair.dual, x2, seeded, master_operator);
    State<NormalScalar> state;
    state.x1 = x1.template cast<NormalScalar>();
    state.x2 = x2.template cast<NormalScalar>();
    state.normals = seeded;
    state.operators.D = Values(pair.operators.D).template cast<NormalScalar>();
    state.operators.M = master_operator;
    for (int i = 0; i < NumMultipliers; ++i) state.multipliers[i] = NormalScalar(lambda[i]);
    LocalVector<NormalScalar> rhs;
    for (int i = 0; i < MatrixSize; ++i) rhs[i] = NormalScalar(0.0);
    AddResidual(state, rCurrentProcessInfo, rhs);
    mForcePerNormal = Jacobian(rhs);
    AfterNormalPass();
}

MORTAR_TEMPLATE
void MORTAR_CLASS::CalculateConditionSystem(Matrix* pLhs, Vector* pRhs, const ProcessInfo& rCurrentProcessInfo) {
    constexpr int slave_dofs = TDim * TNS, master_dofs = TDim * TNM;
    Vector unused_rhs;  // the tangent pass differentiates the residual, so it has one either way
    if (pRhs == nullptr) pRhs = &unused_rhs;
    if (pLhs) {
        pLhs->setZero(MatrixSize, MatrixSize);
        mForcePerNormal.resize(0, 0);
    }
    pRhs->setZero(MatrixSize);
    if (Is(ISOLATED)) return;

    const Geometry& slave = GetParentGeometry();
    const Geometry& master = GetPairedGeometry();
    bool slave_follows = true, master_follows = true;
    const auto x1 = CurrentCoordinates<TDim, TNS>(slave, &slave_follows);
    const auto x2 = CurrentCoordinates<TDim, TNM>(master, &master_follows);
    const SpatialVector<double, TDim> slave_normal = ToSpatialVector<TDim>(GetValue(NORMAL));
    const auto normals = NodalNormals<TDim, TNS>(slave);
    const MultiplierVector lambda = MultiplierValues();
    const MortarIntegrationSettings integration = IntegrationSettings();
    const SegmentationSettings segmentation = SegmentationSettingsFrom(rCurrentProcessInfo);

    // Moving mesh: D, M and the NV normals follow x = X0 + u (finite sliding). Fixed mesh (move_mesh_flag false): they
    // stay on the mesh coordinates and only the gap and slip see u, the geometrically linear contact.
    const bool finite_sliding = slave_follows && master_follows;
    const auto mesh_x1 = finite_sliding ? x1 : MeshCoordinates<TDim, TNS>(slave);
    const auto mesh_x2 = finite_sliding ? x2 : MeshCoordinates<TDim, TNM>(master);

    if (pLhs == nullptr) {  // residual only, in double
        const MortarIntegrator<TDim, TNS, TNM, double> integrator(integration, segmentation);
        const auto pair = IntegrateMortarPair<TDim, TNS, TNM>(integrator, mesh_x1, slave_normal, mesh_x2, normals, true);
        if (!pair.used) return Set(ISOLATED, true);
        InitializeResidual(pair.operators, rCurrentProcessInfo);
        const State<double> state{x1, x2, normals, pair.operators, lambda};
        LocalVector<double> rhs = LocalVector<double>::Zero();
        AddResidual(state, rCurrentProcessInfo, rhs);
        *pRhs = rhs;
        return;
    }

    // Residual and tangent: the pair operators in Dual<d(n_s+n_m)> (coordinates, slave first), then moved to
    // Dual<MatrixSize> over q = [u2, u1, λ].
    using Coordinate = Dual<NumCoordinateDofs>;
    const auto seeded_x1 = Seed<NumCoordinateDofs>(x1, 0);
    const auto seeded_x2 = Seed<NumCoordinateDofs>(x2, slave_dofs);
    State<ADScalar> state;
    if (!finite_sliding) {  // constant operators and normals
        const MortarIntegrator<TDim, TNS, TNM, double> integrator(integration, segmentation);
        const auto pair = IntegrateMortarPair<TDim, TNS, TNM>(integrator, mesh_x1, slave_normal, mesh_x2, normals, true);
        if (!pair.used) return Set(ISOLATED, true);
        state.normals = normals.template cast<ADScalar>();
        state.operators.D = pair.operators.D.template cast<ADScalar>();
        state.operators.M = pair.operators.M.template cast<ADScalar>();
        state.x1 = ToLocalDofs<MatrixSize, slave_dofs, master_dofs>(seeded_x1);
        state.x2 = ToLocalDofs<MatrixSize, slave_dofs, master_dofs>(seeded_x2);
        for (int i = 0; i < NumMultipliers; ++i)
            state.multipliers[i] = ADScalar::Variable(lambda[i], NumCoordinateDofs + i);
        InitializeResidual(pair.operators, rCurrentProcessInfo);
        LocalVector<ADScalar> rhs;
        for (int i = 0; i < MatrixSize; ++i) rhs[i] = ADScalar(0.0);
        AddResidual(state, rCurrentProcessInfo, rhs);
        *pRhs = Values(rhs);
        *pLhs = -Jacobian(rhs);
        return;
    }
    const MortarIntegrator<TDim, TNS, TNM, Coordinate> integrator(integration, segmentation);
    MortarPairIntegration<Coordinate, TDim, TNS, TNM> pair;
    std::vector<MortarGaussPoint<Coordinate, TDim, TNS, TNM>> points;  // kept for the normal pass
    // Normals that follow the iterate, once the sets settled: the face-centre NORMAL is this face's own (differentiated
    // here), the nodal ones are held here and their derivative recorded for NodalNormalCoupling. A penalty pair (the
    // only kind that couples them) without an active slave node adds nothing, so it has nothing to record.
    bool any_active = false;
    for (std::size_t j = 0; j < slave.size(); ++j) any_active = any_active || slave[j].Is(ACTIVE);
    const bool normals_follow =
        CouplesNodalNormals(rCurrentProcessInfo) && NormalsInTangent(rCurrentProcessInfo) && any_active;
    if constexpr (TNV) {
        const auto nodal = WithValues(FaceNodalUnitNormals<TDim, TNS, Coordinate>(seeded_x1), normals);
        const SpatialVector<Coordinate, TDim> center =
            WithValues(FaceCenterUnitNormal<TDim, TNS, Coordinate>(seeded_x1), slave_normal);
        pair = IntegrateMortarPair<TDim, TNS, TNM>(integrator, seeded_x1, center, seeded_x2, nodal, true);
        state.normals = ToLocalDofs<MatrixSize, slave_dofs, master_dofs>(nodal);
    } else if (normals_follow) {
        const SpatialVector<Coordinate, TDim> center =
            WithValues(FaceCenterUnitNormal<TDim, TNS, Coordinate>(seeded_x1), slave_normal);
        const NodeCoordinates<Coordinate, TDim, TNS> held = normals.template cast<Coordinate>();
        pair = IntegrateMortarPair<TDim, TNS, TNM>(integrator, seeded_x1, center, seeded_x2, held, true, &points);
        state.normals = normals.template cast<ADScalar>();
    } else {
        pair = IntegrateMortarPair<TDim, TNS, TNM>(integrator, seeded_x1, slave_normal, seeded_x2, normals, true);
        state.normals = normals.template cast<ADScalar>();
    }
    if (!pair.used) return Set(ISOLATED, true);
    state.x1 = ToLocalDofs<MatrixSize, slave_dofs, master_dofs>(seeded_x1);
    state.x2 = ToLocalDofs<MatrixSize, slave_dofs, master_dofs>(seeded_x2);
    state.operators.D = ToLocalDofs<MatrixSize, slave_dofs, master_dofs>(pair.operators.D);
    state.operators.M = ToLocalDofs<MatrixSize, slave_dofs, master_dofs>(pair.operators.M);
    for (int i = 0; i < NumMultipliers; ++i)
        state.multipliers[i] = ADScalar::Variable(lambda[i], NumCoordinateDofs + i);
    MortarOperators<double, TNS, TNM> operator_values;
    operator_values.D = Values(pair.operators.D);
    operator_values.M = Values(pair.operators.M);
    InitializeResidual(operator_values, rCurrentProcessInfo);
    // Before the main pass: a family that records coupling terms in its AD residual keeps the main pass's.
    if (normals_follow) RecordForcePerNormal(x1, x2, normals, lambda, pair, points, rCurrentProcessInfo);
    LocalVector<ADScalar> rhs;
    for (int i = 0; i < MatrixSize; ++i) rhs[i] = ADScalar(0.0);
    AddResidual(state, rCurrentProcessInfo, rhs);
    *pRhs = Values(rhs);
    *pLhs = -Jacobian(rhs);
}

#undef MORTAR_TEMPLATE
#undef MORTAR_CLASS

// -- Explicit instantiations: the registered pairs of the five families, with and without NV --
CONTACT_APP_INSTANTIATE_FAMILY_BASE(MortarContactCondition)

}  // namespace contact_app
