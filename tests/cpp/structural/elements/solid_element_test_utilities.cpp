// SPDX-License-Identifier: BSD-3-Clause
// Fixtures shared by the solid-element tests (see solid_element_test_utilities.h).
#include "solid_element_test_utilities.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <regex>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include "contact_app/kernel/element.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/registry.h"
#include "contact_app/structural/structural_registration.h"

namespace contact_app::testing {

namespace {

const Variable<double>* const kDisplacement[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
const Variable<double>* const kReaction[3] = {&REACTION_X, &REACTION_Y, &REACTION_Z};

/// Reference-element node coordinates of @p geometry (padded to 3).
std::vector<Array3> ReferenceNodes(const Geometry& geometry) {
    Matrix local;
    geometry.PointsLocalCoordinates(local);
    std::vector<Array3> nodes(local.rows(), Array3::Zero());
    for (Eigen::Index k = 0; k < local.rows(); ++k) nodes[k].head(local.cols()) = local.row(k).transpose();
    return nodes;
}

const Geometry& PrototypeGeometry(const std::string& element_name) {
    return Registry<Element>::Instance().Get(element_name).GetGeometry();
}

std::size_t NumberOfCorners(const Geometry& geometry) {
    const bool simplex =
        geometry.Family() == GeometryFamily::Triangle || geometry.Family() == GeometryFamily::Tetrahedra;
    const int d = geometry.LocalSpaceDimension();
    return simplex ? static_cast<std::size_t>(d + 1) : (std::size_t{1} << d);
}

double SignedMeasure(const std::vector<Array3>& corners, int dimension) {
    if (dimension == 2) {
        const Array3 a = corners[1] - corners[0], b = corners[2] - corners[0];
        return a[0] * b[1] - a[1] * b[0];
    }
    return (corners[1] - corners[0]).cross(corners[2] - corners[0]).dot(corners[3] - corners[0]);
}

/// True on the faces of the box [x_shift, x_shift + 1] × [0, 1]^(d−1).
bool OnBoxBoundary(const Array3& X, int dimension, double x_shift) {
    for (int c = 0; c < dimension; ++c) {
        const double v = X[c] - (c == 0 ? x_shift : 0.0);
        if (std::abs(v) < 1e-12 || std::abs(v - 1.0) < 1e-12) return true;
    }
    return false;
}

}  // namespace

void RegisterForSolidTests() {
    RegisterKernelVariables();
    RegisterKernelEntities();
    RegisterConstitutiveLaws();
    RegisterSolidElements();
}

std::vector<ElementInfo> SolidElements(bool include_aliases) {
    RegisterForSolidTests();
    static const std::regex pattern(
        "^(Axisym)?(SmallDisplacement|TotalLagrangian|UpdatedLagrangian)(Axisym)?"
        "Element([23])D([0-9]+)N$");
    std::vector<ElementInfo> elements;
    for (const std::string& name : Registry<Element>::Instance().Names()) {
        std::smatch match;
        if (!std::regex_match(name, match, pattern)) continue;
        ElementInfo info;
        info.name = name;
        info.alias = match[3].matched;
        info.axisymmetric = match[1].matched || match[3].matched;
        info.family = (info.axisymmetric ? "Axisym" : "") + match[2].str() + "Element";
        info.formulation = match[2] == "SmallDisplacement" ? Formulation::SmallDisplacement
                           : match[2] == "TotalLagrangian" ? Formulation::TotalLagrangian
                                                           : Formulation::UpdatedLagrangian;
        info.dimension = std::stoi(match[4].str());
        info.nodes = std::stoul(match[5].str());
        info.geometry = PrototypeGeometry(name).Name();
        info.strain_size = info.axisymmetric ? 4 : (info.dimension == 2 ? 3 : 6);
        if (include_aliases || !info.alias) elements.push_back(info);
    }
    return elements;
}

std::vector<std::string> CompatibleLaws(const ElementInfo& element) {
    RegisterForSolidTests();
    std::vector<std::string> laws;
    for (const std::string& name : Registry<ConstitutiveLaw>::Instance().Names()) {
        const ConstitutiveLaw& law = Registry<ConstitutiveLaw>::Instance().Get(name);
        if (law.WorkingSpaceDimension() == element.dimension && law.GetStrainSize() == element.strain_size)
            laws.push_back(name);
    }
    return laws;
}

std::vector<ElementLawCase> ElementLawCases() {
    std::vector<ElementLawCase> cases;
    for (const ElementInfo& element : SolidElements())
        for (const std::string& law : CompatibleLaws(element)) cases.push_back({element, law});
    return cases;
}

std::string CaseName(const ::testing::TestParamInfo<ElementLawCase>& info) {
    return info.param.element.name + "_" + info.param.law;
}

std::string ElementName(const ::testing::TestParamInfo<ElementInfo>& info) {
    return info.param.name;
}

bool HasInexactTangent(const ElementLawCase& c) {
    const bool neo_hookean = c.law.rfind("HyperElastic", 0) == 0;
    const bool linear = c.law.rfind("LinearElastic", 0) == 0;
    return (c.element.formulation == Formulation::SmallDisplacement && neo_hookean) ||
           (c.element.formulation == Formulation::UpdatedLagrangian && linear);
}

// -- Model --

SolidTestModel::SolidTestModel(const std::string& law_name, std::size_t buffer_size) {
    RegisterForSolidTests();
    mPart = &mModel.CreateModelPart("Solid", buffer_size);
    for (const VariableData* variable : std::initializer_list<const VariableData*>{
             &DISPLACEMENT, &VELOCITY, &ACCELERATION, &VOLUME_ACCELERATION, &REACTION})
        mPart->AddNodalSolutionStepVariable(*variable);
    mProperties = mPart->CreateNewProperties(1);
    mProperties->SetValue(CONSTITUTIVE_LAW, Registry<ConstitutiveLaw>::Instance().Get(law_name).Clone());
    mProperties->SetValue(YOUNG_MODULUS, 200.0);
    mProperties->SetValue(POISSON_RATIO, 0.3);
    mProperties->SetValue(DENSITY, 2.0);
    mProperties->SetValue(THICKNESS, 0.5);
}

Node& SolidTestModel::AddNode(IndexType id, const Array3& X, bool with_dofs) {
    Node& node = *mPart->CreateNewNode(id, X[0], X[1], X[2]);
    if (with_dofs)
        for (int a = 0; a < 3; ++a) node.AddDof(*kDisplacement[a], *kReaction[a]);
    return node;
}

Element& SolidTestModel::AddElement(const std::string& name, IndexType id, const std::vector<IndexType>& node_ids) {
    return *mPart->CreateNewElement(name, id, node_ids, mProperties);
}

Element& SolidTestModel::AddSingleElement(const ElementInfo& element, IndexType id) {
    std::vector<IndexType> ids;
    for (const Array3& X : DistortedElementCoordinates(element)) {
        ids.push_back(mPart->NumberOfNodes() + 1);
        AddNode(ids.back(), X);
    }
    return AddElement(element.name, id, ids);
}

void SolidTestModel::SetDisplacement(Node& node, const Array3& u, std::size_t step) {
    node.GetSolutionStepValue(DISPLACEMENT, step) = u;
    node.Coordinates() = node.InitialCoordinates() + node.GetSolutionStepValue(DISPLACEMENT, 0);
}

// -- Single elements and deformations --

std::vector<Array3> DistortedElementCoordinates(const ElementInfo& element) {
    const Geometry& prototype = PrototypeGeometry(element.name);
    const bool simplex =
        prototype.Family() == GeometryFamily::Triangle || prototype.Family() == GeometryFamily::Tetrahedra;
    const double scale = simplex ? 1.0 : 0.5;  // reference sizes 1 (simplices) and 2 ([-1, 1]^d)
    Eigen::Matrix3d A;
    A << 1.0, 0.2, 0.1, -0.15, 0.9, 0.05, 0.1, -0.1, 1.1;
    const Array3 center = element.axisymmetric ? Array3(1.5, 0.5, 0.0) : Array3(0.3, -0.2, 0.1);
    std::mt19937 generator(7);
    std::uniform_real_distribution<double> noise(-1.0, 1.0);
    std::vector<Array3> coordinates;
    for (const Array3& xi : ReferenceNodes(prototype)) {
        Array3 X = center + scale * (A * xi);
        for (int a = 0; a < element.dimension; ++a) X[a] += 0.03 * noise(generator);
        if (element.dimension == 2) X[2] = 0.0;
        coordinates.push_back(X);
    }
    return coordinates;
}

Eigen::Matrix3d RotationMatrix(int dimension, double angle) {
    const Eigen::Vector3d axis = dimension == 2 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d(1, 1, 1).normalized();
    return Eigen::AngleAxisd(angle, axis).toRotationMatrix();
}

void ApplyDeformation(SolidTestModel& model, Element& element, const Deformation& deformation, std::size_t step) {
    Geometry& geometry = element.GetGeometry();
    const int d = geometry.WorkingSpaceDimension();
    std::mt19937 generator(deformation.seed);
    std::uniform_real_distribution<double> random(-1.0, 1.0);
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
    for (int a = 0; a < d; ++a)
        for (int b = 0; b < d; ++b) H(a, b) = deformation.strain * random(generator);
    const Eigen::Matrix3d map =
        RotationMatrix(d, deformation.rotation) * (Eigen::Matrix3d::Identity() + H) - Eigen::Matrix3d::Identity();
    Array3 center = Array3::Zero();
    for (std::size_t i = 0; i < geometry.PointsNumber(); ++i) center += geometry[i].InitialCoordinates();
    center /= static_cast<double>(geometry.PointsNumber());
    for (std::size_t i = 0; i < geometry.PointsNumber(); ++i) {
        Array3 u = map * (geometry[i].InitialCoordinates() - center);
        for (int a = 0; a < d; ++a) u[a] += deformation.noise * random(generator);
        if (d == 2) u[2] = 0.0;
        model.SetDisplacement(geometry[i], u, step);
    }
}

Matrix FiniteDifferenceTangent(Element& element, SolidTestModel& model, double h) {
    Geometry& geometry = element.GetGeometry();
    const int d = geometry.WorkingSpaceDimension();
    const auto n = static_cast<Eigen::Index>(geometry.PointsNumber() * d);
    Matrix tangent(n, n);
    Vector plus, minus;
    for (std::size_t i = 0; i < geometry.PointsNumber(); ++i) {
        Node& node = geometry[i];
        const Array3 u = node.GetSolutionStepValue(DISPLACEMENT);
        for (int a = 0; a < d; ++a) {
            Array3 shifted = u;
            shifted[a] = u[a] + h;
            model.SetDisplacement(node, shifted);
            element.CalculateRightHandSide(plus, model.GetProcessInfo());
            shifted[a] = u[a] - h;
            model.SetDisplacement(node, shifted);
            element.CalculateRightHandSide(minus, model.GetProcessInfo());
            tangent.col(static_cast<Eigen::Index>(i * d + a)) = -(plus - minus) / (2.0 * h);
        }
        model.SetDisplacement(node, u);
    }
    return tangent;
}

double RelativeError(const Matrix& a, const Matrix& b) {
    return (a - b).norm() / b.norm();
}

// -- Patch meshes --

namespace {

using CellOffsets = std::vector<std::array<int, 3>>;

/// Corner offsets (in cells) of the elements filling one cell: the reference corners for quadrilaterals and
/// hexahedra, two triangles, or the six Kuhn tetrahedra around the cell diagonal (conforming between cells).
std::vector<CellOffsets> CellElements(const Geometry& prototype, const std::vector<Array3>& reference) {
    const GeometryFamily family = prototype.Family();
    if (family == GeometryFamily::Quadrilateral || family == GeometryFamily::Hexahedra) {
        CellOffsets offsets;
        for (std::size_t c = 0; c < NumberOfCorners(prototype); ++c)
            offsets.push_back({int(reference[c][0] > 0), int(reference[c][1] > 0), int(reference[c][2] > 0)});
        return {offsets};
    }
    if (family == GeometryFamily::Triangle)
        return {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
    std::vector<CellOffsets> tetrahedra;
    std::array<int, 3> axes{0, 1, 2};
    do {
        std::array<int, 3> a{0, 0, 0};
        a[axes[0]] = 1;
        std::array<int, 3> b = a;
        b[axes[1]] = 1;
        tetrahedra.push_back({{0, 0, 0}, a, b, {1, 1, 1}});
    } while (std::next_permutation(axes.begin(), axes.end()));
    return tetrahedra;
}

/// Appends to @p ids the mid-side nodes of a quadratic element (straight edges), shared between elements.
void AddMidsideNodes(const std::vector<Array3>& reference, std::size_t corners, int dimension, double x_shift,
                     std::map<std::pair<IndexType, IndexType>, IndexType>& midside, PatchMesh& mesh,
                     std::vector<IndexType>& ids) {
    for (std::size_t m = corners; m < reference.size(); ++m)
        for (std::size_t a = 0; a < corners; ++a)
            for (std::size_t b = a + 1; b < corners; ++b) {
                if ((0.5 * (reference[a] + reference[b]) - reference[m]).norm() > 1e-12) continue;
                const auto key = std::minmax(ids[a], ids[b]);
                auto found = midside.find(key);
                if (found == midside.end()) {
                    const Array3 X = 0.5 * (mesh.coordinates[ids[a] - 1] + mesh.coordinates[ids[b] - 1]);
                    mesh.coordinates.push_back(X);
                    mesh.on_boundary.push_back(OnBoxBoundary(X, dimension, x_shift));
                    found = midside.emplace(key, mesh.coordinates.size()).first;
                }
                ids.push_back(found->second);
            }
}

}  // namespace

PatchMesh MakePatchMesh(const ElementInfo& element) {
    const Geometry& prototype = PrototypeGeometry(element.name);
    const int d = element.dimension;
    const int cells = d == 2 ? 3 : 2;
    const int layers = d == 3 ? cells : 1;
    const double h = 1.0 / cells;
    const double x_shift = element.axisymmetric ? 1.0 : 0.0;
    PatchMesh mesh;
    std::mt19937 generator(11);
    std::uniform_real_distribution<double> noise(-1.0, 1.0);
    for (int k = 0; k < layers + (d == 3 ? 1 : 0); ++k)  // grid nodes; interior ones perturbed
        for (int j = 0; j <= cells; ++j)
            for (int i = 0; i <= cells; ++i) {
                Array3 X(x_shift + i * h, j * h, k * h);
                const bool boundary = OnBoxBoundary(X, d, x_shift);
                if (!boundary)
                    for (int a = 0; a < d; ++a) X[a] += 0.25 * h * noise(generator);
                mesh.coordinates.push_back(X);
                mesh.on_boundary.push_back(boundary);
            }
    const auto grid_id = [&](int i, int j, int k) {
        return static_cast<IndexType>(1 + i + (cells + 1) * (j + (cells + 1) * k));
    };
    const std::vector<Array3> reference = ReferenceNodes(prototype);
    const std::size_t corners = NumberOfCorners(prototype);
    const std::vector<CellOffsets> cell_elements = CellElements(prototype, reference);
    std::map<std::pair<IndexType, IndexType>, IndexType> midside;
    for (int k = 0; k < layers; ++k)
        for (int j = 0; j < cells; ++j)
            for (int i = 0; i < cells; ++i)
                for (const CellOffsets& offsets : cell_elements) {
                    std::vector<IndexType> ids;
                    std::vector<Array3> x;
                    for (const auto& o : offsets) {
                        ids.push_back(grid_id(i + o[0], j + o[1], k + o[2]));
                        x.push_back(mesh.coordinates[ids.back() - 1]);
                    }
                    if (corners == static_cast<std::size_t>(d + 1) && SignedMeasure(x, d) < 0.0)
                        std::swap(ids[1], ids[2]);
                    AddMidsideNodes(reference, corners, d, x_shift, midside, mesh, ids);
                    mesh.elements.push_back(ids);
                }
    return mesh;
}

int SolvePatch(SolidTestModel& model, const PatchMesh& mesh, const std::function<Array3(const Array3&)>& field) {
    ModelPart& part = model.Part();
    const int d = part.Elements().begin()->get()->GetGeometry().WorkingSpaceDimension();
    const auto n = static_cast<Eigen::Index>(mesh.coordinates.size() * d);
    for (const auto& node : part.Nodes()) {
        for (int a = 0; a < d; ++a) node->GetDof(*kDisplacement[a]).SetEquationId((node->Id() - 1) * d + a);
        if (mesh.on_boundary[node->Id() - 1]) model.SetDisplacement(*node, field(node->InitialCoordinates()));
    }
    std::vector<Eigen::Index> free;
    for (Eigen::Index k = 0; k < n; ++k)
        if (!mesh.on_boundary[static_cast<std::size_t>(k / d)]) free.push_back(k);
    double reference_norm = 0.0;
    for (int iteration = 1; iteration <= 30; ++iteration) {
        Matrix K = Matrix::Zero(n, n);
        Vector r = Vector::Zero(n);
        Matrix lhs;
        Vector rhs;
        EquationIdVectorType ids;
        for (const auto& element : part.Elements()) {
            element->CalculateLocalSystem(lhs, rhs, model.GetProcessInfo());
            element->EquationIdVector(ids, model.GetProcessInfo());
            for (std::size_t i = 0; i < ids.size(); ++i) {
                r[ids[i]] += rhs[i];
                for (std::size_t j = 0; j < ids.size(); ++j) K(ids[i], ids[j]) += lhs(i, j);
            }
        }
        const Vector r_free = r(free);
        if (iteration == 1) reference_norm = std::max(r.norm(), 1e-30);
        if (r_free.norm() <= 1e-13 * reference_norm) return iteration;
        const Vector delta = K(free, free).partialPivLu().solve(r_free);
        for (std::size_t f = 0; f < free.size(); ++f) {
            Node& node = part.GetNode(static_cast<IndexType>(free[f] / d + 1));
            Array3 u = node.GetSolutionStepValue(DISPLACEMENT);
            u[free[f] % d] += delta[static_cast<Eigen::Index>(f)];
            model.SetDisplacement(node, u);
        }
    }
    return -1;
}

Vector LawStress(const std::string& law, const Properties& properties, const Matrix& F, const Vector& strain,
                 bool provided, ConstitutiveLaw::StressMeasure measure) {
    const ConstitutiveLaw::Pointer clone = Registry<ConstitutiveLaw>::Instance().Get(law).Clone();
    ConstitutiveLaw::Parameters values;
    values.use_element_provided_strain = provided;
    values.compute_constitutive_tensor = false;
    values.deformation_gradient = F;
    values.determinant_f = F.determinant();
    values.strain_vector = strain;
    values.material_properties = &properties;
    clone->CalculateMaterialResponse(values, measure);
    return values.stress_vector;
}

}  // namespace contact_app::testing
