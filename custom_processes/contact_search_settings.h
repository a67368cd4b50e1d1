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
/// @param[in] name the spelling to decode
/// @param[in] where the settings block, for the message (a JSON path)
/// @throws InputError listing the valid spellings (no silent fallback, unlike the reference)
SearchTreeType ParseSearchTreeType(const std::string& name, const std::string& where = "search_parameters");
/// @brief CheckGap from "no_check" / "direct_check" / "check_mapping" or "NoCheck" / "DirectCheck" /
///        "MappingCheck". @throws InputError listing the valid spellings
CheckGap ParseCheckGap(const std::string& name, const std::string& where = "search_parameters");
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
    /// @param[in] where the settings block, for the messages (a JSON path)
    /// @throws InputError naming the setting, its value and the expected range
    void Validate(const std::string& where = "search_parameters") const;
};

/// Calls visit(key, member) for every settings key (member: a pointer to the ContactSearchSettings field), the one
/// list the Python binding reads for its properties and its keyword / dict assignment. The search_parameters
/// block of a contact process names allocation_size "max_number_results" and nests the octree keys in
/// "octree_search_parameters".
template <class TVisit>
void ForEachSearchSetting(TVisit&& visit) {
    using S = ContactSearchSettings;
    visit("allocation_size", &S::allocation_size);
    visit("bucket_size", &S::bucket_size);
    visit("search_factor", &S::search_factor);
    visit("type_search", &S::type_search);
    visit("check_gap", &S::check_gap);
    visit("simple_search", &S::simple_search);
    visit("condition_name", &S::condition_name);
    visit("final_string", &S::final_string);
    visit("id_name", &S::id_name);
    visit("inverted_search", &S::inverted_search);
    visit("dynamic_search", &S::dynamic_search);
    visit("static_check_movement", &S::static_check_movement);
    visit("predefined_master_slave", &S::predefined_master_slave);
    visit("normal_orientation_threshold", &S::normal_orientation_threshold);
    visit("consider_gap_threshold", &S::consider_gap_threshold);
    visit("predict_correct_lagrange_multiplier", &S::predict_correct_lagrange_multiplier);
    visit("pure_slip", &S::pure_slip);
    visit("debug_mode", &S::debug_mode);
    visit("bounding_box_factor", &S::bounding_box_factor);
    visit("debug_obb", &S::debug_obb);
    visit("OBB_intersection_type", &S::OBB_intersection_type);
    visit("build_from_bounding_box", &S::build_from_bounding_box);
    visit("lower_bounding_box_coefficient", &S::lower_bounding_box_coefficient);
    visit("higher_bounding_box_coefficient", &S::higher_bounding_box_coefficient);
}

}  // namespace contact_app
