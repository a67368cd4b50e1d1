// SPDX-License-Identifier: BSD-3-Clause
/// MeshTyingMortarCondition: local sizes and DoF order (DISPLACEMENT and a scalar TYING_VARIABLE), the LHS against
/// central differences of the RHS, exactness for linear fields on flat non-matching faces, the scale factor,
/// deactivation of pairs without (enough) overlap and every Check() message — for the five registered pairs.
#include <cstdio>
#include <map>
#include <random>
#include <tuple>

#include "custom_conditions/mesh_tying_mortar_condition.h"
#include "tests/cpp/error_test_utilities.h"
#include "tying_test_utilities.h"

namespace contact_app::testing {
namespace {

std::string TyingName(const PairKind& kind) { return std::string("MeshTyingMortarCondition") + kind.suffix; }

/// The expected local unknowns: (node, variable) in the order [master, slave, multipliers], node-major.
std::vector<std::pair<const Node*, const Variable<double>*>> ExpectedDofs(const PairedCondition& pair, bool scalar,
                                                                          int dim) {
    const std::vector<const Variable<double>*> u =
        scalar ? std::vector<const Variable<double>*>{&TEMPERATURE}
               : std::vector<const Variable<double>*>{&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
    const std::vector<const Variable<double>*> l =
        scalar ? std::vector<const Variable<double>*>{&SCALAR_LAGRANGE_MULTIPLIER}
               : std::vector<const Variable<double>*>{&VECTOR_LAGRANGE_MULTIPLIER_X, &VECTOR_LAGRANGE_MULTIPLIER_Y,
                                                      &VECTOR_LAGRANGE_MULTIPLIER_Z};
    const int n = scalar ? 1 : dim;
    std::vector<std::pair<const Node*, const Variable<double>*>> dofs;
    const Geometry& master = pair.GetPairedGeometry();
    const Geometry& slave = pair.GetParentGeometry();
    for (std::size_t k = 0; k < master.size(); ++k)
        for (int c = 0; c < n; ++c) dofs.push_back({&master[k], u[c]});
    for (std::size_t k = 0; k < slave.size(); ++k)
        for (int c = 0; c < n; ++c) dofs.push_back({&slave[k], u[c]});
    for (std::size_t k = 0; k < slave.size(); ++k)
        for (int c = 0; c < n; ++c) dofs.push_back({&slave[k], l[c]});
    return dofs;
}

/// Random values for every local unknown (tied variable and multipliers).
void RandomValues(const DofsVectorType& dofs, std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (Dof* dof : dofs) dof->GetSolutionStepValue() = u(rng);
}

struct TyingCase {
    PairKind kind;
    bool scalar;
};

/// The case tests: each draws the pair of its case on a model of its own (InitializedPair).
class MeshTyingMortarPairs : public ::testing::TestWithParam<TyingCase> {
protected:
    /// The case's pair on flat non-matching faces drawn by rng seeded with @p seed (the test may draw on),
    /// initialized with @p info.
    std::shared_ptr<PairedCondition> InitializedPair(unsigned seed, const ProcessInfo& info) {
        const TyingCase& c = GetParam();
        rng.seed(seed);
        Eigen::MatrixXd s, m;
        FlatNonMatchingPair(c.kind, rng, s, m);
        if (c.scalar) model.properties->SetValue(TYING_VARIABLE, std::string("TEMPERATURE"));
        auto pair = model.MakePair(TyingName(c.kind), s, m);
        pair->Initialize(info);
        return pair;
    }

    TyingPairModel model;
    std::mt19937 rng;
};

std::vector<TyingCase> AllTyingCases() {
    std::vector<TyingCase> cases;
    for (const auto& kind : AllPairKinds())
        for (const bool scalar : {false, true}) cases.push_back({kind, scalar});
    return cases;
}

std::string CaseName(const ::testing::TestParamInfo<TyingCase>& info) {
    return std::string(info.param.kind.suffix) + (info.param.scalar ? "Temperature" : "Displacement");
}

/// Sizes of docs/registered_conditions.md §2.
int SpecSize(const PairKind& kind, bool scalar) {
    const std::map<std::string, std::pair<int, int>> sizes = {
        {"2D2N", {12, 6}}, {"3D3N", {27, 9}}, {"3D4N", {36, 12}}, {"3D3N4N", {30, 10}}, {"3D4N3N", {33, 11}}};
    const auto& s = sizes.at(kind.suffix);
    return scalar ? s.second : s.first;
}

TEST_P(MeshTyingMortarPairs, LocalSizesAndDofOrderMatchTheSpec) {
    const TyingCase c = GetParam();
    ProcessInfo info;
    auto pair = InitializedPair(11, info);
    EXPECT_EQ(pair->Check(info), 0);
    EXPECT_FALSE(pair->IsDefined(ACTIVE) && pair->IsNot(ACTIVE));
    const int size = SpecSize(c.kind, c.scalar);
    Matrix lhs;
    Vector rhs;
    pair->CalculateLocalSystem(lhs, rhs, info);
    EXPECT_EQ(lhs.rows(), size);
    EXPECT_EQ(lhs.cols(), size);
    EXPECT_EQ(rhs.size(), size);
    if (!c.scalar) EXPECT_EQ(DecodedName(TyingName(c.kind)).matrix_size, size);
    DofsVectorType dofs;
    EquationIdVectorType ids;
    pair->GetDofList(dofs, info);
    pair->EquationIdVector(ids, info);
    ASSERT_EQ(static_cast<int>(dofs.size()), size);
    EXPECT_EQ(static_cast<int>(ids.size()), size);
    const auto expected = ExpectedDofs(*pair, c.scalar, c.kind.dim);
    for (int q = 0; q < size; ++q) {
        EXPECT_EQ(&dofs[q]->GetNode(), expected[q].first) << q;
        EXPECT_EQ(&dofs[q]->GetVariable(), expected[q].second) << q;
    }
    const std::size_t points = ExpectNoMassNoDampingZeroGap(*pair, info);
    std::vector<Vector> vectors;
    pair->CalculateOnIntegrationPoints(CAUCHY_STRESS_VECTOR, vectors, info);
    EXPECT_EQ(vectors.size(), points);
    for (const auto& v : vectors) EXPECT_EQ(v.norm(), 0.0);
}

TEST_P(MeshTyingMortarPairs, LeftHandSideIsMinusTheCentralDifferenceOfTheRightHandSide) {
    const TyingCase c = GetParam();
    ProcessInfo info;
    info.SetValue(SCALE_FACTOR, 3.5);
    auto pair = InitializedPair(23, info);
    DofsVectorType dofs;
    pair->GetDofList(dofs, info);
    RandomValues(dofs, rng);
    Matrix lhs;
    Vector rhs;
    pair->CalculateLocalSystem(lhs, rhs, info);
    ASSERT_GT(lhs.norm(), 1.0);
    const double h = 1e-6;
    Matrix fd(lhs.rows(), lhs.cols());
    for (std::size_t q = 0; q < dofs.size(); ++q) {
        Vector plus, minus;
        dofs[q]->GetSolutionStepValue() += h;
        pair->CalculateRightHandSide(plus, info);
        dofs[q]->GetSolutionStepValue() -= 2 * h;
        pair->CalculateRightHandSide(minus, info);
        dofs[q]->GetSolutionStepValue() += h;
        fd.col(q) = -(plus - minus) / (2 * h);
    }
    const double error = (lhs - fd).cwiseAbs().maxCoeff() / lhs.cwiseAbs().maxCoeff();
    std::printf("[ mesh tying %s ] max |LHS + dRHS/dq| / max |LHS| = %.3e\n", CaseName({c, 0}).c_str(), error);
    EXPECT_LT(error, 1e-8);
    // The multiplier block is symmetric to the constraint block: K = Kᵀ.
    EXPECT_LT((lhs - lhs.transpose()).cwiseAbs().maxCoeff(), 1e-14 * lhs.cwiseAbs().maxCoeff());
}

TEST_P(MeshTyingMortarPairs, LinearFieldsAreTiedExactlyOnFlatNonMatchingFaces) {
    const TyingCase c = GetParam();
    ProcessInfo info;
    auto pair = InitializedPair(5, info);
    const auto& tying = dynamic_cast<const PairedCondition&>(*pair);
    // u(x) = a + B x on every node of both faces, any multiplier values.
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const Eigen::Vector3d a(u(rng), u(rng), u(rng));
    Eigen::Matrix3d B;
    for (int i = 0; i < 9; ++i) B(i / 3, i % 3) = u(rng);
    DofsVectorType dofs;
    pair->GetDofList(dofs, info);
    RandomValues(dofs, rng);
    auto field = [&](const Node& node) -> Eigen::Vector3d { return a + B * node.Coordinates(); };
    for (const Geometry* face : {&tying.GetParentGeometry(), &tying.GetPairedGeometry()})
        for (std::size_t k = 0; k < face->size(); ++k) {
            Node& node = const_cast<Node&>((*face)[k]);
            node.FastGetSolutionStepValue(DISPLACEMENT) = field(node);
            node.FastGetSolutionStepValue(TEMPERATURE) = field(node)[0];
        }
    Vector rhs;
    pair->CalculateRightHandSide(rhs, info);
    const int n = c.scalar ? 1 : c.kind.dim;
    const int lm_offset = n * (c.kind.num_master + c.kind.num_slave);
    const double constraint = rhs.tail(rhs.size() - lm_offset).cwiseAbs().maxCoeff();
    EXPECT_LT(constraint, 1e-13);
    // Not trivially zero: the operators carry the overlap and a non-linear field is not tied.
    const Geometry& slave = tying.GetParentGeometry();
    Node& first = const_cast<Node&>(slave[0]);
    first.FastGetSolutionStepValue(DISPLACEMENT) += Array3(0.1, 0.1, 0.1);
    first.FastGetSolutionStepValue(TEMPERATURE) += 0.1;
    pair->CalculateRightHandSide(rhs, info);
    EXPECT_GT(rhs.tail(rhs.size() - lm_offset).cwiseAbs().maxCoeff(), 1e-3);
}

TEST_P(MeshTyingMortarPairs, ScaleFactorComesFromTheProcessInfoWithFallbacks) {
    ProcessInfo none;
    auto pair = InitializedPair(3, none);
    Matrix unit, scaled, build;
    Vector r;
    pair->CalculateLocalSystem(unit, r, none);
    ProcessInfo with_build;
    with_build.SetValue(BUILD_SCALE_FACTOR, 4.0);
    pair->CalculateLocalSystem(build, r, with_build);
    ProcessInfo with_both = with_build;
    with_both.SetValue(SCALE_FACTOR, 2.0);
    pair->CalculateLocalSystem(scaled, r, with_both);
    ASSERT_GT(unit.norm(), 0.1);
    EXPECT_LT((build - 4.0 * unit).norm(), 1e-13 * build.norm());
    EXPECT_LT((scaled - 2.0 * unit).norm(), 1e-13 * scaled.norm());
}

INSTANTIATE_TEST_SUITE_P(MeshTyingMortar, MeshTyingMortarPairs, ::testing::ValuesIn(AllTyingCases()), CaseName);

TEST(MeshTyingMortarCondition, PairWithoutOverlapIsDeactivated) {
    for (const auto& kind : AllPairKinds()) {
        TyingPairModel model;
        std::mt19937 rng(2);
        Eigen::MatrixXd s, m;
        FlatNonMatchingPair(kind, rng, s, m);
        m.rowwise() += 10.0 * (s.row(1) - s.row(0));  // slid far along the face: no overlap
        auto pair = model.MakePair(TyingName(kind), s, m);
        ProcessInfo info;
        pair->Initialize(info);
        EXPECT_TRUE(pair->IsDefined(ACTIVE) && pair->IsNot(ACTIVE)) << kind.suffix;
        Matrix lhs;
        Vector rhs;
        pair->CalculateLocalSystem(lhs, rhs, info);
        EXPECT_EQ(lhs.rows(), DecodedName(TyingName(kind)).matrix_size);
        EXPECT_EQ(lhs.norm(), 0.0);
        EXPECT_EQ(rhs.norm(), 0.0);
    }
}

TEST(MeshTyingMortarCondition, OverlapRatioBelowTheDimensionlessThresholdDeactivates) {
    // 2D: slave [0, 1], master overlapping it over a fraction f of its length. The isolation rule of the
    // contact conditions (1e−5) keeps f = 5e−4, the mesh-tying rule (1e−3, dimensionless) drops it, for any unit.
    for (const double unit : {1.0e-3, 1.0, 1.0e3})
        for (const double fraction : {5e-4, 2e-3}) {
            TyingPairModel model;
            Eigen::MatrixXd s(2, 2), m(2, 2);
            s << unit, 0.0, 0.0, 0.0;
            m << (1.0 - fraction) * unit, 0.0, 2.0 * unit, 0.0;
            auto pair = model.MakePair("MeshTyingMortarCondition2D2N", s, m);
            pair->Initialize(ProcessInfo());
            const bool deactivated = pair->IsDefined(ACTIVE) && pair->IsNot(ACTIVE);
            const bool below = fraction < MeshTyingMortarCondition<2, 2>::MinimumOverlapRatio;
            EXPECT_EQ(deactivated, below)
                << "unit " << unit << " fraction " << fraction;
        }
}

std::shared_ptr<PairedCondition> MatchingTriangles(TyingPairModel& model, const std::string& tying_variable = "") {
    if (!tying_variable.empty()) model.properties->SetValue(TYING_VARIABLE, tying_variable);
    Eigen::MatrixXd s(3, 3), m(3, 3);
    s << 0, 0, 0, 1, 0, 0, 0, 1, 0;
    m << 0, 1, 0, 1, 0, 0, 0, 0, 0;
    return model.MakePair("MeshTyingMortarCondition3D3N", s, m);
}

TEST(MeshTyingMortarCondition, CheckReportsEveryMissingPiece) {
    {
        TyingPairModel model;
        EXPECT_EQ(CheckMessage(*MatchingTriangles(model)), "");
        TyingPairModel scalar;
        EXPECT_EQ(CheckMessage(*MatchingTriangles(scalar, "TEMPERATURE")), "");
    }
    {  // unpaired (an .mdpa-created condition)
        TyingPairModel model;
        auto pair = MatchingTriangles(model);
        const auto unpaired = pair->Create(7, pair->pGetParentGeometry(), model.properties, nullptr);
        EXPECT_NE(CheckMessage(*unpaired).find("YOU HAVE NOT INITIALIZED THE PAIR GEOMETRY"), std::string::npos);
    }
    {  // wrong node counts for the registered name
        TyingPairModel model;
        auto pair = MatchingTriangles(model);
        const auto& quad_proto = dynamic_cast<const PairedCondition&>(
            Registry<Condition>::Instance().Get("MeshTyingMortarCondition3D4N"));
        const auto wrong = quad_proto.Create(8, pair->pGetParentGeometry(), model.properties, pair->pGetPairedGeometry());
        EXPECT_NE(CheckMessage(*wrong).find("expected: 4 and 4 nodes"), std::string::npos) << CheckMessage(*wrong);
    }
    {  // TYING_VARIABLE of an incompatible kind and an unknown name
        TyingPairModel model;
        auto pair = MatchingTriangles(model, "CAUCHY_STRESS_VECTOR");
        EXPECT_NE(CheckMessage(*pair).find("Compatible variables are: double or array_1d<double, 3>"),
                  std::string::npos);
        EXPECT_THROW(pair->Initialize(ProcessInfo()), InputError);
        TyingPairModel unknown;
        EXPECT_NE(CheckMessage(*MatchingTriangles(unknown, "NOT_A_VARIABLE")).find("NOT_A_VARIABLE"),
                  std::string::npos);
    }
    const std::vector<std::tuple<std::string, std::string, std::string, std::string>> missing = {
        // tying variable, skipped historical variable, skipped DoF, expected fragment
        {"TEMPERATURE", "TEMPERATURE", "", "does not store TEMPERATURE as a historical variable"},
        {"TEMPERATURE", "", "TEMPERATURE", "has no TEMPERATURE DoF"},
        {"TEMPERATURE", "SCALAR_LAGRANGE_MULTIPLIER", "", "does not store SCALAR_LAGRANGE_MULTIPLIER"},
        {"TEMPERATURE", "", "SCALAR_LAGRANGE_MULTIPLIER", "has no SCALAR_LAGRANGE_MULTIPLIER DoF"},
        {"", "DISPLACEMENT", "", "does not store DISPLACEMENT as a historical variable"},
        {"", "", "DISPLACEMENT_Y", "has no DISPLACEMENT_Y DoF"},
        {"", "VECTOR_LAGRANGE_MULTIPLIER", "", "does not store VECTOR_LAGRANGE_MULTIPLIER"},
        {"", "", "VECTOR_LAGRANGE_MULTIPLIER_Z", "has no VECTOR_LAGRANGE_MULTIPLIER_Z DoF"},
    };
    for (const auto& [variable, skip_variable, skip_dof, fragment] : missing) {
        std::set<std::string> skip_variables, skip_dofs;
        if (!skip_variable.empty()) skip_variables.insert(skip_variable);
        if (!skip_dof.empty()) skip_dofs.insert(skip_dof);
        TyingPairModel model(skip_variables, skip_dofs);
        const std::string message = CheckMessage(*MatchingTriangles(model, variable));
        EXPECT_NE(message.find(fragment), std::string::npos) << fragment << " / got: " << message;
        EXPECT_NE(message.find("fix:"), std::string::npos) << message;
    }
}

TEST(MeshTyingMortarCondition, RegisteredPrototypesUseTrueMixedPairs) {
    RegisterContactConditions();
    for (const auto& kind : AllPairKinds()) {
        const auto& prototype =
            dynamic_cast<const PairedCondition&>(Registry<Condition>::Instance().Get(TyingName(kind)));
        EXPECT_EQ(static_cast<int>(prototype.GetParentGeometry().size()), kind.num_slave) << kind.suffix;
        EXPECT_EQ(static_cast<int>(prototype.GetPairedGeometry().size()), kind.num_master) << kind.suffix;
    }
}

}  // namespace
}  // namespace contact_app::testing
