// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/solving/schemes/scheme.h"

namespace contact_app {

/// Implicit Bossak–Newmark displacement scheme (Kratos ResidualBasedBossakDisplacementScheme;
/// Newmark when α_m = 0). β = (1 − α_m)² β_N, γ = 1/2 − α_m.
/// LHS = K + (1 − α_m) c₀ M + c₁ C, RHS = f − M[(1 − α_m) a_{n+1} + α_m a_n] − C v_{n+1}
/// (docs/theory/structural.md §5).
class BossakScheme : public Scheme {
public:
    /// @param damp_factor_m α_m ∈ [−0.5, 0] @param newmark_beta β_N (0.25 average acceleration)
    /// @throws InputError for α_m outside [−0.5, 0] or β_N ≤ 0.
    explicit BossakScheme(double damp_factor_m = -0.3, double newmark_beta = 0.25);

    void InitializeSolutionStep(ModelPart& rModelPart, SparseMatrixType& rA, SystemVectorType& rDx,
                                SystemVectorType& rB) override;
    void Predict(ModelPart& rModelPart, DofsArrayType& rDofSet, SparseMatrixType& rA, SystemVectorType& rDx,
                 SystemVectorType& rB) override;
    void PredictPrescribed(ModelPart& rModelPart) override;
    void Update(ModelPart& rModelPart, DofsArrayType& rDofSet, SparseMatrixType& rA, SystemVectorType& rDx,
                SystemVectorType& rB) override;

    void CalculateSystemContributions(Element& rElement, Matrix& rLHS, Vector& rRHS,
                                      EquationIdVectorType& rEquationIds, const ProcessInfo& rProcessInfo) override;
    void CalculateRHSContribution(Element& rElement, Vector& rRHS, EquationIdVectorType& rEquationIds,
                                  const ProcessInfo& rProcessInfo) override;
    void CalculateLHSContribution(Element& rElement, Matrix& rLHS, EquationIdVectorType& rEquationIds,
                                  const ProcessInfo& rProcessInfo) override;

    /// @throws InputError if the buffer is shorter than 2 or VELOCITY/ACCELERATION are not historical.
    int Check(const ModelPart& rModelPart) const override;
    std::string Info() const override { return mAlphaM == 0.0 ? "newmark" : "bossak"; }

    double Beta() const { return mBeta; }
    double Gamma() const { return mGamma; }

private:
    void ComputeCoefficients(double delta_time);
    /// Displacements of the new step: prescribed velocities/accelerations integrated, free DoFs extrapolated
    /// (u_n + Δt v_n + Δt²/2 a_n) or kept at u_n; then the derivatives.
    void PredictDisplacements(ModelPart& rModelPart, bool extrapolate_free);
    /// v_{n+1}, a_{n+1} of every node from its displacement increment.
    void UpdateDerivatives(ModelPart& rModelPart) const;
    void AddDynamicLHS(Element& rElement, Matrix& rLHS, const ProcessInfo& rProcessInfo);
    void AddDynamicRHS(Element& rElement, Vector& rRHS, const ProcessInfo& rProcessInfo);

    double mAlphaM;
    double mBeta;
    double mGamma;
    double mC[6] = {0, 0, 0, 0, 0, 0};  // c0..c5 of docs/theory/structural.md §5
};

}  // namespace contact_app
