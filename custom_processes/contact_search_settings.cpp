// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/contact_search_settings.h"

#include <array>
#include <utility>
#include <vector>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/string_utilities.h"

namespace contact_app {
namespace {

/// {Python spelling, C++ spelling, value}.
template <class TEnum>
struct Spelling {
    const char* python;
    const char* cpp;
    TEnum value;
};

constexpr std::array<Spelling<SearchTreeType>, 5> kSearchTypes{{
    {"in_radius", "InRadius", SearchTreeType::InRadius},
    {"in_box", "InBox", SearchTreeType::InBox},
    {"in_radius_with_obb", "InRadiusWithOBB", SearchTreeType::InRadiusWithOBB},
    {"in_box_with_obb", "InBoxWithOBB", SearchTreeType::InBoxWithOBB},
    {"octree_with_obb", "OctreeWithOBB", SearchTreeType::OctreeWithOBB},
}};

constexpr std::array<Spelling<CheckGap>, 3> kCheckGaps{{
    {"no_check", "NoCheck", CheckGap::NoCheck},
    {"direct_check", "DirectCheck", CheckGap::DirectCheck},
    {"check_mapping", "MappingCheck", CheckGap::MappingCheck},
}};

template <class TEnum, std::size_t N>
TEnum Parse(const std::array<Spelling<TEnum>, N>& table, const std::string& name, const char* key,
            const std::string& where) {
    std::vector<std::string> valid;
    for (const auto& row : table) {
        if (name == row.python || name == row.cpp) return row.value;
        valid.emplace_back(row.python);
        valid.emplace_back(row.cpp);
    }
    CONTACT_THROW(InputError, "contact search: unknown ", key, " \"", name, "\"",
                  "\n  where:    ", where, " › ", key, "\n  expected: one of ", QuotedList(valid),
                  DidYouMean(name, valid));
}

template <class TEnum, std::size_t N>
std::string Name(const std::array<Spelling<TEnum>, N>& table, TEnum value) {
    for (const auto& row : table)
        if (row.value == value) return row.python;
    return "?";
}

}  // namespace

SearchTreeType ParseSearchTreeType(const std::string& name, const std::string& where) {
    return Parse(kSearchTypes, name, "type_search", where);
}
CheckGap ParseCheckGap(const std::string& name, const std::string& where) {
    return Parse(kCheckGaps, name, "check_gap", where);
}
std::string SearchTreeTypeName(SearchTreeType type) { return Name(kSearchTypes, type); }
std::string CheckGapName(CheckGap check) { return Name(kCheckGaps, check); }

void ContactSearchSettings::Validate(const std::string& where) const {
    const auto positive = [&where](bool ok, const char* key, auto value, const char* expected) {
        CONTACT_CHECK(ok, InputError, "contact search: ", key, " = ", value, " is out of range",
                      "\n  where:    ", where, " › ", key, "\n  expected: ", expected);
    };
    positive(allocation_size > 0, "allocation_size", allocation_size, "≥ 1 (the maximum candidates per face)");
    positive(bucket_size > 0, "bucket_size", bucket_size, "≥ 1 (points per tree leaf, default 4)");
    positive(search_factor > 0.0, "search_factor", search_factor, "> 0 (default 3.5)");
    positive(normal_orientation_threshold >= 0.0, "normal_orientation_threshold", normal_orientation_threshold,
             "≥ 0 (default 0.1)");
    positive(bounding_box_factor >= 0.0, "bounding_box_factor", bounding_box_factor, "≥ 0 (default 0.1)");
    CONTACT_CHECK(OBB_intersection_type == "SeparatingAxisTheorem", InputError,
                  "contact search: OBB_intersection_type \"", OBB_intersection_type, "\" is not supported",
                  "\n  where:    ", where, " › octree_search_parameters › OBB_intersection_type",
                  "\n  expected: \"SeparatingAxisTheorem\"");
}

}  // namespace contact_app
