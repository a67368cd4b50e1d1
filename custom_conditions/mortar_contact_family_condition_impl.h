// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// The member definitions of MortarContactFamilyCondition. Only the families' .cpp files include this: each defines
/// its AddFamilyResidual overload, then instantiates the class for its friction policy
/// (CONTACT_APP_INSTANTIATE_CONTACT_FAMILY), so AddResidual finds that overload (argument-dependent lookup at the
/// point of instantiation) and every other translation unit sees declarations only.
#include <memory>
#include <utility>

#include "custom_conditions/mortar_contact_family_condition.h"

namespace contact_app {

#define FAMILY_TEMPLATE template <int TDim, int TNS, FrictionalCase TF, bool TNV, int TNM>
#define FAMILY_CLASS MortarContactFamilyCondition<TDim, TNS, TF, TNV, TNM>

FAMILY_TEMPLATE
Condition::Pointer FAMILY_CLASS::Create(IndexType new_id, Geometry::Pointer slave, Properties::Pointer properties,
                                       Geometry::Pointer master) const {
    return std::make_shared<FAMILY_CLASS>(new_id, std::move(slave), std::move(properties), std::move(master));
}

FAMILY_TEMPLATE
void FAMILY_CLASS::AddResidual(const State<double>& state, const ProcessInfo& rCurrentProcessInfo,
                               LocalVector<double>& rhs) const {
    AddFamilyResidual(*this, state, rCurrentProcessInfo, rhs);
}

FAMILY_TEMPLATE
void FAMILY_CLASS::AddResidual(const State<ADScalar>& state, const ProcessInfo& rCurrentProcessInfo,
                               LocalVector<ADScalar>& rhs) const {
    AddFamilyResidual(*this, state, rCurrentProcessInfo, rhs);
}

FAMILY_TEMPLATE
void FAMILY_CLASS::AddResidual(const State<NormalScalar>& state, const ProcessInfo& rCurrentProcessInfo,
                               LocalVector<NormalScalar>& rhs) const {
    constexpr bool penalty = TF == FrictionalCase::FRICTIONLESS_PENALTY || TF == FrictionalCase::FRICTIONAL_PENALTY;
    if constexpr (penalty && !TNV)
        AddFamilyResidual(*this, state, rCurrentProcessInfo, rhs);
    else
        BaseType::AddResidual(state, rCurrentProcessInfo, rhs);  // InternalError: this family holds the normals
}

FAMILY_TEMPLATE
void FAMILY_CLASS::Initialize(const ProcessInfo& rCurrentProcessInfo) {
    BaseType::Initialize(rCurrentProcessInfo);
    if constexpr (IsFrictional) mPreviousMortarOperators.Reset();
}

FAMILY_TEMPLATE
void FAMILY_CLASS::InitializeSolutionStep(const ProcessInfo& rCurrentProcessInfo) {
    BaseType::InitializeSolutionStep(rCurrentProcessInfo);
    if constexpr (IsFrictional)
        frictional_detail::ComputePreviousOperatorsOnce<TDim, TNS, TNM>(*this, rCurrentProcessInfo,
                                                                        mPreviousMortarOperators);
}

FAMILY_TEMPLATE
void FAMILY_CLASS::FinalizeSolutionStep(const ProcessInfo& rCurrentProcessInfo) {
    BaseType::FinalizeSolutionStep(rCurrentProcessInfo);
    if constexpr (IsFrictional) mPreviousMortarOperators.initialized = false;
}

FAMILY_TEMPLATE
int FAMILY_CLASS::GetActiveInactiveValue() const {
    if constexpr (IsFrictional)
        return frictional_detail::FrictionalStateValue<TNS>(this->GetParentGeometry());
    else
        return frictional_detail::ActiveNodesValue<TNS>(this->GetParentGeometry());
}

FAMILY_TEMPLATE
void FAMILY_CLASS::AddExplicitContribution(const ProcessInfo& rCurrentProcessInfo) {
    if constexpr (IsFrictional)
        frictional_detail::AddFrictionalExplicitContribution<TDim, TNS, TNM>(*this, rCurrentProcessInfo,
                                                                             mPreviousMortarOperators);
    else
        frictional_detail::AddFrictionlessExplicitContribution<TDim, TNS, TNM>(*this, rCurrentProcessInfo);
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
        frictional_detail::CheckVectorMultiplier<TDim, TNS>(slave, this->Id(), "ALMContactFrictionlessComponents");
    if constexpr (TF == FrictionalCase::FRICTIONAL)
        frictional_detail::CheckVectorMultiplier<TDim, TNS>(slave, this->Id(), "ALMContactFrictional");
    if constexpr (IsFrictional) frictional_detail::CheckFrictionalVariables<TDim, TNS>(slave, this->Id());
    return 0;
}

FAMILY_TEMPLATE
void FAMILY_CLASS::GetDofList(DofsVectorType& rElementalDofList, const ProcessInfo&) const {
    const Geometry& slave = this->GetParentGeometry();
    rElementalDofList.clear();
    rElementalDofList.reserve(BaseType::MatrixSize);
    frictional_detail::AppendDisplacementDofs<TDim, TNS, TNM>(slave, this->GetPairedGeometry(), rElementalDofList);
    if constexpr (HasVectorMultiplier)
        frictional_detail::AppendVectorMultiplierDofs<TDim, TNS>(slave, rElementalDofList);
    if constexpr (TF == FrictionalCase::FRICTIONLESS)
        for (int j = 0; j < TNS; ++j)
            rElementalDofList.push_back(&slave[j].GetDof(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE));
}

FAMILY_TEMPLATE
typename FAMILY_CLASS::BaseType::MultiplierVector FAMILY_CLASS::MultiplierValues() const {
    const Geometry& slave = this->GetParentGeometry();
    if constexpr (HasVectorMultiplier) {
        return frictional_detail::VectorMultiplierValues<TDim, TNS, typename BaseType::MultiplierVector>(slave);
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
        this->Set(MODIFIED, !frictional_detail::IsObjective(operators, mPreviousMortarOperators, rCurrentProcessInfo));
}

FAMILY_TEMPLATE
frictional_detail::SlipData<TDim, TNS, TNM> FAMILY_CLASS::SlipOfStep(bool needs_slip) const {
    if constexpr (IsFrictional)
        return frictional_detail::MakeSlipData<TDim, TNS, TNM>(*this, mPreviousMortarOperators, needs_slip);
    else
        return frictional_detail::SlipData<TDim, TNS, TNM>{};  // a frictionless family measures no slip
}

#undef FAMILY_TEMPLATE
#undef FAMILY_CLASS

}  // namespace contact_app
