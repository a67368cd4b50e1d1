// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "contact_app/solving/convergence_criteria/convergence_criteria.h"

namespace contact_app {

/// Increment criterion with one tolerance pair per variable (Kratos MixedGenericCriteria): for each
/// listed variable (a 3-vector groups its components) ratio = ‖Δx_var‖/‖x_var‖ and
/// abs = ‖Δx_var‖/√n_var over its free DoFs; converged when every variable has ratio ≤ its relative
/// tolerance or abs < its absolute tolerance or ‖Δx_var‖ is at round-off (RoundOffBound). DoFs of other
/// variables form one more group checked with the first variable's tolerances, so no unknown is left unchecked.
class MixedGenericCriteria : public ConvergenceCriteria {
public:
    struct Entry {
        const VariableData* variable;  ///< not owned (a registered global)
        double relative_tolerance;
        double absolute_tolerance;
    };

    /// @throws InputError for an empty list or negative tolerances.
    explicit MixedGenericCriteria(std::vector<Entry> entries);

    bool PostCriteria(ModelPart& rModelPart, DofsArrayType& rDofSet, const SparseMatrixType& rA,
                      const SystemVectorType& rDx, const SystemVectorType& rB, const BuilderAndSolver& rBuilder) override;
    std::string LastNorms() const override;
    std::string Info() const override { return "mixed_generic_criterion"; }
    /// Ratio and absolute norm of group @p i (entries in order, then the "others" group).
    double LastRatio(std::size_t i) const { return mRatios.at(i); }
    double LastAbsolute(std::size_t i) const { return mAbsolutes.at(i); }

private:
    std::size_t GroupOf(const Dof& rDof) const;

    std::vector<Entry> mEntries;
    std::vector<double> mRatios;
    std::vector<double> mAbsolutes;
};

}  // namespace contact_app
