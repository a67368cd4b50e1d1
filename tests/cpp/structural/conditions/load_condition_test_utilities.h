// SPDX-License-Identifier: BSD-3-Clause
/// Helpers shared by the load-condition tests: a structural model part, displaced states, FD of the RHS.
#pragma once

#include <random>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/model.h"
#include "contact_app/kernel/variables.h"
#include "contact_app/structural/structural_registration.h"

namespace contact_app::testing {

/// A model part "Structure" with the historical variables the structural solver adds (DISPLACEMENT,
/// REACTION, the loads and face pressures unless @p nodal_loads is false) and property 1.
class LoadConditionModel {
public:
    explicit LoadConditionModel(bool historical_displacement = true, bool nodal_loads = true) {
        RegisterContactApplication();
        RegisterLoadConditions();
        part = &model.CreateModelPart("Structure");
        if (historical_displacement) {
            part->AddNodalSolutionStepVariable(DISPLACEMENT);
            part->AddNodalSolutionStepVariable(REACTION);
        }
        if (nodal_loads) {
            const VariableData* const loads[] = {&POINT_LOAD, &LINE_LOAD, &SURFACE_LOAD, &POSITIVE_FACE_PRESSURE,
                                                 &NEGATIVE_FACE_PRESSURE};
            for (const VariableData* variable : loads) part->AddNodalSolutionStepVariable(*variable);
        }
        properties = part->CreateNewProperties(1);
    }

    /// Node @p id at @p x with the DISPLACEMENT DoFs (and REACTION) when @p with_dofs.
    Node& AddNode(IndexType id, const Array3& x, bool with_dofs = true) {
        auto node = part->CreateNewNode(id, x[0], x[1], x[2]);
        if (with_dofs) {
            node->AddDof(DISPLACEMENT_X, REACTION_X);
            node->AddDof(DISPLACEMENT_Y, REACTION_Y);
            node->AddDof(DISPLACEMENT_Z, REACTION_Z);
        }
        return *node;
    }
    /// Nodes 1, 2, ... at @p coordinates.
    void AddNodes(const std::vector<Array3>& coordinates, bool with_dofs = true) {
        for (std::size_t i = 0; i < coordinates.size(); ++i) AddNode(i + 1, coordinates[i], with_dofs);
    }
    Condition& AddCondition(const std::string& name, IndexType id, const std::vector<IndexType>& node_ids) {
        return *part->CreateNewCondition(name, id, node_ids, properties);
    }

    Model model;
    ModelPart* part = nullptr;
    Properties::Pointer properties;
};

/// Moves @p node to X + u, storing u in DISPLACEMENT when it is historical (as MoveMesh does).
inline void Displace(Node& node, const Array3& u) {
    node.Coordinates() = node.InitialCoordinates() + u;
    if (node.SolutionStepsDataHas(DISPLACEMENT)) node.FastGetSolutionStepValue(DISPLACEMENT) = u;
}

/// Random displacements of amplitude @p amplitude for every node of @p part (z = 0 when @p dim = 2).
inline void DisplaceRandomly(ModelPart& part, std::mt19937& rng, double amplitude, int dim) {
    std::uniform_real_distribution<double> uniform(-amplitude, amplitude);
    for (const auto& node : part.Nodes()) {
        Array3 u(uniform(rng), uniform(rng), dim == 3 ? uniform(rng) : 0.0);
        Displace(*node, u);
    }
}

/// The RHS of @p condition alone.
inline Vector Rhs(Condition& condition) {
    Vector rhs;
    condition.CalculateRightHandSide(rhs, ProcessInfo());
    return rhs;
}

/// −∂RHS/∂u by central differences of the current coordinates, @p dofs_per_node components per node.
inline Matrix FiniteDifferenceLhs(Condition& condition, int dofs_per_node, double step = 1e-6) {
    Geometry& geometry = condition.GetGeometry();
    const Eigen::Index size = static_cast<Eigen::Index>(geometry.size()) * dofs_per_node;
    Matrix lhs(size, size);
    for (std::size_t j = 0; j < geometry.size(); ++j) {
        for (int c = 0; c < dofs_per_node; ++c) {
            double& x = geometry[j].Coordinates()[c];
            const double saved = x;
            x = saved + step;
            const Vector plus = Rhs(condition);
            x = saved - step;
            const Vector minus = Rhs(condition);
            x = saved;
            lhs.col(static_cast<Eigen::Index>(j) * dofs_per_node + c) = -(plus - minus) / (2.0 * step);
        }
    }
    return lhs;
}

/// Σ over the conditions of @p part of their nodal forces (first @p dim components).
inline Array3 NetForce(const ModelPart& part, int dim) {
    Array3 total = Array3::Zero();
    for (const auto& condition : part.Conditions()) {
        const Vector rhs = Rhs(*condition);
        for (Eigen::Index i = 0; i < rhs.size(); ++i) total[i % dim] += rhs[i];
    }
    return total;
}

}  // namespace contact_app::testing
