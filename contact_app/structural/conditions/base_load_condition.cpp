// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/structural/conditions/base_load_condition.h"

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/variables.h"

namespace contact_app {

namespace {

const Variable<double>* const kDisplacementComponents[] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};

}  // namespace

void BaseLoadCondition::CalculateLocalSystem(Matrix& rLeftHandSideMatrix, Vector& rRightHandSideVector,
                                             const ProcessInfo& rCurrentProcessInfo) {
    const Eigen::Index size = static_cast<Eigen::Index>(GetGeometry().size()) * DofsPerNode();
    rLeftHandSideMatrix = Matrix::Zero(size, size);
    rRightHandSideVector = Vector::Zero(size);
    CalculateAll(&rLeftHandSideMatrix, &rRightHandSideVector, rCurrentProcessInfo);
}

void BaseLoadCondition::CalculateLeftHandSide(Matrix& rLeftHandSideMatrix, const ProcessInfo& rCurrentProcessInfo) {
    const Eigen::Index size = static_cast<Eigen::Index>(GetGeometry().size()) * DofsPerNode();
    rLeftHandSideMatrix = Matrix::Zero(size, size);
    CalculateAll(&rLeftHandSideMatrix, nullptr, rCurrentProcessInfo);
}

void BaseLoadCondition::CalculateRightHandSide(Vector& rRightHandSideVector, const ProcessInfo& rCurrentProcessInfo) {
    rRightHandSideVector = Vector::Zero(static_cast<Eigen::Index>(GetGeometry().size()) * DofsPerNode());
    CalculateAll(nullptr, &rRightHandSideVector, rCurrentProcessInfo);
}

void BaseLoadCondition::EquationIdVector(EquationIdVectorType& rResult, const ProcessInfo&) const {
    const int dim = DofsPerNode();
    rResult.clear();
    rResult.reserve(GetGeometry().size() * dim);
    for (std::size_t i = 0; i < GetGeometry().size(); ++i)
        for (int k = 0; k < dim; ++k) rResult.push_back(GetGeometry()[i].GetDof(*kDisplacementComponents[k]).EquationId());
}

void BaseLoadCondition::GetDofList(DofsVectorType& rElementalDofList, const ProcessInfo&) const {
    const int dim = DofsPerNode();
    rElementalDofList.clear();
    rElementalDofList.reserve(GetGeometry().size() * dim);
    for (std::size_t i = 0; i < GetGeometry().size(); ++i)
        for (int k = 0; k < dim; ++k) rElementalDofList.push_back(&GetGeometry()[i].GetDof(*kDisplacementComponents[k]));
}

void BaseLoadCondition::GetValuesVector(Vector& rValues, int Step) const {
    FillNodalVector(DISPLACEMENT, rValues, Step);
}

void BaseLoadCondition::GetFirstDerivativesVector(Vector& rValues, int Step) const {
    FillNodalVector(VELOCITY, rValues, Step);
}

void BaseLoadCondition::GetSecondDerivativesVector(Vector& rValues, int Step) const {
    FillNodalVector(ACCELERATION, rValues, Step);
}

int BaseLoadCondition::Check(const ProcessInfo& rCurrentProcessInfo) const {
    Condition::Check(rCurrentProcessInfo);
    for (std::size_t i = 0; i < GetGeometry().size(); ++i) {
        const Node& node = GetGeometry()[i];
        CONTACT_CHECK(node.SolutionStepsDataHas(DISPLACEMENT), InputError, Info(), ": node ", node.Id(),
                      " has no historical DISPLACEMENT\n  expected: DISPLACEMENT among the nodal solution-step variables",
                      "\n  fix: call AddNodalSolutionStepVariable(DISPLACEMENT) before creating the nodes"
                      " (the structural solver's AddVariables does it)");
        for (int k = 0; k < DofsPerNode(); ++k) {
            const Variable<double>& component = *kDisplacementComponents[k];
            CONTACT_CHECK(node.HasDofFor(component), InputError, Info(), ": node ", node.Id(), " has no ",
                          component.Name(), " DoF\n  expected: the DoFs DISPLACEMENT_X/Y", (DofsPerNode() == 3 ? "/Z" : ""),
                          " on every node of the condition\n  fix: add them with AddDof(", component.Name(),
                          ", REACTION_", "XYZ"[k], ") (the structural solver's AddDofs does it)");
        }
    }
    return 0;
}

std::vector<double> BaseLoadCondition::NodalPressures() const {
    const double condition_pressure =
        GetValue(PRESSURE) + GetValue(NEGATIVE_FACE_PRESSURE) - GetValue(POSITIVE_FACE_PRESSURE);
    std::vector<double> pressures(GetGeometry().size(), condition_pressure);
    for (std::size_t i = 0; i < GetGeometry().size(); ++i) {
        const Node& node = GetGeometry()[i];
        if (node.SolutionStepsDataHas(NEGATIVE_FACE_PRESSURE))
            pressures[i] += node.GetSolutionStepValue(NEGATIVE_FACE_PRESSURE);
        if (node.SolutionStepsDataHas(POSITIVE_FACE_PRESSURE))
            pressures[i] -= node.GetSolutionStepValue(POSITIVE_FACE_PRESSURE);
    }
    return pressures;
}

std::vector<Array3> BaseLoadCondition::NodalLoads(const Variable<Array3>& variable, bool non_historical_fallback) const {
    std::vector<Array3> loads(GetGeometry().size(), Array3::Zero());
    for (std::size_t i = 0; i < GetGeometry().size(); ++i) {
        const Node& node = GetGeometry()[i];
        if (node.SolutionStepsDataHas(variable)) loads[i] = node.GetSolutionStepValue(variable);
        else if (non_historical_fallback) loads[i] = node.GetValue(variable);
    }
    return loads;
}

void BaseLoadCondition::FillNodalVector(const Variable<Array3>& variable, Vector& rValues, int step) const {
    const int dim = DofsPerNode();
    rValues.resize(static_cast<Eigen::Index>(GetGeometry().size()) * dim);
    for (std::size_t i = 0; i < GetGeometry().size(); ++i) {
        const Array3& value = GetGeometry()[i].GetSolutionStepValue(variable, static_cast<std::size_t>(step));
        for (int k = 0; k < dim; ++k) rValues[static_cast<Eigen::Index>(i) * dim + k] = value[k];
    }
}

}  // namespace contact_app
