// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/face_checks.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include <Eigen/Geometry>

#include "contact_app/kernel/exceptions.h"

namespace contact_app {

namespace {

/// Number of corner nodes of a face (the first nodes in Kratos ordering).
std::size_t CornerCount(const Geometry& geometry) {
    if (geometry.LocalSpaceDimension() == 1) return 2;
    return geometry.size() == 3 || geometry.size() == 6 ? 3 : 4;
}

/// Corner @p k in the working space (z dropped in 2D).
Array3 Corner(const Geometry& geometry, std::size_t k) {
    Array3 x = geometry[k].Coordinates();
    if (geometry.WorkingSpaceDimension() == 2) x[2] = 0.0;
    return x;
}

}  // namespace

std::string DegenerateFaceReason(const Geometry& geometry) {
    const int local_dim = geometry.LocalSpaceDimension();
    if ((local_dim != 1 && local_dim != 2) || local_dim + 1 != geometry.WorkingSpaceDimension()) return "";
    const std::size_t corners = std::min(CornerCount(geometry), geometry.size());
    double longest = 0.0;
    for (std::size_t i = 0; i < corners; ++i)
        for (std::size_t j = i + 1; j < corners; ++j)
            longest = std::max(longest, (Corner(geometry, j) - Corner(geometry, i)).norm());
    double measure = 0.0;
    if (local_dim == 1) {
        measure = longest;
    } else if (corners == 3) {
        measure = 0.5 * (Corner(geometry, 1) - Corner(geometry, 0)).cross(Corner(geometry, 2) - Corner(geometry, 0)).norm();
    } else {  // vector area of a quadrilateral from its diagonals
        measure = 0.5 * (Corner(geometry, 2) - Corner(geometry, 0)).cross(Corner(geometry, 3) - Corner(geometry, 1)).norm();
    }
    if (local_dim == 1 ? measure > 0.0 : measure > 1e-12 * longest * longest) return "";

    std::ostringstream reason;
    reason << (local_dim == 1 ? "zero length: " : "zero area: ");
    for (std::size_t i = 0; i < corners; ++i) {
        for (std::size_t j = i + 1; j < corners; ++j) {
            if (geometry[i].Id() == geometry[j].Id()) {
                reason << "node " << geometry[i].Id() << " is listed twice";
                return reason.str();
            }
        }
    }
    for (std::size_t i = 0; i < corners; ++i) {
        for (std::size_t j = i + 1; j < corners; ++j) {
            if ((Corner(geometry, j) - Corner(geometry, i)).norm() == 0.0) {
                reason << "nodes " << geometry[i].Id() << " and " << geometry[j].Id() << " are at the same point";
                if (local_dim == 1 && geometry[i].Coordinates() != geometry[j].Coordinates()) reason << " in the x-y plane";
                return reason.str();
            }
        }
    }
    reason << (corners == 3 ? "its corners are collinear" : "its corners are collinear or the face crosses itself");
    return reason.str();
}

std::string ModelPartsHoldingCondition(const ModelPart& model_part, IndexType id) {
    const ModelPart& root = model_part.GetRootModelPart();
    std::vector<std::string> names;
    // A part is listed when it holds the condition and none of its sub model parts does.
    std::function<bool(const ModelPart&)> visit = [&](const ModelPart& part) {
        if (!part.HasCondition(id)) return false;
        bool in_child = false;
        for (const ModelPart* sub : part.SubModelParts()) in_child = visit(*sub) || in_child;
        if (!in_child) names.push_back(part.FullName());
        return true;
    };
    visit(root);
    if (names.empty()) names.push_back(model_part.FullName());
    std::string text = names.size() == 1 ? "model part " : "model parts ";
    for (std::size_t i = 0; i < names.size(); ++i) text += (i > 0 ? ", \"" : "\"") + names[i] + "\"";
    return text;
}

void ThrowDegenerateFace(const Condition& condition, const ModelPart& model_part, const std::string& reason,
                         const std::string& location) {
    const Geometry& geometry = condition.GetGeometry();
    CONTACT_THROW(InputError, location, "condition ", condition.Id(), " (", geometry.Name(), " with nodes ",
                  geometry.NodeIdsString(), ") of ", ModelPartsHoldingCondition(model_part, condition.Id()),
                  " is a degenerate face, ", reason,
                  "\n  expected: a line of non-zero length or a face of non-zero area, so that its normal is defined",
                  "\n  fix:      correct the node ids of the condition, or remove it from the mesh");
}

Array3 ConditionUnitNormal(const Condition& condition, const ModelPart& model_part, const Array3& local) {
    const Geometry& geometry = condition.GetGeometry();
    const Array3 normal = geometry.Normal(local);
    const double norm = normal.norm();
    if (norm > 0.0 && std::isfinite(norm)) return normal / norm;
    std::string reason = DegenerateFaceReason(geometry);
    if (reason.empty()) {
        std::ostringstream text;
        text << (std::isfinite(norm) ? "zero normal" : "non-finite normal") << " at local point (" << local[0] << ", "
             << local[1] << ", " << local[2] << ") (a collapsed corner, or a 2D line along z)";
        reason = text.str();
    }
    ThrowDegenerateFace(condition, model_part, reason);
}

}  // namespace contact_app
