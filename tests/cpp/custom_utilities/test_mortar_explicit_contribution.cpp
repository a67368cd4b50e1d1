// SPDX-License-Identifier: BSD-3-Clause
// Explicit contributions: weighted gap, weighted slip, nodal area (reference signs) and the ISOLATED rule.
#include <gtest/gtest.h>

#include "custom_utilities/mortar_explicit_contribution.h"
#include "custom_utilities/mortar_normals.h"
#include "tests/cpp/custom_utilities/mortar_test_utilities.h"

namespace contact_app {
namespace {

template <class TPair>
class MortarExplicitContributionTest : public ::testing::Test {
public:
    static constexpr int D = TPair::Dim, NS = TPair::NumSlave, NM = TPair::NumMaster;
    /// Slave: unit face in z = 0 (y = 0) with normal +z (+y); master: a much larger face at height @p gap.
    static testing::RandomPair<TPair> CoveredPair(double gap) {
        testing::RandomPair<TPair> pair;
        if constexpr (D == 2) {
            pair.slave << 1, 0, 0, 0;
            pair.master << -2, gap, 3, gap;
        } else {
            if constexpr (NS == 3) pair.slave << 0, 0, 0, 1, 0, 0, 0, 1, 0;
            else pair.slave << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
            if constexpr (NM == 3) pair.master << -5, -5, gap, -5, 15, gap, 15, -5, gap;
            else pair.master << -5, -5, gap, -5, 5, gap, 5, 5, gap, 5, -5, gap;
        }
        return pair;
    }
    static double SlaveMeasure() { return D == 2 ? 1.0 : (NS == 3 ? 0.5 : 1.0); }
};
TYPED_TEST_SUITE(MortarExplicitContributionTest, testing::PairKinds, testing::PairKindName);

TYPED_TEST(MortarExplicitContributionTest, test_weighted_gap_and_nodal_area_for_parallel_faces) {
    constexpr int D = TestFixture::D, NS = TestFixture::NS, NM = TestFixture::NM;
    const MortarIntegrator<D, NS, NM, double> integrator;
    for (double gap : {0.1, -0.05}) {
        const auto pair = TestFixture::CoveredPair(gap);
        const auto normals = FaceNodalUnitNormals<D, NS, double>(pair.slave);
        ExplicitContributionOptions options;
        options.compute_nodal_area = true;
        const auto result = ComputeExplicitMortarContribution(integrator, pair.slave,
                                                              FaceCenterUnitNormal<D, NS, double>(pair.slave),
                                                              pair.master, normals, options);
        ASSERT_FALSE(result.isolated);
        ASSERT_TRUE(result.dual);
        EXPECT_NEAR(result.nodal_area.sum(), TestFixture::SlaveMeasure(), 1e-12);
        // g̃_i = gap · NODAL_AREA_i: positive when open, negative when penetrating.
        EXPECT_LT((result.weighted_gap - gap * result.nodal_area).cwiseAbs().maxCoeff(), 1e-12);
    }
}

TYPED_TEST(MortarExplicitContributionTest, test_weighted_slip_of_a_tangential_master_motion) {
    constexpr int D = TestFixture::D, NS = TestFixture::NS, NM = TestFixture::NM;
    const MortarIntegrator<D, NS, NM, double> integrator;
    const auto start = TestFixture::CoveredPair(0.0);
    auto moved = start;
    SpatialVector<double, D> delta = SpatialVector<double, D>::Zero();
    delta[0] = 0.01;
    moved.master.rowwise() += delta.transpose();
    const auto normals = FaceNodalUnitNormals<D, NS, double>(start.slave);
    const auto n_s = FaceCenterUnitNormal<D, NS, double>(start.slave);
    bool dual = false;
    const auto previous = ComputePreviousMortarOperators(integrator, start.slave, n_s, start.master, normals, dual);
    ASSERT_TRUE(dual);
    const double dt = 0.5;
    ExplicitContributionOptions options;
    const auto non_objective = ComputeExplicitFrictionalMortarContribution(
        integrator, moved.slave, n_s, moved.master, normals, previous, start.slave, start.master, dt, false, options);
    // −[D·0 − M·δ] = M δ: every slave node slips by δ · Σ_l M_il = δ · NODAL_AREA_i (dual, full overlap).
    for (int i = 0; i < NS; ++i)
        EXPECT_LT((non_objective.weighted_slip.row(i) - previous.D(i, i) * delta.transpose()).norm(), 1e-12);
    // Objective form: −(M − M_prev) x2 = M_prev δ as well (M x2 is the projected point, unchanged by the motion).
    const auto objective = ComputeExplicitFrictionalMortarContribution(
        integrator, moved.slave, n_s, moved.master, normals, previous, start.slave, start.master, dt, true, options);
    EXPECT_LT((objective.weighted_slip - non_objective.weighted_slip).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((objective.weighted_gap - non_objective.weighted_gap).cwiseAbs().maxCoeff(), 1e-15);
}

TYPED_TEST(MortarExplicitContributionTest, test_isolated_rule_flags_tiny_or_empty_overlaps) {
    constexpr int D = TestFixture::D, NS = TestFixture::NS, NM = TestFixture::NM;
    const MortarIntegrator<D, NS, NM, double> integrator;
    auto pair = TestFixture::CoveredPair(0.0);
    const auto normals = FaceNodalUnitNormals<D, NS, double>(pair.slave);
    const auto n_s = FaceCenterUnitNormal<D, NS, double>(pair.slave);
    // Shift the master so that it overlaps the slave only over 1e-7 of its width.
    const double right = pair.master.col(0).minCoeff();
    pair.master.col(0).array() += 1.0 - 1e-7 - right;
    if constexpr (D == 3) pair.master.col(1).array() -= pair.master.col(1).minCoeff();  // keep y inside
    const auto result = ComputeExplicitMortarContribution(integrator, pair.slave, n_s, pair.master, normals, {});
    EXPECT_TRUE(result.isolated);
    EXPECT_TRUE(result.weighted_gap.isZero());
    pair.master.col(0).array() += 5.0;  // no overlap at all
    EXPECT_TRUE(ComputeExplicitMortarContribution(integrator, pair.slave, n_s, pair.master, normals, {}).isolated);
}

}  // namespace
}  // namespace contact_app
