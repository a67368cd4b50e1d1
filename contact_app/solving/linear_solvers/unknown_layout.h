// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>
#include <string>
#include <cstddef>
#include <vector>

namespace contact_app {

class Dof;
class ModelPart;

/// What each unknown of a system is, for solvers that need the physics behind the equations (the
/// rigid-body near-null space of algebraic multigrid; docs/running.md, "Iterative solver (PETSc)").
struct UnknownLayout {
    int dimension = 0;               ///< 2 or 3 (from the displacement DoFs present); 0 = no displacements
    std::vector<int> node;           ///< node id per unknown (0 = none)
    std::vector<int> component;      ///< displacement component 0..dimension-1, or -1 (multipliers, others)
    std::vector<std::array<double, 3>> coordinates;  ///< current coordinates of the unknown's node
    const ModelPart* model_part = nullptr;  ///< for messages (STEP, TIME, NL_ITERATION_NUMBER); may be null

    std::size_t size() const { return component.size(); }
    /// The layout of the unknowns @p kept (positions in this layout), in that order.
    UnknownLayout Subset(const std::vector<int>& kept) const;
};

/// The layout of a system of @p size equations from the builder's DoF set (equation id = position;
/// DoFs with an id ≥ size, the fixed ones of the elimination builder, are skipped).
UnknownLayout UnknownLayoutFromDofs(const std::vector<Dof*>& rDofSet, std::size_t size, const ModelPart& rModelPart);

/// "step 3 (TIME 0.3), Newton iteration 2" from the model part, "" without one.
std::string NewtonStepText(const ModelPart* pModelPart);

}  // namespace contact_app
