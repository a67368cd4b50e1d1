// SPDX-License-Identifier: BSD-3-Clause
/// Fixtures shared by the solid-element tests: registered names × compatible laws, a small model with the
/// structural variables, distorted single elements, deformation states, finite-difference tangents and
/// patch meshes.
#pragma once

#include <cstddef>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "contact_app/kernel/constitutive_law.h"
#include "contact_app/kernel/model.h"
#include "contact_app/kernel/variables.h"
#include "tests/cpp/error_test_utilities.h"

namespace contact_app::testing {

enum class Formulation { SmallDisplacement, TotalLagrangian, UpdatedLagrangian };

/// What a registered solid-element name says about its class.
struct ElementInfo {
    std::string name;      ///< registered name
    std::string family;    ///< canonical family, e.g. "AxisymTotalLagrangianElement"
    std::string geometry;  ///< geometry of the registered prototype
    int dimension = 0;
    std::size_t nodes = 0;
    Formulation formulation = Formulation::SmallDisplacement;
    bool axisymmetric = false;
    bool alias = false;  ///< a second spelling of an axisymmetric name
    int strain_size = 0;
};

/// Registers variables, laws and solid elements (idempotent).
void RegisterForSolidTests();
/// Every registered solid element, parsed from its name; aliases only if @p include_aliases.
std::vector<ElementInfo> SolidElements(bool include_aliases = false);
/// Registered law names with the dimension and strain size of @p element.
std::vector<std::string> CompatibleLaws(const ElementInfo& element);

struct ElementLawCase {
    ElementInfo element;
    std::string law;
};
/// Every canonical solid element × every compatible registered law.
std::vector<ElementLawCase> ElementLawCases();
std::string CaseName(const ::testing::TestParamInfo<ElementLawCase>& info);
/// gtest printers (names instead of bytes in failure messages).
inline void PrintTo(const ElementInfo& info, std::ostream* os) {
    *os << info.name;
}
inline void PrintTo(const ElementLawCase& c, std::ostream* os) {
    *os << c.element.name << " × " << c.law;
}
std::string ElementName(const ::testing::TestParamInfo<ElementInfo>& info);
/// True where the law's tangent is not ∂(stress)/∂(strain) of what the element hands it (docs/theory/solid_elements.md,
/// last paragraph):
/// SmallDisplacement × Neo-Hookean (tangent ℂ(C_eq) used with ε) and UpdatedLagrangian × linear elastic
/// ("Cauchy" D E(F) with the constant D as spatial tangent). Kratos behaviour, reproduced.
bool HasInexactTangent(const ElementLawCase& c);

/// A root model part "Solid" (buffer @p buffer_size) with DISPLACEMENT, VELOCITY, ACCELERATION,
/// VOLUME_ACCELERATION and REACTION, and property set 1: law @p law_name, E = 200, ν = 0.3, ρ = 2,
/// THICKNESS = 0.5.
class SolidTestModel {
public:
    explicit SolidTestModel(const std::string& law_name, std::size_t buffer_size = 2);
    ModelPart& Part() { return *mPart; }
    Properties& GetProperties() { return *mProperties; }
    const Properties::Pointer& pGetProperties() const { return mProperties; }
    const ProcessInfo& GetProcessInfo() const { return mPart->GetProcessInfo(); }
    /// A node at @p X, with DoFs DISPLACEMENT_X/Y/Z (reactions REACTION_X/Y/Z) if @p with_dofs.
    Node& AddNode(IndexType id, const Array3& X, bool with_dofs = true);
    /// Element @p name with id @p id on the existing nodes @p node_ids.
    Element& AddElement(const std::string& name, IndexType id, const std::vector<IndexType>& node_ids);
    /// Element @p element on new nodes 1..n placed by DistortedElementCoordinates().
    Element& AddSingleElement(const ElementInfo& element, IndexType id = 1);
    /// DISPLACEMENT of @p node at buffer @p step; the node moves to X + u(step 0).
    void SetDisplacement(Node& node, const Array3& u, std::size_t step = 0);

private:
    Model mModel;
    ModelPart* mPart;
    Properties::Pointer mProperties;
};

/// Node coordinates of a distorted, positively oriented element of @p element's geometry
/// (radius x ≥ 0.5 when axisymmetric).
std::vector<Array3> DistortedElementCoordinates(const ElementInfo& element);

/// u(X) = (R(θ)(I + H) − I)(X − c) + noise·ρ_i: a homogeneous stretch H (entries in ±strain), a rotation θ
/// about z (2D) or (1,1,1) (3D), and a random part per node (ρ_i ∈ [−1, 1]^d); c = node average.
struct Deformation {
    double strain = 0.1;
    double rotation = 0.2;
    double noise = 0.01;
    unsigned seed = 1;
};
/// Sets DISPLACEMENT at @p step on the nodes of @p element (moving them if step = 0).
void ApplyDeformation(SolidTestModel& model, Element& element, const Deformation& deformation, std::size_t step = 0);
/// Rotation about z (2D) or about (1,1,1)/√3 (3D), as a 3×3 matrix.
Eigen::Matrix3d RotationMatrix(int dimension, double angle);

/// −∂RHS/∂u by central differences of step @p h, moving each perturbed node (x = X + u).
Matrix FiniteDifferenceTangent(Element& element, SolidTestModel& model, double h);
/// ‖a − b‖_F / ‖b‖_F.
double RelativeError(const Matrix& a, const Matrix& b);

/// A patch of distorted elements filling the unit square/cube (x ∈ [1, 2] when axisymmetric); node ids 1..n.
struct PatchMesh {
    std::vector<Array3> coordinates;
    std::vector<std::vector<IndexType>> elements;
    std::vector<bool> on_boundary;  ///< per node (index id − 1)
};
PatchMesh MakePatchMesh(const ElementInfo& element);

/// Newton solve of the free DoFs of @p model's elements with the boundary nodes of @p mesh held at
/// @p field(X); assembles the element LHS/RHS into dense matrices. Returns the number of iterations.
int SolvePatch(SolidTestModel& model, const PatchMesh& mesh, const std::function<Array3(const Array3&)>& field);

/// Law response in @p measure at the kinematics @p F (kFSize square) and @p strain (used when @p provided).
Vector LawStress(const std::string& law, const Properties& properties, const Matrix& F, const Vector& strain,
                 bool provided, ConstitutiveLaw::StressMeasure measure);

}  // namespace contact_app::testing
