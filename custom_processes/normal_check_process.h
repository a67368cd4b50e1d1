// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>

namespace contact_app {

class ModelPart;

/// Detects interface conditions whose normal points into their parent element and flips them (Kratos
/// NormalCheckProcess). For every non-paired condition of dimension d − 1, the parent is the root element that
/// holds all its nodes; the condition centre is moved by length_proportion × L along the unit normal (L = length
/// in 2D, √area in 3D) and, if the moved point is inside the parent (IsInside with tolerance check_threshold),
/// the condition is rebuilt with its node order reversed (same id, properties, flags and values; MARKER set) in
/// every model part that held it. Only the condition pass of the reference is done (no nodal pass): nodal
/// normals are recomputed afterwards by ComputeNodesMeanNormalModelPart.
class NormalCheckProcess {
public:
    /// @param[in,out] model_part conditions to check (kept by reference; must outlive the process)
    /// @param[in] length_proportion offset of the probe point, as a fraction of the condition size (> 0)
    /// @param[in] check_threshold tolerance of the inside test, in local coordinates
    /// @throws InputError if length_proportion is not positive
    explicit NormalCheckProcess(ModelPart& model_part, double length_proportion = 0.1, double check_threshold = 5.0e-7);
    /// @brief Checks every condition and flips the inverted ones.
    void Execute();
    /// @brief How many conditions the last Execute() flipped.
    std::size_t NumberOfFlippedConditions() const { return mNumberOfFlipped; }

private:
    ModelPart& mrModelPart;
    double mLengthProportion;
    double mCheckThreshold;
    std::size_t mNumberOfFlipped = 0;
};

}  // namespace contact_app
