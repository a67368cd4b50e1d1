// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace contact_app {

class ModelPart;

/// Automatic ALM penalty ε and scale factor k from the interface stiffness (Kratos ALMVariablesCalculationProcess,
/// docs/theory/contact_strategies.md §5). Over the non-paired conditions of the contact part, per side s ∈ {slave,
/// master} (a condition with neither flag counts for both): Ē_s = Σ E_c A_c / (Σ A_c + 1e−12) and
/// h̄_s = Σ_c Σ_nodes NODAL_H·A_c/n_c / (Σ A_c + 1e−12), with E_c = YOUNG_MODULUS of the condition's properties,
/// else of the solid element the face bounds (the reference uses 0 and then a penalty of 1), and A_c its DomainSize. ε_s = f Ē_s/(h̄_s + 1e−12), k_s = p f Ē_s/(h̄_s + 1e−12)
/// (the slave values are replaced by the master ones when Ē_s ≤ machine ε); ProcessInfo INITIAL_PENALTY =
/// min(ε_s, ε_m), SCALE_FACTOR = min(k_s, k_m). f = stiffness_factor, p = penalty_scale_factor.
class ALMVariablesCalculationProcess {
public:
    /// @param[in,out] model_part the contact part (kept by reference; must outlive the process)
    /// @param[in] stiffness_factor f (> 0); @param[in] penalty_scale_factor p (> 0)
    /// @throws InputError for non-positive factors
    ALMVariablesCalculationProcess(ModelPart& model_part, double stiffness_factor = 1.0,
                                   double penalty_scale_factor = 1.0);
    /// @brief Writes ProcessInfo INITIAL_PENALTY and SCALE_FACTOR.
    /// @throws InputError if the part has no condition with a positive area (run the interface preprocessing) or a
    ///         condition has no YOUNG_MODULUS, neither its own nor an adjacent element's
    void Execute();

private:
    ModelPart& mrModelPart;
    double mStiffnessFactor;
    double mPenaltyScaleFactor;
};

}  // namespace contact_app
