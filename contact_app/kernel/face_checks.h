// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "contact_app/kernel/condition.h"
#include "contact_app/kernel/model_part.h"

namespace contact_app {

// Checks of the faces contact and normals are computed on: a line in 2D or a surface in 3D
// (LocalSpaceDimension = WorkingSpaceDimension - 1). A degenerate face has no normal.

/// Why @p geometry is a degenerate face ("zero length: node 3 is listed twice", "zero area: its
/// corners are collinear", ...), or "" if it has a non-zero measure or is not a face. Judged on the
/// corner nodes: a length of exactly 0 (in the working space), an area below 1e-12 times the
/// square of the longest corner distance. O(nodes²), no allocation unless degenerate.
std::string DegenerateFaceReason(const Geometry& geometry);

/// `model part "Structure.Contact_Part"` (or `model parts "A", "B"`): the deepest model parts
/// under the root of @p model_part that hold condition @p id, else the root.
std::string ModelPartsHoldingCondition(const ModelPart& model_part, IndexType id);

/// @brief Throws the InputError for a degenerate face condition.
/// @param[in] condition the degenerate face condition (its Id and node Ids go into the message)
/// @param[in] model_part a model part of the same tree, to name the model parts that hold @p condition
/// @param[in] location prefix for the message (`"mesh.mdpa:56: "`), may be empty.
/// @param[in] reason as returned by DegenerateFaceReason.
[[noreturn]] void ThrowDegenerateFace(const Condition& condition, const ModelPart& model_part, const std::string& reason,
                                      const std::string& location = "");

/// @brief Unit normal of @p condition's geometry at @p local.
/// @throws InputError naming the condition, its model parts and why, if the normal is zero.
Array3 ConditionUnitNormal(const Condition& condition, const ModelPart& model_part, const Array3& local);

}  // namespace contact_app
