// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/normal_check_process.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/face_checks.h"
#include "contact_app/kernel/model_part.h"

namespace contact_app {

namespace {

/// The root element holding every node of @p geometry, or nullptr.
const Element* ParentElement(const Geometry& geometry,
                             const std::unordered_map<const Node*, std::vector<const Element*>>& elements_of_node) {
    const auto candidates = elements_of_node.find(&geometry[0]);
    if (candidates == elements_of_node.end()) return nullptr;
    for (const Element* element : candidates->second) {
        const auto& points = element->GetGeometry().Points();
        const bool holds_all = std::all_of(geometry.Points().begin(), geometry.Points().end(), [&](const Node::Pointer& node) {
            return std::find(points.begin(), points.end(), node) != points.end();
        });
        if (holds_all) return element;
    }
    return nullptr;
}

/// Model parts (root and below) that hold the condition @p id.
void PartsHolding(ModelPart& part, IndexType id, std::vector<ModelPart*>& holders) {
    if (part.HasCondition(id)) holders.push_back(&part);
    for (ModelPart* child : part.SubModelParts()) PartsHolding(*child, id, holders);
}

/// Rebuilds @p condition with the reversed node order and puts it in place of the old one everywhere.
void FlipCondition(ModelPart& root, const Condition::Pointer& condition) {
    Geometry::PointsArrayType points = condition->GetGeometry().Points();
    // A line swaps its nodes; a polygon keeps node 0 and reverses the rest.
    if (points.size() == 2) std::swap(points[0], points[1]);
    else std::reverse(points.begin() + 1, points.end());
    auto flipped = condition->Create(condition->Id(), points, condition->pGetProperties());
    static_cast<Flags&>(*flipped) = static_cast<const Flags&>(*condition);
    static_cast<DataValueHolder&>(*flipped) = static_cast<const DataValueHolder&>(*condition);
    flipped->Set(MARKER, true);
    std::vector<ModelPart*> holders;
    PartsHolding(root, condition->Id(), holders);
    root.RemoveCondition(condition->Id());
    for (ModelPart* part : holders) part->AddCondition(flipped);
}

}  // namespace

NormalCheckProcess::NormalCheckProcess(ModelPart& model_part, double length_proportion, double check_threshold)
    : mrModelPart(model_part), mLengthProportion(length_proportion), mCheckThreshold(check_threshold) {
    CONTACT_CHECK(length_proportion > 0.0 && std::isfinite(length_proportion), InputError,
                  "NormalCheckProcess: length_proportion is ", length_proportion,
                  "\n  expected: a positive fraction of the condition size (default 0.1)",
                  "\n  fix: set normal_check_proportion to e.g. 0.1");
    CONTACT_CHECK(check_threshold >= 0.0 && std::isfinite(check_threshold), InputError,
                  "NormalCheckProcess: check_threshold is ", check_threshold,
                  "\n  expected: a finite tolerance >= 0 (default 5e-7)");
}

void NormalCheckProcess::Execute() {
    ModelPart& root = mrModelPart.GetRootModelPart();
    std::unordered_map<const Node*, std::vector<const Element*>> elements_of_node;
    for (const auto& element : root.Elements()) {
        const Geometry& geometry = element->GetGeometry();
        for (std::size_t i = 0; i < geometry.size(); ++i) elements_of_node[&geometry[i]].push_back(element.get());
    }
    std::vector<Condition::Pointer> inverted;
    for (const auto& condition : mrModelPart.Conditions()) {
        const Geometry& geometry = condition->GetGeometry();
        if (geometry.NumberOfGeometryParts() != 0) continue;
        if (geometry.LocalSpaceDimension() + 1 != geometry.WorkingSpaceDimension()) continue;  // not a face
        const Element* parent = ParentElement(geometry, elements_of_node);
        if (parent == nullptr) continue;
        Matrix local_nodes;
        geometry.PointsLocalCoordinates(local_nodes);
        Array3 local_center = Array3::Zero();
        for (int j = 0; j < local_nodes.cols(); ++j) local_center[j] = local_nodes.col(j).mean();
        const double size = geometry.LocalSpaceDimension() == 1 ? geometry.Length() : std::sqrt(geometry.Area());
        const Array3 probe = geometry.Center() + mLengthProportion * size * ConditionUnitNormal(*condition, mrModelPart, local_center);
        Array3 local;
        if (parent->GetGeometry().IsInside(probe, local, mCheckThreshold)) inverted.push_back(condition);
    }
    for (const auto& condition : inverted) FlipCondition(root, condition);
    mNumberOfFlipped = inverted.size();
}

}  // namespace contact_app
