// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/interface_preprocess_condition.h"

#include <algorithm>
#include <map>
#include <set>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/model_part.h"

namespace contact_app {

namespace {

using FaceKey = std::vector<IndexType>;

/// One element face, nodes in outward order (corner nodes only).
struct ElementFace {
    std::vector<Node::Pointer> nodes;
    const Element* parent;
};

FaceKey SortedIds(const std::vector<Node::Pointer>& nodes) {
    FaceKey key;
    for (const auto& node : nodes) key.push_back(node->Id());
    std::sort(key.begin(), key.end());
    return key;
}

FaceKey SortedIds(const Geometry& geometry) {
    return SortedIds(geometry.Points());
}

bool IsLinearSolid(const std::string& name) {
    static const std::set<std::string> linear = {"Triangle2D3", "Quadrilateral2D4", "Tetrahedra3D4", "Hexahedra3D8",
                                                 "Prism3D6"};
    return linear.count(name) != 0;
}

bool IsQuadraticSolid(const std::string& name) {
    return name == "Triangle2D6" || name == "Tetrahedra3D10";
}

/// Corner count of a face of @p face_size nodes (quadratic faces list the corners first).
std::size_t FaceCorners(int dimension, std::size_t face_size) {
    if (dimension == 2) return 2;
    if (face_size == 6) return 3;
    if (face_size == 8 || face_size == 9) return 4;
    return face_size;
}

/// Reverses a line (swap) or a polygon (keep the first node, reverse the rest).
void ReverseOrientation(std::vector<Node::Pointer>& nodes) {
    if (nodes.size() == 2) std::swap(nodes[0], nodes[1]);
    else std::reverse(nodes.begin() + 1, nodes.end());
}

/// Every face of the root's solid elements, with how many elements share its node set.
void CollectFaces(const ModelPart& root, bool simplify_geometry, std::vector<ElementFace>& faces,
                  std::map<FaceKey, int>& multiplicity) {
    for (const auto& element : root.Elements()) {
        const Geometry& geometry = element->GetGeometry();
        const int dimension = geometry.WorkingSpaceDimension();
        if (geometry.LocalSpaceDimension() != dimension) continue;  // shells, beams, trusses have no solid skin
        const std::string name = geometry.Name();
        CONTACT_CHECK(IsLinearSolid(name) || (simplify_geometry && IsQuadraticSolid(name)), InputError,
                      "InterfacePreprocessCondition: element ", element->Id(), " of model part ", root.Name(),
                      " has geometry ", name, "\n  expected: a linear solid (Triangle2D3, Quadrilateral2D4,",
                      " Tetrahedra3D4, Hexahedra3D8, Prism3D6)",
                      IsQuadraticSolid(name) ? "\n  fix: pass simplify_geometry=True to build linear interface"
                                               " conditions on the corner nodes, or use linear elements"
                                             : "\n  fix: mesh the contact bodies with linear solid elements");
        const bool inverted = geometry.DomainSize() < 0.0;  // faces of an inverted element point inwards
        for (const auto& local_face : geometry.LocalFacesConnectivity()) {
            ElementFace face{{}, element.get()};
            const std::size_t corners = FaceCorners(dimension, local_face.size());
            for (std::size_t i = 0; i < corners; ++i) face.nodes.push_back(geometry.pGetPoint(local_face[i]));
            if (inverted) ReverseOrientation(face.nodes);
            ++multiplicity[SortedIds(face.nodes)];
            faces.push_back(std::move(face));
        }
    }
}

void SetInterfaceFlags(Condition& condition) {
    Geometry& geometry = condition.GetGeometry();
    bool all_slave = true, all_master = true;
    for (std::size_t i = 0; i < geometry.size(); ++i) {
        geometry[i].Set(INTERFACE, true);
        all_slave = all_slave && geometry[i].Is(SLAVE);
        all_master = all_master && geometry[i].Is(MASTER);
    }
    condition.Set(INTERFACE, true);
    if (all_slave) {
        condition.Set(SLAVE, true);
        condition.Set(MASTER, false);
    } else if (all_master) {
        condition.Set(MASTER, true);
        condition.Set(SLAVE, false);
    }
}

}  // namespace

std::size_t InterfacePreprocessCondition::GenerateInterfacePart(ModelPart& interface_part, bool simplify_geometry,
                                                                IndexType contact_property_id) {
    return Generate(interface_part, false, simplify_geometry, contact_property_id);
}

std::size_t InterfacePreprocessCondition::GenerateSkinModelPart(ModelPart& destination_part,
                                                                IndexType contact_property_id) {
    return Generate(destination_part, true, false, contact_property_id);
}

std::size_t InterfacePreprocessCondition::Generate(ModelPart& part, bool whole_skin, bool simplify_geometry,
                                                   IndexType contact_property_id) {
    ModelPart& root = mrMainModelPart.GetRootModelPart();
    CONTACT_CHECK(&part.GetRootModelPart() == &root, InputError, "InterfacePreprocessCondition: model part ",
                  part.FullName(), " is not part of ", root.Name(), "\n  fix: pass a sub model part of the main model part");
    std::vector<ElementFace> faces;
    std::map<FaceKey, int> multiplicity;
    CollectFaces(root, simplify_geometry, faces, multiplicity);

    // Reusable: the part's own conditions and the interface conditions built before (e.g. by another pair).
    std::map<FaceKey, Condition::Pointer> existing;
    for (const auto& condition : root.Conditions())
        if (condition->GetGeometry().NumberOfGeometryParts() == 0 &&
            (condition->Is(INTERFACE) || part.HasCondition(condition->Id())))
            existing.emplace(SortedIds(condition->GetGeometry()), condition);

    IndexType next_id = root.Conditions().MaxId();
    std::size_t created = 0;
    for (const ElementFace& face : faces) {
        const FaceKey key = SortedIds(face.nodes);
        if (multiplicity.at(key) != 1) continue;  // shared by two elements: inside the mesh
        if (!whole_skin && !std::all_of(key.begin(), key.end(), [&](IndexType id) { return part.HasNode(id); }))
            continue;
        const auto found = existing.find(key);
        if (found != existing.end()) {
            part.AddCondition(found->second);
            if (whole_skin) part.AddNodes(key);
            SetInterfaceFlags(*found->second);
            continue;
        }
        std::vector<IndexType> ids;
        for (const auto& node : face.nodes) ids.push_back(node->Id());
        const bool is_line = face.nodes.size() == 2;
        const char* name = is_line ? "LineCondition2D2N"
                                   : (face.nodes.size() == 3 ? "SurfaceCondition3D3N" : "SurfaceCondition3D4N");
        Properties::Pointer properties =
            contact_property_id != 0 ? root.pGetProperties(contact_property_id) : face.parent->pGetProperties();
        if (whole_skin) part.AddNodes(ids);
        auto condition = part.CreateNewCondition(name, ++next_id, ids, properties);
        SetInterfaceFlags(*condition);
        existing.emplace(key, condition);
        ++created;
    }
    return created;
}

}  // namespace contact_app
