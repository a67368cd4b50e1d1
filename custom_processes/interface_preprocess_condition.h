// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "contact_app/kernel/types.h"

namespace contact_app {

class ModelPart;

/// Builds the interface (skin) conditions of a contact part from the elements of the main model part (Kratos
/// InterfacePreprocessCondition). A face of a root element is a boundary face when no other root element has
/// the same node set; it becomes a geometry-only condition LineCondition2D2N (2D) or SurfaceCondition3D3N / 4N
/// (3D), with the element's face node order so that its normal points out of the body (reversed for an inverted
/// element). New condition ids continue after the root's largest one; INTERFACE is set on the nodes and the
/// conditions, and a condition whose nodes are all SLAVE (all MASTER) is flagged SLAVE (MASTER).
/// Linear elements only (Triangle2D3, Quadrilateral2D4, Tetrahedra3D4, Hexahedra3D8, Prism3D6); quadratic ones
/// are an InputError unless simplify_geometry, which keeps their corner nodes.
class InterfacePreprocessCondition {
public:
    /// @param[in,out] main_model_part the body model part whose root elements are scanned (kept by reference)
    explicit InterfacePreprocessCondition(ModelPart& main_model_part) : mrMainModelPart(main_model_part) {}

    /// @brief Creates a condition on every boundary face whose nodes all belong to @p interface_part and adds it to
    ///        @p interface_part (and so to its ancestors). Faces already covered by a condition of the part, or
    ///        by an INTERFACE condition of the root (an earlier call), are reused: added to the part, flags set,
    ///        nothing duplicated, so the call is idempotent.
    /// @param[in,out] interface_part a sub model part of the main model part holding the interface nodes
    /// @param[in] simplify_geometry quadratic elements: build linear conditions on the corner nodes
    /// @param[in] contact_property_id properties of the new conditions; 0 = the parent element's properties
    /// @return the number of conditions created
    /// @throws InputError for quadratic or unsupported elements (without simplify_geometry)
    std::size_t GenerateInterfacePart(ModelPart& interface_part, bool simplify_geometry = false,
                                      IndexType contact_property_id = 0);

    /// @brief Skin of the whole main model part (every boundary face) into @p destination_part, for contact
    ///        without interface lists (Kratos SkinDetectionProcess + generate pair); nodes are added too.
    /// @param[in,out] destination_part a sub model part of the main model part (e.g. Contact.ContactSub0)
    /// @param[in] contact_property_id as GenerateInterfacePart
    /// @return the number of conditions created
    std::size_t GenerateSkinModelPart(ModelPart& destination_part, IndexType contact_property_id = 0);

private:
    std::size_t Generate(ModelPart& part, bool whole_skin, bool simplify_geometry, IndexType contact_property_id);

    ModelPart& mrMainModelPart;
};

}  // namespace contact_app
