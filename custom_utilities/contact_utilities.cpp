// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/contact_utilities.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/condition.h"
#include "contact_app/kernel/dof.h"
#include "contact_app/kernel/model_part.h"

namespace contact_app {

namespace {

/// Sets a nodal double to zero where the model stores it (historical first, as the conditions write it).
void ZeroNodal(Node& node, const Variable<double>& variable) {
    if (node.SolutionStepsDataHas(variable))
        node.FastGetSolutionStepValue(variable) = 0.0;
    else
        node.SetValue(variable, 0.0);
}

void ZeroNodal(Node& node, const Variable<Array3>& variable) {
    if (node.SolutionStepsDataHas(variable))
        node.FastGetSolutionStepValue(variable) = Array3::Zero();
    else if (node.Has(variable))
        node.SetValue(variable, Array3(Array3::Zero()));
}

}  // namespace

double ContactUtilities::NodalH(const Node& node) {
    return node.SolutionStepsDataHas(NODAL_H) ? node.FastGetSolutionStepValue(NODAL_H) : node.GetValue(NODAL_H);
}

double ContactUtilities::TransmittedWeightedGap(const Node& node) {
    const double area = node.GetValue(NODAL_AREA);
    const double gap = node.SolutionStepsDataHas(WEIGHTED_GAP) ? node.FastGetSolutionStepValue(WEIGHTED_GAP)
                                                               : node.GetValue(WEIGHTED_GAP);
    return area > 0.0 ? node.GetValue(AREA_WEIGHTED_PAIR_GAP) / area : gap;
}

double ContactUtilities::PenaltyShare(const Node& node) {
    const double area = node.GetValue(NODAL_AREA);
    return area > 0.0 ? node.GetValue(SQUARED_PAIR_AREA) / (area * area) : 1.0;
}

double ContactUtilities::PenaltyWeightedGap(const Node& node) {
    const double gap = node.SolutionStepsDataHas(WEIGHTED_GAP) ? node.FastGetSolutionStepValue(WEIGHTED_GAP)
                                                               : node.GetValue(WEIGHTED_GAP);
    return PenaltyShare(node) * gap;
}

Array3 ContactUtilities::TransmittedWeightedSlip(const Node& node) {
    const double area = node.GetValue(NODAL_AREA);
    if (area > 0.0) return node.GetValue(AREA_WEIGHTED_PAIR_SLIP) / area;
    return node.SolutionStepsDataHas(WEIGHTED_SLIP) ? node.FastGetSolutionStepValue(WEIGHTED_SLIP)
                                                     : Array3(Array3::Zero());
}

namespace {
const Variable<double>* const kMultiplierComponents[3] = {&VECTOR_LAGRANGE_MULTIPLIER_X, &VECTOR_LAGRANGE_MULTIPLIER_Y,
                                                          &VECTOR_LAGRANGE_MULTIPLIER_Z};
const Variable<double>* const kDisplacementComponents[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
}  // namespace

bool ContactUtilities::IsMultiplierComponentHeld(const Node& node, int c) {
    return node.HasDofFor(*kMultiplierComponents[c]) && node.IsFixed(*kMultiplierComponents[c]);
}

bool ContactUtilities::IsDisplacementComponentPrescribed(const Node& node, int c) {
    return node.IsFixed(*kDisplacementComponents[c]);
}

double ContactUtilities::CalculateMaxNodalH(const ModelPart& model_part) {
    double result = 0.0;
    for (const auto& node : model_part.Nodes()) result = std::max(result, NodalH(*node));
    return result;
}

double ContactUtilities::CalculateMeanNodalH(const ModelPart& model_part) {
    if (model_part.NumberOfNodes() == 0) return 0.0;
    double sum = 0.0;
    for (const auto& node : model_part.Nodes()) sum += NodalH(*node);
    return sum / static_cast<double>(model_part.NumberOfNodes());
}

double ContactUtilities::CalculateMinimalNodalH(const ModelPart& model_part) {
    // The reference starts its buffers at 0 and keeps the larger value ([BUG?]): this is a true minimum.
    if (model_part.NumberOfNodes() == 0) return 0.0;
    double result = std::numeric_limits<double>::max();
    for (const auto& node : model_part.Nodes()) result = std::min(result, NodalH(*node));
    return result;
}

double ContactUtilities::CalculateRelativeSizeMesh(const ModelPart& model_part) {
    const double minimum = CalculateMinimalNodalH(model_part);
    CONTACT_CHECK(minimum > 0.0, InputError, "CalculateRelativeSizeMesh: model part ", model_part.FullName(),
                  " has a node with NODAL_H ", minimum, "\n  expected: positive nodal sizes",
                  "\n  fix: run FindNodalHProcess on the model part first");
    return CalculateMaxNodalH(model_part) / minimum;
}

void ContactUtilities::ComputeStepJump(ModelPart& model_part, double delta_time, bool half_step) {
    const double velocity_factor = half_step ? 0.25 : 0.5;
    const double acceleration_factor = half_step ? 0.125 : 0.5;
    for (const auto& node : model_part.Nodes()) {
        CONTACT_CHECK(node->SolutionStepsDataHas(VELOCITY) && node->SolutionStepsDataHas(ACCELERATION), InputError,
                      "ComputeStepJump: node ", node->Id(), " of model part ", model_part.FullName(),
                      " does not store VELOCITY and ACCELERATION\n  fix: use a dynamic solver (it adds them) or",
                      " disable dynamic_search");
        const Array3& velocity = node->GetSolutionStepValue(VELOCITY, 0);
        const Array3& velocity_old = node->GetSolutionStepValue(VELOCITY, 1);
        const Array3& acceleration_old = node->GetSolutionStepValue(ACCELERATION, 1);
        Array3 jump = velocity_factor * delta_time * (velocity + velocity_old) +
                      acceleration_factor * delta_time * delta_time * acceleration_old;
        for (int c = 0; c < 3; ++c)
            if (IsDisplacementComponentPrescribed(*node, c)) jump[c] = 0.0;
        node->SetValue(DELTA_COORDINATES, jump);
    }
}

Array3 ContactUtilities::GetHalfJumpCenter(const Geometry& geometry) {
    Matrix local_nodes;
    geometry.PointsLocalCoordinates(local_nodes);
    Array3 local_center = Array3::Zero();
    for (int j = 0; j < local_nodes.cols(); ++j) local_center[j] = local_nodes.col(j).mean();
    Vector N;
    geometry.ShapeFunctionsValues(N, local_center);
    Array3 center = geometry.Center();
    for (std::size_t i = 0; i < geometry.size(); ++i) center += N[i] * geometry[i].GetValue(DELTA_COORDINATES);
    return center;
}

ModelPart* ContactUtilities::FindContactPart(ModelPart& model_part, const char* name) {
    ModelPart& root = model_part.GetRootModelPart();
    if (root.HasSubModelPart(name)) return &root.GetSubModelPart(name);
    if (model_part.HasSubModelPart(name)) return &model_part.GetSubModelPart(name);
    return nullptr;
}

bool ContactUtilities::CheckActivity(const ModelPart& model_part, bool throw_error) {
    const bool is_active = std::any_of(model_part.Nodes().begin(), model_part.Nodes().end(),
                                       [](const Node::Pointer& node) { return node->Is(SLAVE) && node->Is(ACTIVE); });
    CONTACT_CHECK(is_active || !throw_error, ConvergenceError, "CONTACT LOST: no SLAVE node of model part ",
                  model_part.FullName(), " is ACTIVE\n  fix: check the loads and supports (a body may have",
                  " separated), or the search parameters (search_factor, active_check_factor)");
    return is_active;
}

bool ContactUtilities::CheckModelPartHasRotationDoF(const ModelPart& model_part) {
    return std::any_of(model_part.Nodes().begin(), model_part.Nodes().end(), [](const Node::Pointer& node) {
        return node->HasDofFor(ROTATION_X) || node->HasDofFor(ROTATION_Y) || node->HasDofFor(ROTATION_Z);
    });
}

void ContactUtilities::CleanContactModelParts(ModelPart& model_part) {
    std::vector<IndexType> pairs;
    for (const auto& condition : model_part.Conditions())
        if (condition->GetGeometry().NumberOfGeometryParts() != 0) pairs.push_back(condition->Id());
    for (const IndexType id : pairs) model_part.RemoveCondition(id);
}

void ContactUtilities::ComputeExplicitContributionConditions(ModelPart& model_part) {
    for (const auto& condition : model_part.Conditions()) {
        Geometry& geometry = condition->GetGeometry();
        for (std::size_t i = 0; i < geometry.size(); ++i) ResetExplicitNodalValues(geometry[i]);
    }
    const ProcessInfo& process_info = model_part.GetProcessInfo();
    for (const auto& condition : model_part.Conditions()) condition->AddExplicitContribution(process_info);
}

void ContactUtilities::ResetExplicitNodalValues(Node& node) {
    ZeroNodal(node, WEIGHTED_GAP);
    ZeroNodal(node, WEIGHTED_SLIP);
    node.SetValue(NODAL_AREA, 0.0);
    node.SetValue(AREA_WEIGHTED_PAIR_GAP, 0.0);
    node.SetValue(SQUARED_PAIR_AREA, 0.0);
    node.SetValue(AREA_WEIGHTED_PAIR_SLIP, Array3(Array3::Zero()));
}

namespace {
/// |n_c| / |n| below which a plane c = const counts as containing the interface normal: the mean normal of a node on a
/// symmetry plane tilts by about half an element angle, h/(2R) (0.02 on the mirrored Hertz mesh).
constexpr double kSymmetryPlaneNormalTolerance = 0.1;
}  // namespace

std::vector<Dof*> ContactUtilities::FixSymmetryPlaneMultipliers(ModelPart& computing, const std::vector<Dof*>& fixed) {
    const Variable<double>* displacement[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
    for (Dof* dof : fixed) dof->FreeDof();
    // Per slave node and component c: bit c of .first = some pair has master nodes on the node's plane c = X_c, all
    // held in c; bit c of .second = some pair has such a master node that is free.
    std::unordered_map<Node*, std::pair<unsigned, unsigned>> planes;
    for (const auto& condition : computing.Conditions()) {
        Geometry& geometry = condition->GetGeometry();
        if (geometry.NumberOfGeometryParts() != 2) continue;
        Geometry& slave = geometry.GetGeometryPart(0);
        const Geometry& master = geometry.GetGeometryPart(1);
        double extent = 0.0;
        for (std::size_t l = 1; l < master.size(); ++l)
            extent = std::max(extent, (master[l].InitialCoordinates() - master[0].InitialCoordinates()).norm());
        const double tolerance = 1e-8 * extent;
        for (std::size_t j = 0; j < slave.size(); ++j) {
            Node& node = slave[j];
            auto& [held, free] = planes[&node];
            // Only stick rows constrain tangential components, and only a normal in the plane makes it a symmetry
            // plane (a roller under a sloped interface carries the normal traction's c part).
            if (!node.SolutionStepsDataHas(WEIGHTED_SLIP)) continue;
            const Array3& normal = node.FastGetSolutionStepValue(NORMAL);
            for (int c = 0; c < 3; ++c) {
                if (!node.IsFixed(*displacement[c]) || !node.HasDofFor(*kMultiplierComponents[c])) continue;
                if (std::abs(normal[c]) > kSymmetryPlaneNormalTolerance * normal.norm()) continue;
                for (std::size_t l = 0; l < master.size(); ++l) {
                    if (std::abs(master[l].InitialCoordinates()[c] - node.InitialCoordinates()[c]) > tolerance) continue;
                    if (master[l].IsFixed(*displacement[c]))
                        held |= 1u << c;
                    else
                        free |= 1u << c;
                }
            }
        }
    }
    std::vector<Dof*> result;
    for (const auto& [node, plane] : planes) {
        for (int c = 0; c < 3; ++c) {
            if (!(plane.first & ~plane.second & (1u << c))) continue;
            Dof& dof = node->GetDof(*kMultiplierComponents[c]);
            if (dof.IsFixed()) continue;  // fixed by the user
            dof.FixDof();
            node->FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER)[c] = 0.0;
            result.push_back(&dof);
        }
    }
    return result;
}

void ContactUtilities::ActivateConditionWithActiveNodes(ModelPart& model_part) {
    for (const auto& condition : model_part.Conditions()) {
        const Geometry& geometry = condition->GetGeometry();
        const Geometry& slave = geometry.NumberOfGeometryParts() != 0 ? geometry.GetGeometryPart(0) : geometry;
        bool is_active = false;
        for (std::size_t i = 0; i < slave.size(); ++i) is_active = is_active || slave[i].Is(ACTIVE);
        condition->Set(ACTIVE, is_active);
    }
}

void ContactUtilities::ScaleNode(Array3& point, const Array3& normal, double length) {
    point += normal * length;
}

std::map<IndexType, std::vector<std::pair<std::size_t, int>>> ContactUtilities::SharedSlaveNodes(
    const std::vector<const Condition*>& pairs) {
    std::map<IndexType, std::vector<std::pair<std::size_t, int>>> nodes;
    for (std::size_t p = 0; p < pairs.size(); ++p) {
        const Geometry& slave = pairs[p]->GetGeometry();
        for (std::size_t j = 0; j < slave.size(); ++j) nodes[slave[j].Id()].emplace_back(p, static_cast<int>(j));
    }
    for (auto it = nodes.begin(); it != nodes.end();) it = it->second.size() < 2 ? nodes.erase(it) : std::next(it);
    return nodes;
}

double ContactUtilities::DistancePoints(const Array3& a, const Array3& b) {
    return (a - b).norm();
}

}  // namespace contact_app
