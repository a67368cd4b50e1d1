// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/mortar_contact_family_condition.h"

namespace contact_app {

using namespace frictional_detail;

#define FAMILY_TEMPLATE template <int TDim, int TNS, FrictionalCase TF, bool TNV, int TNM>
#define FAMILY_CLASS MortarContactFamilyCondition<TDim, TNS, TF, TNV, TNM>

FAMILY_TEMPLATE
void FAMILY_CLASS::Initialize(const ProcessInfo& rCurrentProcessInfo) {
    BaseType::Initialize(rCurrentProcessInfo);
    if constexpr (IsFrictional) mPreviousMortarOperators.Reset();
}

FAMILY_TEMPLATE
void FAMILY_CLASS::InitializeSolutionStep(const ProcessInfo& rCurrentProcessInfo) {
    BaseType::InitializeSolutionStep(rCurrentProcessInfo);
    if constexpr (IsFrictional)
        ComputePreviousOperatorsOnce<TDim, TNS, TNM>(*this, rCurrentProcessInfo, mPreviousMortarOperators);
}

FAMILY_TEMPLATE
void FAMILY_CLASS::FinalizeSolutionStep(const ProcessInfo& rCurrentProcessInfo) {
    BaseType::FinalizeSolutionStep(rCurrentProcessInfo);
    if constexpr (IsFrictional) mPreviousMortarOperators.initialized = false;
}

FAMILY_TEMPLATE
int FAMILY_CLASS::GetActiveInactiveValue() const {
    if constexpr (IsFrictional)
        return FrictionalStateValue<TNS>(this->GetParentGeometry());
    else
        return ActiveNodesValue<TNS>(this->GetParentGeometry());
}

FAMILY_TEMPLATE
void FAMILY_CLASS::AddExplicitContribution(const ProcessInfo& rCurrentProcessInfo) {
    if constexpr (IsFrictional)
        AddFrictionalExplicitContribution<TDim, TNS, TNM>(*this, rCurrentProcessInfo, mPreviousMortarOperators);
    else
        AddFrictionlessExplicitContribution<TDim, TNS, TNM>(*this, rCurrentProcessInfo);
}

FAMILY_TEMPLATE
int FAMILY_CLASS::Check(const ProcessInfo& rCurrentProcessInfo) const {
    BaseType::Check(rCurrentProcessInfo);
    const Geometry& slave = this->GetParentGeometry();
    if constexpr (TF == FrictionalCase::FRICTIONLESS)
        for (int j = 0; j < TNS; ++j)
            CONTACT_CHECK(slave[j].SolutionStepsDataHas(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) &&
                              slave[j].HasDofFor(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE),
                          InputError, "condition ", this->Id(), ": slave node ", slave[j].Id(),
                          " lacks LAGRANGE_MULTIPLIER_CONTACT_PRESSURE (historical variable and DoF)",
                          "\n  fix: use mortar_type \"ALMContactFrictionless\" so the solver adds them");
    if constexpr (TF == FrictionalCase::FRICTIONLESS_COMPONENTS)
        CheckVectorMultiplier<TDim, TNS>(slave, this->Id(), "ALMContactFrictionlessComponents");
    if constexpr (TF == FrictionalCase::FRICTIONAL)
        CheckVectorMultiplier<TDim, TNS>(slave, this->Id(), "ALMContactFrictional");
    if constexpr (IsFrictional) CheckFrictionalVariables<TDim, TNS>(slave, this->Id());
    return 0;
}

FAMILY_TEMPLATE
void FAMILY_CLASS::GetDofList(DofsVectorType& rElementalDofList, const ProcessInfo&) const {
    const Geometry& slave = this->GetParentGeometry();
    rElementalDofList.clear();
    rElementalDofList.reserve(BaseType::MatrixSize);
    AppendDisplacementDofs<TDim, TNS, TNM>(slave, this->GetPairedGeometry(), rElementalDofList);
    if constexpr (HasVectorMultiplier) AppendVectorMultiplierDofs<TDim, TNS>(slave, rElementalDofList);
    if constexpr (TF == FrictionalCase::FRICTIONLESS)
        for (int j = 0; j < TNS; ++j)
            rElementalDofList.push_back(&slave[j].GetDof(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE));
}

FAMILY_TEMPLATE
typename FAMILY_CLASS::BaseType::MultiplierVector FAMILY_CLASS::MultiplierValues() const {
    const Geometry& slave = this->GetParentGeometry();
    if constexpr (HasVectorMultiplier) {
        return VectorMultiplierValues<TDim, TNS, typename BaseType::MultiplierVector>(slave);
    } else if constexpr (TF == FrictionalCase::FRICTIONLESS) {
        typename BaseType::MultiplierVector lambda;
        for (int j = 0; j < TNS; ++j)
            lambda[j] = slave[j].FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE);
        return lambda;
    } else {
        return BaseType::MultiplierValues();  // penalty: no multipliers
    }
}

FAMILY_TEMPLATE
void FAMILY_CLASS::Save(Serializer& rSerializer) const {
    BaseType::Save(rSerializer);
    if constexpr (IsFrictional) mPreviousMortarOperators.Save(rSerializer);
}

FAMILY_TEMPLATE
void FAMILY_CLASS::Load(Serializer& rSerializer) {
    BaseType::Load(rSerializer);
    if constexpr (IsFrictional) mPreviousMortarOperators.Load(rSerializer);
}

FAMILY_TEMPLATE
void FAMILY_CLASS::InitializeResidual(const MortarOperators<double, TNS, TNM>& operators,
                                      const ProcessInfo& rCurrentProcessInfo) {
    if constexpr (IsFrictional)
        this->Set(MODIFIED, !IsObjective(operators, mPreviousMortarOperators, rCurrentProcessInfo));
}

FAMILY_TEMPLATE
SlipData<TDim, TNS, TNM> FAMILY_CLASS::SlipOfStep(bool needs_slip) const {
    if constexpr (IsFrictional)
        return MakeSlipData<TDim, TNS, TNM>(*this, mPreviousMortarOperators, needs_slip);
    else
        return SlipData<TDim, TNS, TNM>{};  // a frictionless family measures no slip
}

#undef FAMILY_TEMPLATE
#undef FAMILY_CLASS

// -- Explicit instantiations: the registered pairs of the five families, with and without NV --
CONTACT_APP_INSTANTIATE_FAMILY_BASE(MortarContactFamilyCondition)

}  // namespace contact_app
