// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace contact_app {

class ModelPart;

/// Nodal characteristic length (Kratos FindNodalHProcess): NODAL_H of a node = the shortest distance between
/// two nodes of an element around it (every node pair of the element, as the reference; for the usual convex
/// elements this is the shortest adjacent edge). Nodes without an element use the non-paired conditions around
/// them; isolated nodes get 0. Written to the historical NODAL_H when the model part stores it (the contact
/// solvers declare it), else to the node's non-historical value; ContactUtilities::NodalH reads it back the same
/// way. Current coordinates are used (as the reference; the processes run it before the first step).
class FindNodalHProcess {
public:
    /// @param[in,out] model_part nodes and elements to scan (kept by reference; must outlive the process)
    explicit FindNodalHProcess(ModelPart& model_part) : mrModelPart(model_part) {}
    /// @brief Computes NODAL_H on every node of the model part.
    void Execute();

private:
    ModelPart& mrModelPart;
};

}  // namespace contact_app
