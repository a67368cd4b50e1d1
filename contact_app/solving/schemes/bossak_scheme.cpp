// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/schemes/bossak_scheme.h"

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/variables.h"

namespace contact_app {

namespace {

const Variable<double>* kDisplacement[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
const Variable<double>* kVelocity[3] = {&VELOCITY_X, &VELOCITY_Y, &VELOCITY_Z};
const Variable<double>* kAcceleration[3] = {&ACCELERATION_X, &ACCELERATION_Y, &ACCELERATION_Z};

int Dimension(const ModelPart& rModelPart) {
    const ProcessInfo& info = rModelPart.GetProcessInfo();
    return info.Has(DOMAIN_SIZE) ? info.GetValue(DOMAIN_SIZE) : 3;
}

}  // namespace

BossakScheme::BossakScheme(double damp_factor_m, double newmark_beta) : mAlphaM(damp_factor_m) {
    CONTACT_CHECK(damp_factor_m >= -0.5 && damp_factor_m <= 0.0, InputError, "damp_factor_m = ", damp_factor_m,
                  " is outside the Bossak range\n  expected: a value in [-0.5, 0] (0 gives Newmark)");
    CONTACT_CHECK(newmark_beta > 0.0, InputError, "newmark_beta = ", newmark_beta,
                  " must be positive (0.25: average acceleration)");
    mBeta = (1.0 - mAlphaM) * (1.0 - mAlphaM) * newmark_beta;
    mGamma = 0.5 - mAlphaM;
}

void BossakScheme::ComputeCoefficients(double delta_time) {
    CONTACT_CHECK(delta_time > 0.0, InputError, "the Bossak scheme needs DELTA_TIME > 0, got ", delta_time,
                  "\n  fix: check time_step in solver_settings");
    mC[0] = 1.0 / (mBeta * delta_time * delta_time);
    mC[1] = mGamma / (mBeta * delta_time);
    mC[2] = 1.0 / (mBeta * delta_time);
    mC[3] = 0.5 / mBeta - 1.0;
    mC[4] = mGamma / mBeta - 1.0;
    mC[5] = 0.5 * delta_time * (mGamma / mBeta - 2.0);
}

void BossakScheme::InitializeSolutionStep(ModelPart& rModelPart, SparseMatrixType& rA, SystemVectorType& rDx,
                                          SystemVectorType& rB) {
    Scheme::InitializeSolutionStep(rModelPart, rA, rDx, rB);
    ComputeCoefficients(rModelPart.GetProcessInfo().GetValue(DELTA_TIME));
    // A prescribed acceleration or velocity prescribes the displacement of the step.
    for (const auto& node : rModelPart.Nodes()) {
        for (int k = 0; k < 3; ++k) {
            if (!node->HasDofFor(*kDisplacement[k])) continue;
            if (node->IsFixed(*kAcceleration[k]) || node->IsFixed(*kVelocity[k])) node->Fix(*kDisplacement[k]);
        }
    }
}

void BossakScheme::Predict(ModelPart& rModelPart, DofsArrayType&, SparseMatrixType&, SystemVectorType&,
                           SystemVectorType&) {
    PredictDisplacements(rModelPart, true);
}

void BossakScheme::PredictPrescribed(ModelPart& rModelPart) { PredictDisplacements(rModelPart, false); }

void BossakScheme::PredictDisplacements(ModelPart& rModelPart, bool extrapolate_free) {
    const double dt = rModelPart.GetProcessInfo().GetValue(DELTA_TIME);
    ComputeCoefficients(dt);
    const int dimension = Dimension(rModelPart);
    for (const auto& node : rModelPart.Nodes()) {
        if (!node->SolutionStepsDataHas(DISPLACEMENT)) continue;
        Array3& u = node->FastGetSolutionStepValue(DISPLACEMENT);
        const Array3& u_n = node->FastGetSolutionStepValue(DISPLACEMENT, 1);
        const Array3& v_n = node->FastGetSolutionStepValue(VELOCITY, 1);
        const Array3& a_n = node->FastGetSolutionStepValue(ACCELERATION, 1);
        const Array3& v = node->FastGetSolutionStepValue(VELOCITY);
        const Array3& a = node->FastGetSolutionStepValue(ACCELERATION);
        for (int k = 0; k < dimension; ++k) {
            if (node->IsFixed(*kAcceleration[k])) {
                u[k] = u_n[k] + (a[k] + mC[3] * a_n[k] + mC[2] * v_n[k]) / mC[0];
            } else if (node->IsFixed(*kVelocity[k])) {
                u[k] = u_n[k] + (v[k] + mC[4] * v_n[k] + mC[5] * a_n[k]) / mC[1];
            } else if (!node->IsFixed(*kDisplacement[k])) {
                u[k] = extrapolate_free ? u_n[k] + dt * v_n[k] + 0.5 * dt * dt * a_n[k] : u_n[k];
            }
        }
    }
    UpdateDerivatives(rModelPart);
}

void BossakScheme::Update(ModelPart& rModelPart, DofsArrayType& rDofSet, SparseMatrixType& rA,
                          SystemVectorType& rDx, SystemVectorType& rB) {
    Scheme::Update(rModelPart, rDofSet, rA, rDx, rB);
    UpdateDerivatives(rModelPart);
}

void BossakScheme::UpdateDerivatives(ModelPart& rModelPart) const {
    for (const auto& node : rModelPart.Nodes()) {
        if (!node->SolutionStepsDataHas(DISPLACEMENT)) continue;
        const Array3 delta = node->FastGetSolutionStepValue(DISPLACEMENT) - node->FastGetSolutionStepValue(DISPLACEMENT, 1);
        const Array3 v_n = node->FastGetSolutionStepValue(VELOCITY, 1);
        const Array3 a_n = node->FastGetSolutionStepValue(ACCELERATION, 1);
        // Prescribed velocities/accelerations keep their values; the displacement follows them.
        for (int k = 0; k < 3; ++k) {
            if (!node->IsFixed(*kVelocity[k]))
                node->FastGetSolutionStepValue(*kVelocity[k]) = mC[1] * delta[k] - mC[4] * v_n[k] - mC[5] * a_n[k];
            if (!node->IsFixed(*kAcceleration[k]))
                node->FastGetSolutionStepValue(*kAcceleration[k]) = mC[0] * delta[k] - mC[2] * v_n[k] - mC[3] * a_n[k];
        }
    }
}

void BossakScheme::AddDynamicLHS(Element& rElement, Matrix& rLHS, const ProcessInfo& rProcessInfo) {
    Matrix mass, damping;
    rElement.CalculateMassMatrix(mass, rProcessInfo);
    rElement.CalculateDampingMatrix(damping, rProcessInfo);
    if (mass.size() != 0) rLHS += (1.0 - mAlphaM) * mC[0] * mass;
    if (damping.size() != 0) rLHS += mC[1] * damping;
}

void BossakScheme::AddDynamicRHS(Element& rElement, Vector& rRHS, const ProcessInfo& rProcessInfo) {
    Matrix mass, damping;
    rElement.CalculateMassMatrix(mass, rProcessInfo);
    rElement.CalculateDampingMatrix(damping, rProcessInfo);
    if (mass.size() != 0) {
        Vector a_new, a_old;
        rElement.GetSecondDerivativesVector(a_new, 0);
        rElement.GetSecondDerivativesVector(a_old, 1);
        rRHS -= mass * ((1.0 - mAlphaM) * a_new + mAlphaM * a_old);
    }
    if (damping.size() != 0) {
        Vector velocity;
        rElement.GetFirstDerivativesVector(velocity, 0);
        rRHS -= damping * velocity;
    }
}

void BossakScheme::CalculateSystemContributions(Element& rElement, Matrix& rLHS, Vector& rRHS,
                                                EquationIdVectorType& rEquationIds, const ProcessInfo& rProcessInfo) {
    Scheme::CalculateSystemContributions(rElement, rLHS, rRHS, rEquationIds, rProcessInfo);
    AddDynamicLHS(rElement, rLHS, rProcessInfo);
    AddDynamicRHS(rElement, rRHS, rProcessInfo);
}

void BossakScheme::CalculateRHSContribution(Element& rElement, Vector& rRHS, EquationIdVectorType& rEquationIds,
                                            const ProcessInfo& rProcessInfo) {
    Scheme::CalculateRHSContribution(rElement, rRHS, rEquationIds, rProcessInfo);
    AddDynamicRHS(rElement, rRHS, rProcessInfo);
}

void BossakScheme::CalculateLHSContribution(Element& rElement, Matrix& rLHS, EquationIdVectorType& rEquationIds,
                                            const ProcessInfo& rProcessInfo) {
    Scheme::CalculateLHSContribution(rElement, rLHS, rEquationIds, rProcessInfo);
    AddDynamicLHS(rElement, rLHS, rProcessInfo);
}

int BossakScheme::Check(const ModelPart& rModelPart) const {
    Scheme::Check(rModelPart);
    CONTACT_CHECK(rModelPart.GetBufferSize() >= 2, InputError, "the ", Info(), " scheme needs a buffer size of at least 2 in model part ",
                  rModelPart.Name(), ", got ", rModelPart.GetBufferSize(), "\n  fix: set solver_settings.buffer_size to 2 or more");
    for (const VariableData* variable : {static_cast<const VariableData*>(&DISPLACEMENT), static_cast<const VariableData*>(&VELOCITY),
                                         static_cast<const VariableData*>(&ACCELERATION)})
        CONTACT_CHECK(rModelPart.HasNodalSolutionStepVariable(*variable), InputError, "the ", Info(), " scheme needs ",
                      variable->Name(), " as a solution-step variable of model part ", rModelPart.Name());
    return 0;
}

}  // namespace contact_app
