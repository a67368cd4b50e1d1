// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/convergence_criteria/mixed_generic_criteria.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/solving/convergence_criteria/round_off_bound.h"

namespace contact_app {

MixedGenericCriteria::MixedGenericCriteria(std::vector<Entry> entries) : mEntries(std::move(entries)) {
    CONTACT_CHECK(!mEntries.empty(), InputError, "mixed_generic_criterion needs at least one variable with tolerances");
    for (const Entry& entry : mEntries)
        CONTACT_CHECK(entry.variable != nullptr && entry.relative_tolerance >= 0.0 && entry.absolute_tolerance >= 0.0,
                      InputError, "mixed_generic_criterion: tolerances of ",
                      entry.variable ? entry.variable->Name() : std::string("(null)"), " must be non-negative");
}

std::size_t MixedGenericCriteria::GroupOf(const Dof& rDof) const {
    const VariableData& variable = rDof.GetVariable();
    const VariableData& source = variable.IsComponent() ? *variable.SourceVariable() : variable;
    for (std::size_t i = 0; i < mEntries.size(); ++i)
        if (*mEntries[i].variable == variable || *mEntries[i].variable == source) return i;
    return mEntries.size();
}

bool MixedGenericCriteria::PostCriteria(ModelPart&, DofsArrayType& rDofSet, const SparseMatrixType&,
                                        const SystemVectorType& rDx, const SystemVectorType&, const BuilderAndSolver&) {
    const std::size_t groups = mEntries.size() + 1;
    std::vector<double> increment(groups, 0.0), reference(groups, 0.0), magnitude(groups, 0.0);
    std::vector<std::size_t> count(groups, 0);
    for (const Dof* dof : rDofSet) {
        const auto id = static_cast<Eigen::Index>(dof->EquationId());
        if (dof->IsFixed() || id >= rDx.size()) continue;
        const std::size_t group = GroupOf(*dof);
        increment[group] += rDx[id] * rDx[id];
        reference[group] += dof->GetSolutionStepValue() * dof->GetSolutionStepValue();
        magnitude[group] += RoundOffBound::StateMagnitude(*dof) * RoundOffBound::StateMagnitude(*dof);
        ++count[group];
    }
    constexpr double eps = std::numeric_limits<double>::epsilon();
    mRatios.assign(groups, 0.0);
    mAbsolutes.assign(groups, 0.0);
    bool converged = true;
    for (std::size_t g = 0; g < groups; ++g) {
        if (count[g] == 0) continue;
        const double dx = std::sqrt(increment[g]);
        const double x = std::sqrt(reference[g]) < eps ? dx : std::sqrt(reference[g]);
        mRatios[g] = dx < eps ? 0.0 : dx / x;
        mAbsolutes[g] = dx / std::sqrt(static_cast<double>(count[g]));
        const Entry& tolerances = g < mEntries.size() ? mEntries[g] : mEntries.front();
        // An increment below the round-off floor of its state cannot get smaller (RoundOffBound).
        converged = converged && (mRatios[g] <= tolerances.relative_tolerance ||
                                  mAbsolutes[g] < tolerances.absolute_tolerance ||
                                  RoundOffBound::IsRoundOff(dx, magnitude[g], 0.0));
    }
    return converged;
}

std::string MixedGenericCriteria::LastNorms() const {
    std::ostringstream out;
    out.precision(3);
    out << std::scientific;
    for (std::size_t g = 0; g < mRatios.size(); ++g) {
        if (g > 0) out << "; ";
        out << (g < mEntries.size() ? mEntries[g].variable->Name() : std::string("others")) << " ratio " << mRatios[g]
            << " abs " << mAbsolutes[g];
    }
    return out.str();
}

}  // namespace contact_app
