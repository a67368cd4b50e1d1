// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <string>

namespace contact_app {

/// Broad/narrow phase of the contact search (Kratos SearchTreeType; KDOP is not provided).
enum class SearchTreeType { InRadius, InBox, InRadiusWithOBB, InBoxWithOBB, OctreeWithOBB };
/// How the search decides which slave nodes are in contact (Kratos CheckGap).
enum class CheckGap { NoCheck, DirectCheck, MappingCheck };

/// @brief SearchTreeType from its Python ("in_radius", ...) or C++ ("InRadius", ...) spelling.
/// @throws InputError listing the valid spellings (no silent fallback, unlike the reference)
SearchTreeType ParseSearchTreeType(const std::string& name);
/// @brief CheckGap from "no_check" / "direct_check" / "check_mapping" or "NoCheck" / "DirectCheck" /
///        "MappingCheck". @throws InputError listing the valid spellings
CheckGap ParseCheckGap(const std::string& name);
/// The Python spelling ("in_radius_with_obb", "check_mapping", ...).
std::string SearchTreeTypeName(SearchTreeType type);
std::string CheckGapName(CheckGap check);

/// Settings of ContactSearchProcess / MPCContactSearchProcess (docs/theory/contact_search.md §5; defaults of the
/// reference's C++ process, which the Python SearchBaseProcess overrides with its own).
struct ContactSearchSettings {
    std::size_t allocation_size = 1000;  ///< max candidates per slave face (Python max_number_results)
    std::size_t bucket_size = 4;         ///< points per kd-tree leaf
    double search_factor = 3.5;          ///< search radius / box size as a multiple of the face size
    SearchTreeType type_search = SearchTreeType::InRadius;
    CheckGap check_gap = CheckGap::MappingCheck;
    bool simple_search = false;          ///< gap-only activation (Kratos SimpleContactSearchProcess)
    std::string condition_name;          ///< stem, e.g. "ALMFrictionlessMortarContact"; "" = record pairs only
    std::string final_string;            ///< suffix after the node count, e.g. "4N" (3D3N4N)
    std::string id_name;                 ///< pair key: sub parts ContactSub<id>, ComputingContactSub<id>
    bool inverted_search = false;        ///< swap the slave and master roles
    bool dynamic_search = false;         ///< search at VELOCITY·DELTA_TIME-predicted positions
    bool static_check_movement = false;
    bool predefined_master_slave = true; ///< false: self contact, the search assigns the roles
    double normal_orientation_threshold = 0.1;  ///< pairs need |n_slave − n_master| ≥ this (+1e−16)
    bool consider_gap_threshold = false;
    bool predict_correct_lagrange_multiplier = false;
    bool pure_slip = false;
    bool debug_mode = false;
    // octree_search_parameters
    double bounding_box_factor = 0.1;    ///< OBB half-thickness = factor × max NODAL_H of the contact part
    bool debug_obb = false;
    std::string OBB_intersection_type = "SeparatingAxisTheorem";
    bool build_from_bounding_box = true;
    double lower_bounding_box_coefficient = 0.0;
    double higher_bounding_box_coefficient = 1.0;

    /// @brief Checks ranges and the OBB intersection type.
    /// @throws InputError naming the setting, its value and the expected range
    void Validate() const;
};

}  // namespace contact_app
