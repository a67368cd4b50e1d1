// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/mesh_tying_mortar_condition.h"

#include <utility>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/serializer.h"
#include "contact_app/kernel/variable_registry.h"
#include "custom_conditions/mortar_pair_settings.h"
#include "custom_utilities/mortar_geometry_adapters.h"
#include "custom_utilities/mortar_normals.h"
#include "custom_utilities/mortar_operators.h"

namespace contact_app {
namespace {

const Variable<double>* const kVectorMultipliers[] = {&VECTOR_LAGRANGE_MULTIPLIER_X, &VECTOR_LAGRANGE_MULTIPLIER_Y,
                                                      &VECTOR_LAGRANGE_MULTIPLIER_Z};

/// Slave normals for the segmentation: the condition NORMAL and the historical nodal NORMAL when the search
/// set them (non-zero), otherwise the face's own normals (a tied temperature interface has no NORMAL).
template <int TDim, int TNS>
void PairNormals(const Condition& condition, const Geometry& slave, const NodeCoordinates<double, TDim, TNS>& x1,
                 SpatialVector<double, TDim>& center, NodeCoordinates<double, TDim, TNS>& nodal) {
    center = condition.Has(NORMAL) ? ToSpatialVector<TDim>(condition.GetValue(NORMAL))
                                   : SpatialVector<double, TDim>::Zero();
    if (center.norm() < 0.5) center = FaceCenterUnitNormal<TDim, TNS, double>(x1);
    const NodeCoordinates<double, TDim, TNS> own = FaceNodalUnitNormals<TDim, TNS, double>(x1);
    for (int i = 0; i < TNS; ++i) {
        const Node& node = slave[i];
        const bool stored = node.SolutionStepsDataHas(NORMAL) &&
                            node.FastGetSolutionStepValue(NORMAL).head<TDim>().norm() > 0.5;
        if (stored) nodal.row(i) = node.FastGetSolutionStepValue(NORMAL).head<TDim>().transpose();
        else nodal.row(i) = own.row(i);
    }
}

}  // namespace

#define TYING_TEMPLATE template <int TDim, int TNS, int TNM>
#define TYING_CLASS MeshTyingMortarCondition<TDim, TNS, TNM>

TYING_TEMPLATE
Condition::Pointer TYING_CLASS::Create(IndexType new_id, Geometry::Pointer slave, Properties::Pointer properties,
                                       Geometry::Pointer master) const {
    return std::make_shared<TYING_CLASS>(new_id, std::move(slave), std::move(properties), std::move(master));
}

TYING_TEMPLATE
typename TYING_CLASS::TyingVariables TYING_CLASS::ResolveTyingVariables() const {
    const auto& properties = pGetProperties();
    const std::string name = properties && properties->Has(TYING_VARIABLE) ? properties->GetValue(TYING_VARIABLE)
                                                                           : std::string("DISPLACEMENT");
    const VariableRegistry& registry = VariableRegistry::Instance();
    const VariableData& data = registry.Get(name);  // unknown name: InputError with the closest names
    TyingVariables result;
    result.variable = &data;
    if (data.Type() == VariableType::Double || data.Type() == VariableType::Component) {
        result.dofs = {&registry.GetTyped<double>(name)};
        result.multipliers = {&SCALAR_LAGRANGE_MULTIPLIER};
        result.multiplier = &SCALAR_LAGRANGE_MULTIPLIER;
    } else if (data.Type() == VariableType::Array) {
        const char* suffix[] = {"_X", "_Y", "_Z"};
        for (int c = 0; c < TDim; ++c) {
            result.dofs.push_back(&registry.GetTyped<double>(name + suffix[c]));
            result.multipliers.push_back(kVectorMultipliers[c]);
        }
        result.multiplier = &VECTOR_LAGRANGE_MULTIPLIER;
    } else {
        CONTACT_THROW(InputError, "MeshTyingMortarCondition ", Id(), ": TYING_VARIABLE ", name, " is of type ",
                      VariableTypeName(data.Type()),
                      "\n  expected: Compatible variables are: double or array_1d<double, 3>",
                      "\n  fix: set TYING_VARIABLE on the pair properties to a double variable (e.g. TEMPERATURE)",
                      " or a 3-vector variable (e.g. DISPLACEMENT)");
    }
    return result;
}

TYING_TEMPLATE
const std::vector<const Variable<double>*>& TYING_CLASS::TiedVariables() const {
    if (mTying.dofs.empty()) mTying = ResolveTyingVariables();
    return mTying.dofs;
}

TYING_TEMPLATE
void TYING_CLASS::Initialize(const ProcessInfo& rCurrentProcessInfo) {
    if (std::exchange(mRestored, false)) {
        // Restarted: integrating again would use the deformed coordinates; the operators of the tied interface
        // are those of the undeformed pair, as loaded.
        mTying = ResolveTyingVariables();
        return;
    }
    PairedCondition::Initialize(rCurrentProcessInfo);
    mTying = ResolveTyingVariables();
    mOperators.Initialize();
    mDual = false;
    mInitialized = true;

    const Geometry& slave = GetParentGeometry();
    const auto x1 = CurrentCoordinates<TDim, TNS>(slave);
    const auto x2 = CurrentCoordinates<TDim, TNM>(GetPairedGeometry());
    SpatialVector<double, TDim> center;
    NodeCoordinates<double, TDim, TNS> normals;
    PairNormals<TDim, TNS>(*this, slave, x1, center, normals);
    const MortarIntegrator<TDim, TNS, TNM, double> integrator(
        pair_settings::IntegrationSettingsFrom(pGetProperties()),
        pair_settings::PairSegmentationSettings<TDim, TNS, TNM>(rCurrentProcessInfo, pGetProperties(),
                                                                GetParentGeometry(), GetPairedGeometry()));
    const auto pair = IntegrateMortarPair<TDim, TNS, TNM>(integrator, x1, center, x2, normals, true);
    // B5: a dimensionless overlap ratio instead of the reference's area / area² test.
    if (!pair.used || pair.area <= MinimumOverlapRatio * slave.DomainSize()) return Set(ACTIVE, false);
    mOperators = pair.operators;
    mDual = pair.dual.dual;
}

TYING_TEMPLATE
void TYING_CLASS::CalculateConditionSystem(Matrix* pLhs, Vector* pRhs, const ProcessInfo& rCurrentProcessInfo) {
    const auto& tied = TiedVariables();
    const int n = static_cast<int>(tied.size());
    const int size = LocalSize();
    if (pLhs) pLhs->setZero(size, size);
    if (pRhs) pRhs->setZero(size);
    if (!mInitialized || (IsDefined(ACTIVE) && IsNot(ACTIVE))) return;

    const double k = rCurrentProcessInfo.Has(SCALE_FACTOR)         ? rCurrentProcessInfo.GetValue(SCALE_FACTOR)
                     : rCurrentProcessInfo.Has(BUILD_SCALE_FACTOR) ? rCurrentProcessInfo.GetValue(BUILD_SCALE_FACTOR)
                                                                   : 1.0;
    const auto& D = mOperators.D;
    const auto& M = mOperators.M;
    const int slave_offset = n * TNM, lm_offset = n * (TNM + TNS);
    auto master_index = [&](int l, int c) { return l * n + c; };
    auto slave_index = [&](int a, int c) { return slave_offset + a * n + c; };
    auto lm_index = [&](int j, int c) { return lm_offset + j * n + c; };

    if (pLhs) {
        Matrix& K = *pLhs;
        for (int c = 0; c < n; ++c)
            for (int j = 0; j < TNS; ++j) {
                for (int l = 0; l < TNM; ++l) {
                    K(lm_index(j, c), master_index(l, c)) = -k * M(j, l);
                    K(master_index(l, c), lm_index(j, c)) = -k * M(j, l);
                }
                for (int a = 0; a < TNS; ++a) {
                    K(lm_index(j, c), slave_index(a, c)) = k * D(j, a);
                    K(slave_index(a, c), lm_index(j, c)) = k * D(j, a);
                }
            }
    }
    if (pRhs) {
        const Geometry& slave = GetParentGeometry();
        const Geometry& master = GetPairedGeometry();
        const auto& multipliers = mTying.multipliers;
        Eigen::MatrixXd u1(TNS, n), u2(TNM, n), lambda(TNS, n);
        for (int c = 0; c < n; ++c) {
            for (int a = 0; a < TNS; ++a) {
                u1(a, c) = slave[a].FastGetSolutionStepValue(*tied[c]);
                lambda(a, c) = slave[a].FastGetSolutionStepValue(*multipliers[c]);
            }
            for (int l = 0; l < TNM; ++l) u2(l, c) = master[l].FastGetSolutionStepValue(*tied[c]);
        }
        const Eigen::MatrixXd master_force = k * M.transpose() * lambda;  // n_m × n
        const Eigen::MatrixXd slave_force = -k * D.transpose() * lambda;  // n_s × n
        const Eigen::MatrixXd constraint = -k * (D * u1 - M * u2);        // n_s × n
        Vector& r = *pRhs;
        for (int c = 0; c < n; ++c) {
            for (int l = 0; l < TNM; ++l) r[master_index(l, c)] = master_force(l, c);
            for (int a = 0; a < TNS; ++a) {
                r[slave_index(a, c)] = slave_force(a, c);
                r[lm_index(a, c)] = constraint(a, c);
            }
        }
    }
}

TYING_TEMPLATE
void TYING_CLASS::GetDofList(DofsVectorType& rElementalDofList, const ProcessInfo&) const {
    const auto& tied = TiedVariables();
    const Geometry& slave = GetParentGeometry();
    const Geometry& master = GetPairedGeometry();
    rElementalDofList.clear();
    rElementalDofList.reserve(LocalSize());
    for (int l = 0; l < TNM; ++l)
        for (const auto* variable : tied) rElementalDofList.push_back(&master[l].GetDof(*variable));
    for (int a = 0; a < TNS; ++a)
        for (const auto* variable : tied) rElementalDofList.push_back(&slave[a].GetDof(*variable));
    for (int j = 0; j < TNS; ++j)
        for (const auto* variable : mTying.multipliers) rElementalDofList.push_back(&slave[j].GetDof(*variable));
}

TYING_TEMPLATE
int TYING_CLASS::Check(const ProcessInfo& rCurrentProcessInfo) const {
    PairedCondition::Check(rCurrentProcessInfo);  // unpaired: YOU HAVE NOT INITIALIZED THE PAIR GEOMETRY
    CheckNodeCounts("MeshTyingMortarCondition", TNS, TNM);
    const Geometry& slave = GetParentGeometry();
    const Geometry& master = GetPairedGeometry();
    const TyingVariables tying = ResolveTyingVariables();
    auto check_node = [&](const Node& node, const char* side, const VariableData& variable,
                          const std::vector<const Variable<double>*>& components) {
        CONTACT_CHECK(node.SolutionStepsDataHas(variable), InputError, "MeshTyingMortarCondition ", Id(), ": ", side,
                      " node ", node.Id(), " does not store ", variable.Name(), " as a historical variable",
                      "\n  fix: add ", variable.Name(), " to the model part's solution-step variables");
        for (const auto* component : components)
            CONTACT_CHECK(node.HasDofFor(*component), InputError, "MeshTyingMortarCondition ", Id(), ": ", side,
                          " node ", node.Id(), " has no ", component->Name(), " DoF",
                          "\n  fix: add the ", component->Name(), " DoF to the ", side, " nodes");
    };
    for (std::size_t l = 0; l < master.size(); ++l) check_node(master[l], "master", *tying.variable, tying.dofs);
    for (std::size_t j = 0; j < slave.size(); ++j) {
        check_node(slave[j], "slave", *tying.variable, tying.dofs);
        check_node(slave[j], "slave", *tying.multiplier, tying.multipliers);
    }
    return 0;
}

TYING_TEMPLATE
void TYING_CLASS::Save(Serializer& rSerializer) const {
    PairedCondition::Save(rSerializer);
    mOperators.Save(rSerializer, "MortarOperators");
    rSerializer.Save("DualBasis", mDual);
    rSerializer.Save("Initialized", mInitialized);
}

TYING_TEMPLATE
void TYING_CLASS::Load(Serializer& rSerializer) {
    PairedCondition::Load(rSerializer);
    mOperators.Load(rSerializer, "MortarOperators");
    rSerializer.Load("DualBasis", mDual);
    rSerializer.Load("Initialized", mInitialized);
    mRestored = mInitialized;  // a pair saved before its Initialize still needs it
}

TYING_TEMPLATE
std::string TYING_CLASS::Info() const {
    return PairInfo("MeshTyingMortarCondition");
}

#undef TYING_TEMPLATE
#undef TYING_CLASS

CONTACT_APP_INSTANTIATE_FOR_EACH_MORTAR_PAIR(MeshTyingMortarCondition)

}  // namespace contact_app
