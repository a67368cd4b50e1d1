// SPDX-License-Identifier: BSD-3-Clause
/// Frictionless mortar conditions (ALM, ALM components and penalty): sizes, DoF order, FD tangent, flat-pair gap, nodal area and
/// RHS, for every registered name.
#include <algorithm>
#include <cstdio>
#include <map>
#include <random>

#include "../custom_utilities/mortar_test_utilities.h"
#include "contact_condition_test_utilities.h"
#include "custom_conditions/frictionless_mortar_contact_common.h"
#include "custom_conditions/mortar_contact_condition.h"
#include "custom_utilities/contact_utilities.h"
#include "custom_utilities/mortar_normals.h"

namespace contact_app::testing {
namespace {

bool IsComponents(const ContactConditionName& row) { return row.family == "ALMFrictionlessComponents"; }

/// Sets the multiplier of slave node @p node: λ_n for the scalar family, λ = λ_n n + τ for the components one.
void SetMultiplier(Node& node, double lambda_n, const Array3& tangential = Array3::Zero()) {
    node.FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) = lambda_n;
    node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) =
        lambda_n * node.FastGetSolutionStepValue(NORMAL) + tangential;
}

class FrictionlessMortarNames : public ::testing::TestWithParam<std::string> {};

TEST_P(FrictionlessMortarNames, LocalSystemSizesAndDofOrderMatchTheSpec) {
    ContactPairModel model;
    const auto& row = DecodedName(GetParam());
    std::mt19937 rng(7);
    Eigen::MatrixXd s, m;
    RandomPairCoordinates(row, rng, s, m);
    auto pair = model.MakeNormalPair(GetParam(), s, m, 1.5);
    ProcessInfo info;
    info.SetValue(SCALE_FACTOR, 1.0);
    for (std::size_t j = 0; j < pair->GetParentGeometry().size(); ++j)
        const_cast<Node&>(pair->GetParentGeometry()[j]).SetValue(INITIAL_PENALTY, 10.0);
    ExpectSpecLocalSystem(*pair, GetParam(), info);
    ExpectNoMassNoDampingZeroGap(*pair, info);
    // Active/inactive encoding: Σ 2^i over ACTIVE slave nodes.
    auto& slave = const_cast<Geometry&>(pair->GetParentGeometry());
    int expected_value = 0;
    for (std::size_t j = 0; j < slave.size(); ++j) {
        slave[j].Set(ACTIVE, j % 2 == 0);
        if (j % 2 == 0) expected_value += 1 << j;
    }
    const int value = ActiveInactiveValue(pair.get());
    EXPECT_EQ(value, expected_value);
}

TEST_P(FrictionlessMortarNames, TangentIsTheCentralDifferenceOfMinusRhs) {
    const auto& row = DecodedName(GetParam());
    double worst = 0.0;
    for (int state = 0; state < 3; ++state) {
        ContactPairModel model;
        std::mt19937 rng(100 + state);
        Eigen::MatrixXd s, m;
        RandomPairCoordinates(row, rng, s, m);
        auto pair = model.MakeNormalPair(GetParam(), s, m, 1.5);
        model.properties->SetValue(INTEGRATION_ORDER_CONTACT, 3);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        ProcessInfo info;
        info.SetValue(SCALE_FACTOR, 1.5);
        info.SetValue(CONSIDER_NORMAL_VARIATION, row.normal_variation ? 2 : 0);
        auto& slave = const_cast<Geometry&>(pair->GetParentGeometry());
        for (std::size_t j = 0; j < slave.size(); ++j) {
            slave[j].Set(ACTIVE, state == 2 || (j + state) % 2 == 0);  // mixed in states 0 and 1, all active in 2
            slave[j].SetValue(INITIAL_PENALTY, 5.0 + 10.0 * u(rng));
            if (j % 2 == 1) slave[j].SetValue(DYNAMIC_FACTOR, 0.5 + 0.5 * u(rng));
            Array3 tangential = Array3::Zero();  // a non-zero tangential multiplier (components family)
            tangential.head(row.dim) = Eigen::VectorXd::NullaryExpr(row.dim, [&] { return 0.2 * u(rng) - 0.1; });
            SetMultiplier(slave[j], -u(rng), tangential);
        }
        pair->Initialize(info);
        Matrix lhs;
        Vector rhs;
        pair->CalculateLocalSystem(lhs, rhs, info);
        ASSERT_FALSE(pair->Is(ISOLATED)) << GetParam() << " state " << state;
        Vector rhs_only;
        pair->CalculateRightHandSide(rhs_only, info);
        EXPECT_LT((rhs_only - rhs).norm(), 1e-12 * (1.0 + rhs.norm()));
        const auto dofs = LocalDofs(*pair, row);
        const double h = 1e-5;
        Matrix fd(row.matrix_size, row.matrix_size);
        for (int q = 0; q < row.matrix_size; ++q) {
            Vector plus, minus;
            Perturb(dofs[q], h);
            if (row.normal_variation) UpdateNormals(*pair, row.dim);
            pair->CalculateRightHandSide(plus, info);
            Perturb(dofs[q], -2.0 * h);
            if (row.normal_variation) UpdateNormals(*pair, row.dim);
            pair->CalculateRightHandSide(minus, info);
            Perturb(dofs[q], h);
            if (row.normal_variation) UpdateNormals(*pair, row.dim);
            fd.col(q) = -(plus - minus) / (2.0 * h);
        }
        ASSERT_FALSE(pair->Is(ISOLATED));
        ASSERT_GT(lhs.norm(), 0.0);
        const double error = RowwiseRelativeError(lhs, fd);
        worst = std::max(worst, error);
        EXPECT_LT(error, 1e-6) << GetParam() << " state " << state;
    }
    std::printf("[ FD       ] %-52s worst row-wise relative error %.2e\n", GetParam().c_str(), worst);
}

/// Matching flat faces at a uniform gap g, all nodes active: WEIGHTED_GAP_j = g ∫N_j, NODAL_AREA_j = ∫N_j (penalty
/// only; the ALM contribution leaves it untouched) and the RHS of docs/theory/contact_residuals.md §3 (ALM) or §6
/// (penalty).
class MatchingPairNames : public ::testing::TestWithParam<std::string> {};

/// A tangential multiplier of the flat pairs (normal ±y in 2D, ±z in 3D): zero unless components family.
Array3 Tangential(const ContactConditionName& row, int j) {
    if (!IsComponents(row)) return Array3::Zero();
    return row.dim == 2 ? Array3(0.03 * (j + 1), 0.0, 0.0) : Array3(0.02 * (j + 1), -0.01 * j, 0.0);
}

/// The registered names of the three frictionless families (the other families have their own test files).
std::vector<ContactConditionName> FrictionlessRows() {
    std::vector<ContactConditionName> rows;
    for (const auto& row : RegisteredContactConditionNames())
        if (row.family == "ALMFrictionless" || row.family == "ALMFrictionlessComponents" ||
            row.family == "PenaltyFrictionless")
            rows.push_back(row);
    return rows;
}

std::vector<std::string> FrictionlessNames() {
    std::vector<std::string> names;
    for (const auto& row : FrictionlessRows()) names.push_back(row.name);
    return names;
}

std::vector<std::string> MatchingPairRegisteredNames() {
    std::vector<std::string> names;
    for (const auto& row : FrictionlessRows())
        if (row.num_slave == row.num_master) names.push_back(row.name);
    return names;
}

/// ∫N_j over the slave face of FlatMatchingPair: plane faces area/n; axisymmetric line ∫ 2π r / t N_j ds (t = 1).
double FlatNodalMeasure(const ContactConditionName& row, const Geometry& slave, int j) {
    if (row.axisymmetric) return 2.0 * M_PI * (slave[j].X() / 3.0 + slave[1 - j].X() / 6.0);
    return (row.num_slave == 3 ? 0.5 : 1.0) / row.num_slave;
}

TEST_P(MatchingPairNames, MatchingFlatPairUnderUniformGap) {
    const auto& row = DecodedName(GetParam());
    const double g = 0.01, k = 2.0, eps = 30.0;
    Eigen::MatrixXd s, m;
    FlatMatchingPair(row, g, s, m);
    ContactPairModel model;
    auto pair = model.MakeNormalPair(GetParam(), s, m, 1.0);
    ProcessInfo info;
    info.SetValue(SCALE_FACTOR, k);
    auto& slave = const_cast<Geometry&>(pair->GetParentGeometry());
    const auto& master = pair->GetPairedGeometry();
    std::vector<double> lambda(row.num_slave);
    for (int j = 0; j < row.num_slave; ++j) {
        slave[j].Set(ACTIVE, true);
        slave[j].SetValue(INITIAL_PENALTY, eps);
        lambda[j] = -0.1 * (j + 1);
        SetMultiplier(slave[j], lambda[j], Tangential(row, j));
    }
    pair->Initialize(info);
    pair->AddExplicitContribution(info);
    std::vector<double> nodal_measure(row.num_slave);
    for (int j = 0; j < row.num_slave; ++j) {
        nodal_measure[j] = FlatNodalMeasure(row, slave, j);
        EXPECT_NEAR(slave[j].FastGetSolutionStepValue(WEIGHTED_GAP), g * nodal_measure[j], 1e-12) << j;
        EXPECT_NEAR(slave[j].GetValue(NODAL_AREA), nodal_measure[j], 1e-12) << j;  // every family
    }
    Vector rhs;
    pair->CalculateRightHandSide(rhs, info);
    const int d = row.dim, nm = row.num_master, ns = row.num_slave;
    Vector expected = Vector::Zero(row.matrix_size);
    for (int j = 0; j < ns; ++j) {
        const double gap = g * nodal_measure[j];
        const Array3 n = slave[j].FastGetSolutionStepValue(NORMAL);
        // Force vector: ε g̃ n (penalty), (k λ_n + ε g̃) n (ALM), k λ + ε g̃ n (components: tangential part included).
        Array3 force = ((IsPenalty(row) ? 0.0 : k * lambda[j]) + eps * gap) * n;
        if (IsComponents(row)) force += k * Tangential(row, j);
        int l = 0;
        while ((master[l].Coordinates() - slave[j].Coordinates()).head(d - 0).cwiseAbs().maxCoeff() > 2 * g) ++l;
        for (int c = 0; c < d; ++c) {
            expected[d * nm + j * d + c] += force[c] * nodal_measure[j];
            expected[l * d + c] -= force[c] * nodal_measure[j];
        }
        if (IsComponents(row))  // k g̃ n − k²/ε P λ, P λ = the tangential part
            for (int c = 0; c < d; ++c)
                expected[d * (nm + ns) + j * d + c] = k * gap * n[c] - k * k / eps * Tangential(row, j)[c];
        else if (!IsPenalty(row))
            expected[d * (nm + ns) + j] = k * gap;
    }
    EXPECT_LT((rhs - expected).norm(), 1e-10 * (1.0 + expected.norm())) << "rhs\n" << rhs.transpose() << "\nexpected\n"
                                                                     << expected.transpose();
}

/// A pair is reused from step to step while its slave face slides: the search pairs a face with master faces it does
/// not overlap yet. Such a pair is ISOLATED at its first explicit pass; once the master lies under the face, the next
/// pass must count it again (NODAL_AREA, WEIGHTED_GAP, residual). The flag used to stay set for the life of the pair:
/// on the sliding cylinders of the example collection NODAL_AREA fell to 1e-5 of the tributary area and the pressure
/// (force / NODAL_AREA) spiked to 1e5 x the median (issue 17).
TEST_P(MatchingPairNames, PairIsolatedAtAnEarlierPassCountsOnceItOverlaps) {
    const auto& row = DecodedName(GetParam());
    const double g = 0.01, k = 2.0, eps = 30.0, shift = 5.0;  // master starts beside the slave, along x
    Eigen::MatrixXd s, m;
    FlatMatchingPair(row, g, s, m);
    m.col(0).array() += shift;
    ContactPairModel model;
    auto pair = model.MakeNormalPair(GetParam(), s, m, 1.0);
    ProcessInfo info;
    info.SetValue(SCALE_FACTOR, k);
    auto& slave = const_cast<Geometry&>(pair->GetParentGeometry());
    auto& master = const_cast<Geometry&>(pair->GetPairedGeometry());
    for (int j = 0; j < row.num_slave; ++j) {
        slave[j].Set(ACTIVE, true);
        slave[j].SetValue(INITIAL_PENALTY, eps);
        SetMultiplier(slave[j], -0.1 * (j + 1));
    }
    pair->Initialize(info);
    const auto pass = [&] {
        for (int j = 0; j < row.num_slave; ++j) ContactUtilities::ResetExplicitNodalValues(slave[j]);
        pair->AddExplicitContribution(info);
    };
    pass();
    ASSERT_TRUE(pair->Is(ISOLATED));
    for (int j = 0; j < row.num_slave; ++j) EXPECT_EQ(slave[j].GetValue(NODAL_AREA), 0.0) << j;
    Vector rhs;
    pair->CalculateRightHandSide(rhs, info);
    EXPECT_EQ(rhs.norm(), 0.0);

    // The master slides under the slave (a moving mesh: coordinates = X0 + u).
    for (std::size_t l = 0; l < master.size(); ++l) {
        master[l].FastGetSolutionStepValue(DISPLACEMENT)[0] = -shift;
        master[l].Coordinates()[0] -= shift;
    }
    pass();
    EXPECT_FALSE(pair->Is(ISOLATED));
    for (int j = 0; j < row.num_slave; ++j) {
        const double measure = FlatNodalMeasure(row, slave, j);
        EXPECT_NEAR(slave[j].GetValue(NODAL_AREA), measure, 1e-12) << j;
        EXPECT_NEAR(slave[j].FastGetSolutionStepValue(WEIGHTED_GAP), g * measure, 1e-12) << j;
    }
    pair->CalculateRightHandSide(rhs, info);
    EXPECT_GT(rhs.norm(), 0.0);

    // And away again: isolated by the next pass, nothing left in the nodal sums.
    for (std::size_t l = 0; l < master.size(); ++l) {
        master[l].FastGetSolutionStepValue(DISPLACEMENT)[0] = 0.0;
        master[l].Coordinates()[0] += shift;
    }
    pass();
    EXPECT_TRUE(pair->Is(ISOLATED));
    for (int j = 0; j < row.num_slave; ++j) EXPECT_EQ(slave[j].GetValue(NODAL_AREA), 0.0) << j;
}

/// Penalty only (docs/theory/contact_residuals.md §6): no SCALE_FACTOR needed; inactive nodes contribute nothing (all
/// inactive → zero system);
/// an active node without INITIAL_PENALTY is an input error.
class PenaltyFrictionlessNames : public ::testing::TestWithParam<std::string> {};

std::vector<std::string> PenaltyRegisteredNames() {
    std::vector<std::string> names;
    for (const auto& row : FrictionlessRows())
        if (IsPenalty(row)) names.push_back(row.name);
    return names;
}

TEST_P(PenaltyFrictionlessNames, InactiveNodesContributeNothingAndActiveOnesNeedAPenalty) {
    const auto& row = DecodedName(GetParam());
    ContactPairModel model;
    std::mt19937 rng(11);
    Eigen::MatrixXd s, m;
    RandomPairCoordinates(row, rng, s, m);
    auto pair = model.MakeNormalPair(GetParam(), s, m, 1.5);
    ProcessInfo info;  // no SCALE_FACTOR: the penalty family does not read it
    auto& slave = const_cast<Geometry&>(pair->GetParentGeometry());
    for (std::size_t j = 0; j < slave.size(); ++j) slave[j].Set(ACTIVE, false);  // no INITIAL_PENALTY either
    pair->Initialize(info);
    Matrix lhs;
    Vector rhs;
    pair->CalculateLocalSystem(lhs, rhs, info);
    ASSERT_FALSE(pair->Is(ISOLATED));
    EXPECT_EQ(lhs.rows(), row.matrix_size);
    EXPECT_EQ(lhs.norm(), 0.0);
    EXPECT_EQ(rhs.norm(), 0.0);
    slave[0].Set(ACTIVE, true);
    EXPECT_THROW(pair->CalculateLocalSystem(lhs, rhs, info), InputError);
    slave[0].SetValue(INITIAL_PENALTY, 10.0);
    pair->CalculateLocalSystem(lhs, rhs, info);
    EXPECT_GT(lhs.norm(), 0.0);
}

/// ALM families (docs/theory/contact_residuals.md §3, §4): on inactive nodes RHS_λ = −k²/ε λ, LHS_λλ = k²/ε I and
/// nothing else, so the Newton
/// step returns every multiplier (all components for the components family) to zero.
class ALMInactiveNames : public ::testing::TestWithParam<std::string> {};

std::vector<std::string> ALMRegisteredNames() {
    std::vector<std::string> names;
    for (const auto& row : FrictionlessRows())
        if (!IsPenalty(row)) names.push_back(row.name);
    return names;
}

TEST_P(ALMInactiveNames, InactiveNodesReturnTheMultipliersToZero) {
    const auto& row = DecodedName(GetParam());
    ContactPairModel model;
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Eigen::MatrixXd s, m;
    RandomPairCoordinates(row, rng, s, m);
    auto pair = model.MakeNormalPair(GetParam(), s, m, 1.5);
    const double k = 1.7;
    ProcessInfo info;
    info.SetValue(SCALE_FACTOR, k);
    auto& slave = const_cast<Geometry&>(pair->GetParentGeometry());
    for (std::size_t j = 0; j < slave.size(); ++j) {
        slave[j].Set(ACTIVE, false);
        slave[j].SetValue(INITIAL_PENALTY, 5.0 + 10.0 * u(rng));
        slave[j].SetValue(DYNAMIC_FACTOR, 0.7);
        SetMultiplier(slave[j], -u(rng), Array3(0.1 * u(rng), 0.1 * u(rng), row.dim == 3 ? 0.1 * u(rng) : 0.0));
    }
    pair->Initialize(info);
    Matrix lhs;
    Vector rhs;
    pair->CalculateLocalSystem(lhs, rhs, info);
    ASSERT_FALSE(pair->Is(ISOLATED));
    const int nu = row.dim * (row.num_slave + row.num_master), nl = row.matrix_size - nu;
    EXPECT_EQ(rhs.head(nu).norm(), 0.0);
    EXPECT_EQ(lhs.topRows(nu).norm(), 0.0);
    EXPECT_EQ(lhs.bottomLeftCorner(nl, nu).norm(), 0.0);
    const auto dofs = LocalDofs(*pair, row);
    for (int i = 0; i < nl; ++i) {
        const LocalDof& dof = dofs[nu + i];
        const double eps = dof.node->GetValue(INITIAL_PENALTY);
        const double lambda = dof.component < 0 ? dof.node->FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE)
                                                : dof.node->FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER)[dof.component - kVectorMultiplier];
        for (int j = 0; j < nl; ++j) EXPECT_NEAR(lhs(nu + i, nu + j), i == j ? k * k / eps : 0.0, 1e-12) << i << " " << j;
        const double delta = rhs[nu + i] / lhs(nu + i, nu + i);  // LHS Δq = RHS
        EXPECT_NEAR(lambda + delta, 0.0, 1e-12) << i;
    }
}

/// The pair's weighted gap far from the origin: taken about the slave face (MortarDifference), its round-off is that of
/// the face size, not of the position. Computed from absolute coordinates it carried ε·|x|·Σ|D|, which times the penalty
/// was the multiplier residual's floor of the 3D press fit (about 1e-9 against its absolute tolerance 1e-9).
TEST(MortarDifference, WeightedGapRoundOffDoesNotGrowWithTheDistanceFromTheOrigin) {
    using Pair = MortarPairTraits<3, 4, 4>;
    struct PairState {
        MortarOperators<double, 4, 4> operators;
        NodeCoordinates<double, 3, 4> x1, x2, normals;
    };
    std::mt19937 rng(7);
    int compared = 0;
    double worst_absolute = 0.0;
    for (int sample = 0; sample < 20; ++sample) {
        const auto pair = MakeRandomPair<Pair>(rng, 0.3);
        const MortarIntegrator<3, 4, 4, double> integrator;
        PairState home{{}, pair.slave, pair.master, FaceNodalUnitNormals<3, 4, double>(pair.slave)};
        const auto integrated = IntegrateMortarPair(integrator, pair.slave, FaceCenterUnitNormal<3, 4, double>(pair.slave),
                                                    pair.master, home.normals, true);
        if (!integrated.used) continue;
        home.operators = integrated.operators;
        PairState away = home;  // the same operators and normals (they are translation invariant), moved coordinates
        const Eigen::RowVector3d offset(3.0e4, -2.0e4, 1.0e4);
        away.x1.rowwise() += offset;
        away.x2.rowwise() += offset;
        for (int j = 0; j < 4; ++j) {
            // Reference: the same (already rounded) coordinates in long double, differenced before the products.
            long double reference = 0.0L;
            for (int c = 0; c < 3; ++c) {
                long double r = 0.0L;
                for (int k = 0; k < 4; ++k)
                    r += static_cast<long double>(away.operators.D(j, k)) *
                         (static_cast<long double>(away.x1(k, c)) - static_cast<long double>(away.x1(0, c)));
                for (int l = 0; l < 4; ++l)
                    r -= static_cast<long double>(away.operators.M(j, l)) *
                         (static_cast<long double>(away.x2(l, c)) - static_cast<long double>(away.x1(0, c)));
                reference -= r * static_cast<long double>(away.normals(j, c));
            }
            const double scale = home.operators.D.row(j).cwiseAbs().sum() + home.operators.M.row(j).cwiseAbs().sum();
            const double gap = frictionless_detail::PairGap<double, 3>(away, j);
            // About the face: round-off of ε·h·Σ|D| (h ≈ 1); about the origin it was ε·4e4·Σ|D|.
            EXPECT_LT(std::abs(gap - static_cast<double>(reference)), 64.0 * 2.2e-16 * scale)
                << "sample " << sample << " node " << j;
            const Eigen::RowVector3d absolute = away.operators.D.row(j) * away.x1 - away.operators.M.row(j) * away.x2;
            worst_absolute = std::max(worst_absolute, std::abs(-absolute.dot(away.normals.row(j)) -
                                                               static_cast<double>(reference)) / scale);
            ++compared;
        }
    }
    EXPECT_GT(compared, 40);
    EXPECT_GT(worst_absolute, 1e-13);  // the absolute form's error, which the test would otherwise not notice
}

INSTANTIATE_TEST_SUITE_P(Registered, ALMInactiveNames, ::testing::ValuesIn(ALMRegisteredNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });
INSTANTIATE_TEST_SUITE_P(Registered, PenaltyFrictionlessNames, ::testing::ValuesIn(PenaltyRegisteredNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });
INSTANTIATE_TEST_SUITE_P(Registered, MatchingPairNames, ::testing::ValuesIn(MatchingPairRegisteredNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });
INSTANTIATE_TEST_SUITE_P(Registered, FrictionlessMortarNames, ::testing::ValuesIn(FrictionlessNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace contact_app::testing
