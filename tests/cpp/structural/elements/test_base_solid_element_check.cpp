// SPDX-License-Identifier: BSD-3-Clause
// Check() and input errors of every registered solid element; DoF lists, equation ids, values vectors and
// the integration rule.
#include <gtest/gtest.h>

#include "contact_app/kernel/geometries/geometry_factory.h"
#include "contact_app/kernel/geometries/quadrature.h"
#include "contact_app/kernel/properties.h"
#include "contact_app/kernel/registry.h"
#include "solid_element_test_utilities.h"

namespace contact_app::testing {
namespace {

class SolidElementCheckTest : public ::testing::TestWithParam<ElementInfo> {
protected:
    SolidElementCheckTest() : model(CompatibleLaws(GetParam()).front()) {}
    SolidTestModel model;
};

TEST_P(SolidElementCheckTest, ValidElementPassesCheck) {
    Element& element = model.AddSingleElement(GetParam());
    EXPECT_EQ(element.Check(model.GetProcessInfo()), 0);
    element.Initialize(model.GetProcessInfo());
    EXPECT_EQ(element.Check(model.GetProcessInfo()), 0);
}

TEST_P(SolidElementCheckTest, MissingConstitutiveLawIsReported) {
    Element& element = model.AddSingleElement(GetParam());
    model.GetProperties().Data().Erase(CONSTITUTIVE_LAW);
    const std::string where = GetParam().family;
    ExpectError<InputError>([&] { element.Check(model.GetProcessInfo()); }, {"CONSTITUTIVE_LAW", where, "#1", "fix:"});
    ExpectError<InputError>([&] { element.Initialize(model.GetProcessInfo()); }, {"CONSTITUTIVE_LAW"});
}

TEST_P(SolidElementCheckTest, LawOfWrongDimensionOrStrainSizeIsReported) {
    Element& element = model.AddSingleElement(GetParam());
    // A 3D law on 2D elements, a plane law (dimension 2, strain size 3) on 3D and axisymmetric ones.
    const std::string wrong =
        GetParam().dimension == 2 && !GetParam().axisymmetric ? "LinearElastic3DLaw" : "LinearElasticPlaneStrain2DLaw";
    model.GetProperties().SetValue(CONSTITUTIVE_LAW, Registry<ConstitutiveLaw>::Instance().Get(wrong).Clone());
    ExpectError<InputError>([&] { element.Check(model.GetProcessInfo()); }, {"strain size", wrong, "#1"});
    ExpectError<InputError>([&] { element.Initialize(model.GetProcessInfo()); }, {"strain size"});
}

TEST_P(SolidElementCheckTest, InvertedElementIsReported) {
    std::vector<IndexType> ids;
    for (const Array3& X : DistortedElementCoordinates(GetParam())) {  // mirrored: x -> 4 - x
        ids.push_back(ids.size() + 1);
        model.AddNode(ids.back(), Array3(4.0 - X[0], X[1], X[2]));
    }
    Element& element = model.AddElement(GetParam().name, 1, ids);
    ExpectError<InputError>([&] { element.Check(model.GetProcessInfo()); }, {"inverted", "det J", "#1"});
    ExpectError<InputError>([&] { element.Initialize(model.GetProcessInfo()); }, {"inverted"});
}

TEST_P(SolidElementCheckTest, MissingDofIsReported) {
    std::vector<IndexType> ids;
    for (const Array3& X : DistortedElementCoordinates(GetParam())) {
        ids.push_back(ids.size() + 1);
        model.AddNode(ids.back(), X, /*with_dofs=*/false);
    }
    Element& element = model.AddElement(GetParam().name, 1, ids);
    ExpectError<InputError>([&] { element.Check(model.GetProcessInfo()); }, {"DISPLACEMENT_X", "node 1", "AddDof"});
}

TEST_P(SolidElementCheckTest, UninitializedElementIsReported) {
    Element& element = model.AddSingleElement(GetParam());
    Matrix lhs;
    Vector rhs;
    ExpectError<InputError>([&] { element.CalculateLocalSystem(lhs, rhs, model.GetProcessInfo()); },
                            {"not initialized", "#1"});
}

TEST_P(SolidElementCheckTest, GeometryOfWrongTypeIsRejected) {
    const bool planar = GetParam().dimension == 2;
    Geometry::PointsArrayType nodes;
    for (IndexType id = 1; id <= (planar ? 4u : 3u); ++id) nodes.push_back(std::make_shared<Node>(id, 0.0, 0.0, 0.0));
    const Geometry::Pointer wrong = CreateGeometry(planar ? "Tetrahedra3D4" : "Triangle2D3", nodes);
    const Element& prototype = Registry<Element>::Instance().Get(GetParam().name);
    ExpectError<InputError>([&] { prototype.Create(1, wrong, model.pGetProperties()); }, {"cannot carry"});
}

TEST_P(SolidElementCheckTest, IntegrationOrderSelectsTheRule) {
    Element& element = model.AddSingleElement(GetParam());
    model.GetProperties().SetValue(INTEGRATION_ORDER, 3);
    element.Initialize(model.GetProcessInfo());
    std::vector<Vector> strains;
    element.CalculateOnIntegrationPoints(GREEN_LAGRANGE_STRAIN_VECTOR, strains, model.GetProcessInfo());
    EXPECT_EQ(strains.size(), GaussRule(element.GetGeometry().Family(), 3).size());
    model.GetProperties().SetValue(INTEGRATION_ORDER, 7);
    ExpectError<InputError>([&] { element.Check(model.GetProcessInfo()); }, {"INTEGRATION_ORDER = 7", "1..5"});
}

TEST_P(SolidElementCheckTest, DofsAndValuesFollowNodeThenComponentOrder) {
    Element& element = model.AddSingleElement(GetParam());
    element.Initialize(model.GetProcessInfo());
    const int d = GetParam().dimension;
    const Variable<double>* components[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
    Geometry& geometry = element.GetGeometry();
    for (std::size_t i = 0; i < geometry.PointsNumber(); ++i) {
        for (int a = 0; a < 3; ++a) geometry[i].GetDof(*components[a]).SetEquationId(100 + 10 * i + a);
        const double s = static_cast<double>(i + 1);
        model.SetDisplacement(geometry[i], Array3(0.01 * s, -0.02 * s, 0.03 * s));
        geometry[i].GetSolutionStepValue(VELOCITY) = Array3(s, 2 * s, 3 * s);
        geometry[i].GetSolutionStepValue(ACCELERATION, 1) = Array3(-s, -2 * s, -3 * s);
    }
    DofsVectorType dofs;
    EquationIdVectorType ids;
    Vector u, v, a_previous;
    element.GetDofList(dofs, model.GetProcessInfo());
    element.EquationIdVector(ids, model.GetProcessInfo());
    element.GetValuesVector(u);
    element.GetFirstDerivativesVector(v);
    element.GetSecondDerivativesVector(a_previous, 1);
    ASSERT_EQ(dofs.size(), GetParam().nodes * d);
    ASSERT_EQ(ids.size(), dofs.size());
    for (std::size_t k = 0; k < dofs.size(); ++k) {
        const std::size_t i = k / d;
        const int a = static_cast<int>(k % d);
        EXPECT_EQ(&dofs[k]->GetVariable(), components[a]);
        EXPECT_EQ(dofs[k]->Id(), geometry[i].Id());
        EXPECT_EQ(ids[k], 100 + 10 * i + a);
        const auto index = static_cast<Eigen::Index>(k);
        EXPECT_EQ(u[index], geometry[i].GetSolutionStepValue(DISPLACEMENT)[a]);
        EXPECT_EQ(v[index], geometry[i].GetSolutionStepValue(VELOCITY)[a]);
        EXPECT_EQ(a_previous[index], geometry[i].GetSolutionStepValue(ACCELERATION, 1)[a]);
    }
}

INSTANTIATE_TEST_SUITE_P(All, SolidElementCheckTest, ::testing::ValuesIn(SolidElements()), ElementName);

}  // namespace
}  // namespace contact_app::testing
