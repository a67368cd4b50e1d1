// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/alm_frictionless_mortar_contact_condition.h"

#include "contact_app/application.h"
#include "contact_app/kernel/exceptions.h"
#include "custom_utilities/mortar_explicit_contribution.h"
#include "custom_utilities/mortar_geometry_adapters.h"

namespace contact_app {
namespace {

const Variable<double>* const kDisplacementComponents[] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};

/// Per-node constants of the residual (held constant by the tangent).
template <int TNumNodes>
struct NodalParameters {
    Eigen::Matrix<double, TNumNodes, 1> penalty, dynamic_factor;
    std::array<bool, TNumNodes> active{};
    double scale_factor = 0.0;
};

template <int TNumNodes>
NodalParameters<TNumNodes> ReadParameters(const Geometry& slave, const ProcessInfo& process_info, IndexType id) {
    NodalParameters<TNumNodes> p;
    CONTACT_CHECK(process_info.Has(SCALE_FACTOR), InputError, "ALM contact condition ", id,
                  ": SCALE_FACTOR is not set in the ProcessInfo\n  fix: run the ALM initialisation (ALMFastInit)",
                  " or set ProcessInfo[SCALE_FACTOR]");
    p.scale_factor = process_info.GetValue(SCALE_FACTOR);
    for (int j = 0; j < TNumNodes; ++j) {
        const Node& node = slave[j];
        p.active[j] = node.Is(ACTIVE);
        p.penalty[j] = node.GetValue(INITIAL_PENALTY);
        p.dynamic_factor[j] = node.Has(DYNAMIC_FACTOR) ? node.GetValue(DYNAMIC_FACTOR) : 1.0;
        CONTACT_CHECK(p.active[j] || p.penalty[j] > 0.0, InputError, "ALM contact condition ", id, ": slave node ",
                      node.Id(), " has INITIAL_PENALTY ", p.penalty[j], "\n  expected: a positive nodal penalty",
                      "\n  fix: run the ALM initialisation (ALMFastInit) before assembling");
    }
    return p;
}

/// RHS of kratos_residuals.md §3.1 for one pair, q = [u2 (d·n_m), u1 (d·n_s), λ (n_s)].
template <class T, int TDim, int TNS, int TNM, class TState, class TVector>
void AddFrictionlessResidual(const TState& s, const NodalParameters<TNS>& p, TVector& rhs) {
    constexpr int slave_offset = TDim * TNM, lambda_offset = TDim * (TNS + TNM);
    const double k = p.scale_factor;
    for (int j = 0; j < TNS; ++j) {
        const double eps = p.penalty[j];
        if (!p.active[j]) {
            rhs[lambda_offset + j] += -(k * k / eps) * s.multipliers[j];
            continue;
        }
        Eigen::Matrix<T, 1, TDim> r = s.operators.D.row(j) * s.x1 - s.operators.M.row(j) * s.x2;
        const T gap = -r.dot(s.normals.row(j));
        const T force = p.dynamic_factor[j] * (k * s.multipliers[j] + eps * gap);
        for (int c = 0; c < TDim; ++c) {
            const T f = force * s.normals(j, c);
            for (int a = 0; a < TNS; ++a) rhs[slave_offset + a * TDim + c] += s.operators.D(j, a) * f;
            for (int l = 0; l < TNM; ++l) rhs[l * TDim + c] -= s.operators.M(j, l) * f;
        }
        rhs[lambda_offset + j] += k * gap;
    }
}

}  // namespace

#define ALM_TEMPLATE template <int TDim, int TNS, bool TNV, int TNM>
#define ALM_CLASS AugmentedLagrangianMethodFrictionlessMortarContactCondition<TDim, TNS, TNV, TNM>

ALM_TEMPLATE
Condition::Pointer ALM_CLASS::Create(IndexType new_id, Geometry::Pointer slave, Properties::Pointer properties,
                                     Geometry::Pointer master) const {
    return std::make_shared<ALM_CLASS>(new_id, std::move(slave), std::move(properties), std::move(master));
}

ALM_TEMPLATE
void ALM_CLASS::EquationIdVector(EquationIdVectorType& rResult, const ProcessInfo& rCurrentProcessInfo) const {
    DofsVectorType dofs;
    GetDofList(dofs, rCurrentProcessInfo);
    rResult.resize(dofs.size());
    for (std::size_t i = 0; i < dofs.size(); ++i) rResult[i] = dofs[i]->EquationId();
}

ALM_TEMPLATE
void ALM_CLASS::GetDofList(DofsVectorType& rElementalDofList, const ProcessInfo&) const {
    const Geometry& slave = this->GetParentGeometry();
    const Geometry& master = this->GetPairedGeometry();
    rElementalDofList.clear();
    rElementalDofList.reserve(BaseType::MatrixSize);
    for (int l = 0; l < TNM; ++l)
        for (int c = 0; c < TDim; ++c) rElementalDofList.push_back(&master[l].GetDof(*kDisplacementComponents[c]));
    for (int j = 0; j < TNS; ++j)
        for (int c = 0; c < TDim; ++c) rElementalDofList.push_back(&slave[j].GetDof(*kDisplacementComponents[c]));
    for (int j = 0; j < TNS; ++j) rElementalDofList.push_back(&slave[j].GetDof(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE));
}

ALM_TEMPLATE
int ALM_CLASS::GetActiveInactiveValue() const {
    const Geometry& slave = this->GetParentGeometry();
    int value = 0;
    for (int j = 0; j < TNS; ++j)
        if (slave[j].Is(ACTIVE)) value += 1 << j;
    return value;
}

ALM_TEMPLATE
void ALM_CLASS::AddExplicitContribution(const ProcessInfo& rCurrentProcessInfo) {
    Geometry& slave = *this->pGetParentGeometry();
    const MortarIntegrator<TDim, TNS, TNM, double> integrator(this->IntegrationSettings(),
                                                              this->SegmentationSettingsFrom(rCurrentProcessInfo));
    const auto result = ComputeExplicitMortarContribution<TDim, TNS, TNM, double, double>(
        integrator, CurrentCoordinates<TDim, TNS>(slave), ToSpatialVector<TDim>(this->GetValue(NORMAL)),
        CurrentCoordinates<TDim, TNM>(this->GetPairedGeometry()), NodalNormals<TDim, TNS>(slave),
        ExplicitContributionOptions{});
    if (result.isolated) return this->Set(ISOLATED, true);
    for (int j = 0; j < TNS; ++j) slave[j].FastGetSolutionStepValue(WEIGHTED_GAP) += result.weighted_gap[j];
}

ALM_TEMPLATE
int ALM_CLASS::Check(const ProcessInfo& rCurrentProcessInfo) const {
    BaseType::Check(rCurrentProcessInfo);
    const Geometry& slave = this->GetParentGeometry();
    for (int j = 0; j < TNS; ++j)
        CONTACT_CHECK(slave[j].SolutionStepsDataHas(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) &&
                          slave[j].HasDofFor(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE),
                      InputError, "condition ", this->Id(), ": slave node ", slave[j].Id(),
                      " lacks LAGRANGE_MULTIPLIER_CONTACT_PRESSURE (historical variable and DoF)",
                      "\n  fix: use mortar_type \"ALMContactFrictionless\" so the solver adds them");
    return 0;
}

ALM_TEMPLATE
typename ALM_CLASS::BaseType::MultiplierVector ALM_CLASS::MultiplierValues() const {
    const Geometry& slave = this->GetParentGeometry();
    typename BaseType::MultiplierVector lambda;
    for (int j = 0; j < TNS; ++j) lambda[j] = slave[j].FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE);
    return lambda;
}

ALM_TEMPLATE
void ALM_CLASS::AddResidual(const State<double>& state, const ProcessInfo& rCurrentProcessInfo,
                            LocalVector<double>& rhs) const {
    const auto p = ReadParameters<TNS>(this->GetParentGeometry(), rCurrentProcessInfo, this->Id());
    AddFrictionlessResidual<double, TDim, TNS, TNM>(state, p, rhs);
}

ALM_TEMPLATE
void ALM_CLASS::AddResidual(const State<ADScalar>& state, const ProcessInfo& rCurrentProcessInfo,
                            LocalVector<ADScalar>& rhs) const {
    const auto p = ReadParameters<TNS>(this->GetParentGeometry(), rCurrentProcessInfo, this->Id());
    AddFrictionlessResidual<ADScalar, TDim, TNS, TNM>(state, p, rhs);
}

template <int TNS, bool TNV>
Condition::Pointer AugmentedLagrangianMethodFrictionlessMortarContactAxisymCondition<TNS, TNV>::Create(
    IndexType new_id, Geometry::Pointer slave, Properties::Pointer properties, Geometry::Pointer master) const {
    return std::make_shared<AugmentedLagrangianMethodFrictionlessMortarContactAxisymCondition<TNS, TNV>>(
        new_id, std::move(slave), std::move(properties), std::move(master));
}

#undef ALM_TEMPLATE
#undef ALM_CLASS

template class AugmentedLagrangianMethodFrictionlessMortarContactCondition<2, 2, false, 2>;
template class AugmentedLagrangianMethodFrictionlessMortarContactCondition<2, 2, true, 2>;
template class AugmentedLagrangianMethodFrictionlessMortarContactCondition<3, 3, false, 3>;
template class AugmentedLagrangianMethodFrictionlessMortarContactCondition<3, 3, true, 3>;
template class AugmentedLagrangianMethodFrictionlessMortarContactCondition<3, 4, false, 4>;
template class AugmentedLagrangianMethodFrictionlessMortarContactCondition<3, 4, true, 4>;
template class AugmentedLagrangianMethodFrictionlessMortarContactCondition<3, 3, false, 4>;
template class AugmentedLagrangianMethodFrictionlessMortarContactCondition<3, 3, true, 4>;
template class AugmentedLagrangianMethodFrictionlessMortarContactCondition<3, 4, false, 3>;
template class AugmentedLagrangianMethodFrictionlessMortarContactCondition<3, 4, true, 3>;
template class AugmentedLagrangianMethodFrictionlessMortarContactAxisymCondition<2, false>;
template class AugmentedLagrangianMethodFrictionlessMortarContactAxisymCondition<2, true>;

}  // namespace contact_app
