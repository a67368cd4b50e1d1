// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "custom_conditions/mortar_contact_condition.h"
#include "custom_conditions/nodal_gap_coupling.h"
#include "custom_utilities/contact_variables.h"

namespace contact_app {

/// What the two penalty families share beyond MortarContactCondition: the record of their nodal-gap coupling terms
/// (nodal_gap_coupling.h, docs/theory/mortar.md §7 "Nodal penalty"). Every tangent evaluation starts it afresh, the
/// family residual's AD pass fills it, and NodalPenaltyCoupling reads it after the builder assembled the pairs. The
/// penalty pairs also differentiate the nodal normals the criteria move every iteration (NodalNormalCoupling).
template <int TDim, int TNumNodes, FrictionalCase TFrictional, bool TNormalVariation, int TNumNodesMaster>
class PenaltyMortarContactCondition
    : public MortarContactCondition<TDim, TNumNodes, TFrictional, TNormalVariation, TNumNodesMaster>,
      public NodalGapCouplingSource {
public:
    using BaseType = MortarContactCondition<TDim, TNumNodes, TFrictional, TNormalVariation, TNumNodesMaster>;
    using BaseType::BaseType;

    bool GetNodalGapCoupling(int j, NodalGapCouplingTerms& rTerms) const override {
        return mCouplingRecord.Get(j, rTerms);
    }
    /// Without NV, when CONSIDER_NORMAL_VARIATION ≠ 0 (the criteria move the nodal normals every iteration): the
    /// penalty pairs differentiate them (docs/theory/mortar.md §7 "Normals that follow the iterate").
    bool CouplesNodalNormals(const ProcessInfo& rCurrentProcessInfo) const override {
        return !TNormalVariation && rCurrentProcessInfo.Has(CONSIDER_NORMAL_VARIATION) &&
               rCurrentProcessInfo.GetValue(CONSIDER_NORMAL_VARIATION) != 0;
    }

    using CouplingRecord = NodalGapCouplingRecord<TDim, TNumNodes, BaseType::MatrixSize>;
    /// Written by the family's (const) AD residual (AddFamilyResidual, mortar_contact_family_condition.h).
    CouplingRecord* MutableCouplingRecord() const { return &mCouplingRecord; }

protected:
    /// A tangent evaluation (@p pLhs not null) starts the coupling record afresh.
    void CalculateConditionSystem(Matrix* pLhs, Vector* pRhs, const ProcessInfo& rCurrentProcessInfo) override {
        if (pLhs) mCouplingRecord.Clear();
        BaseType::CalculateConditionSystem(pLhs, pRhs, rCurrentProcessInfo);
    }
    void AfterNormalPass() override { mCouplingRecord.normals_recorded = true; }

private:
    mutable CouplingRecord mCouplingRecord;
};

}  // namespace contact_app
