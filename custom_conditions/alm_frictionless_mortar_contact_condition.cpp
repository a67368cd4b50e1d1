// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/alm_frictionless_mortar_contact_condition.h"

#include "custom_conditions/frictionless_mortar_contact_common.h"

namespace contact_app {
namespace {

using namespace frictionless_detail;

/// RHS of docs/theory/contact_residuals.md §3 for one pair, q = [u2 (d·n_m), u1 (d·n_s), λ (n_s)].
template <class T, int TDim, int TNS, int TNM, class TState, class TVector>
void AddFrictionlessResidual(const TState& s, double k, const NodalParameters<TNS>& p, TVector& rhs) {
    constexpr int lambda_offset = TDim * (TNS + TNM);
    for (int j = 0; j < TNS; ++j) {
        const double eps = p.penalty[j];
        if (!p.active[j]) {
            rhs[lambda_offset + j] += -(k * k / eps) * s.multipliers[j];
            continue;
        }
        const T gap = PairGap<T, TDim>(s, j);
        SpreadNormalForce<T, TDim, TNS, TNM>(s, j, T(p.dynamic_factor[j] * (k * s.multipliers[j] + eps * gap)), rhs);
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
void ALM_CLASS::AddResidual(const State<double>& state, const ProcessInfo& rCurrentProcessInfo,
                            LocalVector<double>& rhs) const {
    const auto [k, p] = ReadALMParameters<TNS>(this->GetParentGeometry(), rCurrentProcessInfo, this->Id());
    AddFrictionlessResidual<double, TDim, TNS, TNM>(state, k, p, rhs);
}

ALM_TEMPLATE
void ALM_CLASS::AddResidual(const State<ADScalar>& state, const ProcessInfo& rCurrentProcessInfo,
                            LocalVector<ADScalar>& rhs) const {
    const auto [k, p] = ReadALMParameters<TNS>(this->GetParentGeometry(), rCurrentProcessInfo, this->Id());
    AddFrictionlessResidual<ADScalar, TDim, TNS, TNM>(state, k, p, rhs);
}

#undef ALM_TEMPLATE
#undef ALM_CLASS

CONTACT_APP_INSTANTIATE_CONTACT_FAMILY(AugmentedLagrangianMethodFrictionlessMortarContactCondition)
CONTACT_APP_INSTANTIATE_AXISYM_FAMILY(AugmentedLagrangianMethodFrictionlessMortarContactCondition)

}  // namespace contact_app
