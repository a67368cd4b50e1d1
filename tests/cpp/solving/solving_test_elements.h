// SPDX-License-Identifier: BSD-3-Clause
// Small elements with closed-form answers for testing the solving layer in isolation.
#pragma once

#include <memory>

#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/element.h"
#include "contact_app/kernel/geometries/geometry_factory.h"
#include "contact_app/kernel/model.h"
#include "contact_app/kernel/variables.h"

namespace contact_app::testing {

/// Axial spring along x between two nodes: N = k (e + c e³), e = u₂ − u₁ (c = 0: linear).
class SpringElement : public Element {
public:
    SpringElement(IndexType id, Geometry::Pointer geometry, double stiffness, double cubic = 0.0)
        : Element(id, std::move(geometry)), mK(stiffness), mC(cubic) {}

    void CalculateLocalSystem(Matrix& rLHS, Vector& rRHS, const ProcessInfo&) override {
        const double e = Displacement(1) - Displacement(0);
        const double force = mK * (e + mC * e * e * e);
        const double tangent = mK * (1.0 + 3.0 * mC * e * e);
        rRHS.resize(2);
        rRHS << force, -force;
        rLHS.resize(2, 2);
        rLHS << tangent, -tangent, -tangent, tangent;
    }
    void EquationIdVector(EquationIdVectorType& rResult, const ProcessInfo&) const override {
        rResult = {GetGeometry()[0].GetDof(DISPLACEMENT_X).EquationId(), GetGeometry()[1].GetDof(DISPLACEMENT_X).EquationId()};
    }
    void GetDofList(DofsVectorType& rList, const ProcessInfo&) const override {
        rList = {&GetGeometry()[0].GetDof(DISPLACEMENT_X), &GetGeometry()[1].GetDof(DISPLACEMENT_X)};
    }

private:
    double Displacement(std::size_t i) const { return GetGeometry()[i].FastGetSolutionStepValue(DISPLACEMENT_X); }
    double mK, mC;
};

/// A point mass on a spring to the ground (x direction) with an optional external force.
class OscillatorElement : public Element {
public:
    OscillatorElement(IndexType id, Geometry::Pointer geometry, double mass, double stiffness, double force = 0.0)
        : Element(id, std::move(geometry)), mM(mass), mK(stiffness), mF(force) {}

    void CalculateLocalSystem(Matrix& rLHS, Vector& rRHS, const ProcessInfo&) override {
        rLHS = Matrix::Constant(1, 1, mK);
        rRHS = Vector::Constant(1, mF - mK * GetGeometry()[0].FastGetSolutionStepValue(DISPLACEMENT_X));
    }
    void CalculateMassMatrix(Matrix& rMass, const ProcessInfo&) override { rMass = Matrix::Constant(1, 1, mM); }
    void EquationIdVector(EquationIdVectorType& rResult, const ProcessInfo&) const override {
        rResult = {GetGeometry()[0].GetDof(DISPLACEMENT_X).EquationId()};
    }
    void GetDofList(DofsVectorType& rList, const ProcessInfo&) const override {
        rList = {&GetGeometry()[0].GetDof(DISPLACEMENT_X)};
    }
    void GetFirstDerivativesVector(Vector& rValues, int step) const override {
        rValues = Vector::Constant(1, GetGeometry()[0].FastGetSolutionStepValue(VELOCITY_X, step));
    }
    void GetSecondDerivativesVector(Vector& rValues, int step) const override {
        rValues = Vector::Constant(1, GetGeometry()[0].FastGetSolutionStepValue(ACCELERATION_X, step));
    }

private:
    double mM, mK, mF;
};

/// A model part "Main" with historical DISPLACEMENT/REACTION/VELOCITY/ACCELERATION and @p n nodes on
/// the x axis, each with DoF DISPLACEMENT_X (reaction REACTION_X).
inline ModelPart& MakeLine(Model& model, std::size_t n, std::size_t buffer_size = 2) {
    RegisterContactApplication();
    ModelPart& part = model.CreateModelPart("Main", buffer_size);
    for (const VariableData* variable : std::initializer_list<const VariableData*>{&DISPLACEMENT, &REACTION, &VELOCITY, &ACCELERATION})
        part.AddNodalSolutionStepVariable(*variable);
    for (IndexType id = 1; id <= n; ++id) part.CreateNewNode(id, double(id - 1), 0.0, 0.0)->AddDof(DISPLACEMENT_X, REACTION_X);
    part.GetProcessInfo().SetValue(DOMAIN_SIZE, 1);
    return part;
}

/// Springs between consecutive nodes with stiffness @p k and cubic coefficient @p c.
inline void AddSprings(ModelPart& part, double k, double c = 0.0) {
    for (IndexType id = 1; id < part.NumberOfNodes(); ++id) {
        auto geometry = CreateGeometry("Line2D2", {part.pGetNode(id), part.pGetNode(id + 1)});
        part.AddElement(std::make_shared<SpringElement>(id, geometry, k, c));
    }
}

}  // namespace contact_app::testing
