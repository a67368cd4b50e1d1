// SPDX-License-Identifier: BSD-3-Clause
// Mortar operators and dual basis: consistency, invariances, Gauss orders, biorthogonality, AD vs FD.
#include <gtest/gtest.h>

#include <cstdio>

#include "automatic_differentiation/ad_helpers.h"
#include "custom_utilities/mortar_explicit_contribution.h"
#include "custom_utilities/mortar_normals.h"
#include "custom_utilities/mortar_operators.h"
#include "tests/cpp/custom_utilities/mortar_test_utilities.h"

namespace contact_app {
namespace {

template <class TPair>
class MortarOperatorsTest : public ::testing::Test {
public:
    static constexpr int D = TPair::Dim, NS = TPair::NumSlave, NM = TPair::NumMaster, N = TPair::NumDofs;
    using AD = typename TPair::ADScalar;

    /// D, M (standard or dual) of a pair with its own normals.
    static MortarPairIntegration<double, D, NS, NM> Integrate(const testing::RandomPair<TPair>& pair, bool dual,
                                                             int order = 2) {
        MortarIntegrationSettings settings;
        settings.integration_order = order;
        const MortarIntegrator<D, NS, NM, double> integrator(settings);
        const auto normals = FaceNodalUnitNormals<D, NS, double>(pair.slave);
        return IntegrateMortarPair(integrator, pair.slave, FaceCenterUnitNormal<D, NS, double>(pair.slave), pair.master,
                                   normals, dual);
    }

    /// Outputs differentiated in the AD test: D, M, Ae, weighted gap (+ normals with NV), flattened.
    template <class T>
    static std::vector<T> Outputs(const NodeCoordinates<T, D, NS>& x1, const NodeCoordinates<T, D, NM>& x2, bool nv,
                                  const SpatialVector<double, D>& fixed_normal,
                                  const NodeCoordinates<double, D, NS>& fixed_nodal, bool* has_edge_vertex) {
        MortarIntegrationSettings settings;
        settings.integration_order = 3;
        const MortarIntegrator<D, NS, NM, T> integrator(settings);
        std::vector<T> out;
        auto collect = [&](const auto& result, const auto& normals) {
            for (int i = 0; i < NS; ++i) {
                for (int k = 0; k < NS; ++k) out.push_back(result.operators.D(i, k));
                for (int k = 0; k < NS; ++k) out.push_back(result.dual.Ae(i, k));
                for (int l = 0; l < NM; ++l) out.push_back(result.operators.M(i, l));
            }
            const auto gap = WeightedGap<D, NS, NM>(result.operators, x1, x2, normals);
            for (int i = 0; i < NS; ++i) out.push_back(gap[i]);
            if (has_edge_vertex)
                for (const auto& cell : result.cells)
                    for (int tag : cell.belong) *has_edge_vertex |= tag > NS + NM;
        };
        if (nv) {
            const SpatialVector<T, D> normal = FaceCenterUnitNormal<D, NS, T>(x1);
            const NodeCoordinates<T, D, NS> nodal = FaceNodalUnitNormals<D, NS, T>(x1);
            collect(IntegrateMortarPair(integrator, x1, normal, x2, nodal, true), nodal);
            for (int i = 0; i < NS; ++i)
                for (int c = 0; c < D; ++c) out.push_back(nodal(i, c));
        } else {
            collect(IntegrateMortarPair(integrator, x1, fixed_normal, x2, fixed_nodal, true), fixed_nodal);
        }
        return out;
    }

    /// max |J_AD − J_FD| / max |J_FD| over all outputs and coordinates.
    static double RelativeError(const testing::RandomPair<TPair>& pair, bool nv, bool* has_edge_vertex) {
        const auto fixed_normal = FaceCenterUnitNormal<D, NS, double>(pair.slave);
        const auto fixed_nodal = FaceNodalUnitNormals<D, NS, double>(pair.slave);
        const auto x1 = Seed<N>(pair.slave, 0);
        const auto x2 = Seed<N>(pair.master, NS * D);
        const std::vector<AD> ad = Outputs<AD>(x1, x2, nv, fixed_normal, fixed_nodal, has_edge_vertex);
        const double h = 1.0e-6;
        double max_error = 0.0, max_reference = 0.0;
        for (int q = 0; q < N; ++q) {
            auto plus1 = pair.slave, minus1 = pair.slave;
            auto plus2 = pair.master, minus2 = pair.master;
            if (q < NS * D) {
                plus1(q / D, q % D) += h;
                minus1(q / D, q % D) -= h;
            } else {
                plus2((q - NS * D) / D, q % D) += h;
                minus2((q - NS * D) / D, q % D) -= h;
            }
            const auto fp = Outputs<double>(plus1, plus2, nv, fixed_normal, fixed_nodal, nullptr);
            const auto fm = Outputs<double>(minus1, minus2, nv, fixed_normal, fixed_nodal, nullptr);
            EXPECT_EQ(fp.size(), ad.size());
            for (std::size_t k = 0; k < ad.size() && k < fp.size(); ++k) {
                const double fd = (fp[k] - fm[k]) / (2.0 * h);
                max_error = std::max(max_error, std::abs(fd - ad[k].Derivatives()[q]));
                max_reference = std::max(max_reference, std::abs(fd));
            }
        }
        return max_error / std::max(max_reference, 1e-300);
    }
};
TYPED_TEST_SUITE(MortarOperatorsTest, testing::PairKinds, testing::PairKindName);

TYPED_TEST(MortarOperatorsTest, test_operators_consistency_sum_d_equals_sum_m) {
    std::mt19937 rng(1);
    for (int sample = 0; sample < 50; ++sample) {
        const auto pair = testing::MakeRandomPair<TypeParam>(rng, 0.5);
        for (bool dual : {false, true}) {
            const auto result = TestFixture::Integrate(pair, dual, 4);
            if (!result.used) continue;
            EXPECT_NEAR(result.operators.D.sum(), result.operators.M.sum(), 1e-9 * std::abs(result.operators.D.sum()) + 1e-14);
            EXPECT_NEAR(result.operators.D.sum(), result.area, 1e-10);
        }
    }
}

TYPED_TEST(MortarOperatorsTest, test_operators_matching_meshes_give_d_equal_m) {
    if constexpr (TypeParam::NumSlave == TypeParam::NumMaster) {
        std::mt19937 rng(2);
        for (int sample = 0; sample < 10; ++sample) {
            auto pair = testing::MakeRandomPair<TypeParam>(rng, 0.5);
            pair.master = pair.slave;
            for (bool dual : {false, true}) {
                const auto result = TestFixture::Integrate(pair, dual, 3);
                ASSERT_TRUE(result.used);
                EXPECT_LT((result.operators.D - result.operators.M).cwiseAbs().maxCoeff(), 1e-12);
            }
        }
    }
}

TYPED_TEST(MortarOperatorsTest, test_operators_rigid_master_translation_along_normal_keeps_d) {
    std::mt19937 rng(3);
    for (int sample = 0; sample < 20; ++sample) {
        auto pair = testing::MakeRandomPair<TypeParam>(rng, 0.4);
        const auto before = TestFixture::Integrate(pair, true);
        if (!before.used) continue;
        const auto n = FaceCenterUnitNormal<TestFixture::D, TestFixture::NS, double>(pair.slave);
        pair.master.rowwise() += 0.37 * n.transpose();
        const auto after = TestFixture::Integrate(pair, true);
        ASSERT_TRUE(after.used);
        EXPECT_LT((before.operators.D - after.operators.D).cwiseAbs().maxCoeff(), 1e-9);
    }
}

// A pair far from the origin (|x| up to 10^4 face sizes) has the operators of the same pair at the origin. Before the
// projections iterated on coordinates relative to the face, their Newton steps stalled on the round-off of ε|x| and
// Gauss points were dropped at random: D row sums of the frictional double arch (|x| ≈ 15 face sizes) jumped by up to
// 37 % between iterates that differed by 1e-8 (docs/theory/mortar.md §2).
TYPED_TEST(MortarOperatorsTest, test_operators_do_not_depend_on_where_the_pair_lies) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int sample = 0; sample < 20; ++sample) {
        const auto pair = testing::MakeRandomPair<TypeParam>(rng, 0.4);
        const auto home = TestFixture::Integrate(pair, true, 3);
        if (!home.used) continue;
        for (double distance : {15.0, 1.0e3, 1.0e4}) {
            SpatialVector<double, TestFixture::D> offset;
            for (int c = 0; c < TestFixture::D; ++c) offset[c] = u(rng);
            offset *= distance / offset.norm();
            auto moved = pair;
            moved.slave.rowwise() += offset.transpose();
            moved.master.rowwise() += offset.transpose();
            const auto away = TestFixture::Integrate(moved, true, 3);
            ASSERT_TRUE(away.used) << "distance " << distance;
            // Translated coordinates carry ε·distance of round-off; the operators may move by that much, no more.
            const double tolerance = 1e-14 * distance;
            EXPECT_NEAR(away.area, home.area, tolerance) << "distance " << distance;
            EXPECT_LT((away.operators.D - home.operators.D).cwiseAbs().maxCoeff(), tolerance) << "distance " << distance;
            EXPECT_LT((away.operators.M - home.operators.M).cwiseAbs().maxCoeff(), tolerance) << "distance " << distance;
        }
    }
}

// Where the overlap polygon gains a vertex (a master node crossing a slave edge, or a slave node a master edge) the
// cells change. Fanned around the polygon's area centroid (the default) the operators stay continuous there; fanned
// from the first vertex (the reference's default) they jump by the quadrature error, which made D and M of the 3D press
// fit alternate between two values at fixed contact sets (docs/theory/mortar.md §1).
TYPED_TEST(MortarOperatorsTest, test_operators_are_continuous_where_the_overlap_gains_a_vertex) {
    if constexpr (TestFixture::D == 3) {
        constexpr int D = TestFixture::D, NS = TestFixture::NS, NM = TestFixture::NM;
        const auto integrate = [](const testing::RandomPair<TypeParam>& pair, bool tessellation) {
            SegmentationSettings segmentation;
            segmentation.consider_tessellation = tessellation;
            const MortarIntegrator<D, NS, NM, double> integrator(MortarIntegrationSettings{}, segmentation);
            const auto normals = FaceNodalUnitNormals<D, NS, double>(pair.slave);
            return IntegrateMortarPair(integrator, pair.slave, FaceCenterUnitNormal<D, NS, double>(pair.slave),
                                       pair.master, normals, true);
        };
        std::mt19937 rng(12);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        int events = 0;
        double worst_centroid = 0.0, worst_first_vertex = 0.0;
        for (int sample = 0; sample < 40; ++sample) {
            const auto pair = testing::MakeRandomPair<TypeParam>(rng, 0.3, false);  // slave in z = 0
            Eigen::RowVector3d direction(u(rng), u(rng), 0.0);
            direction.normalize();
            const auto moved = [&](double s) {
                auto p = pair;
                p.master.rowwise() += s * direction;
                return p;
            };
            const auto vertices = [&](double s) {  // cells of the first-vertex fan: polygon vertices − 2
                const auto r = integrate(moved(s), false);
                return r.used ? static_cast<int>(r.cells.size()) : -1;
            };
            for (double s = 0.0; s < 0.6; s += 0.02) {
                if (vertices(s) < 0 || vertices(s + 0.02) < 0 || vertices(s) == vertices(s + 0.02)) continue;
                double lo = s, hi = s + 0.02;  // bisect to the change of the polygon
                for (int k = 0; k < 60 && hi - lo > 1e-13; ++k) {
                    const double mid = 0.5 * (lo + hi);
                    (vertices(mid) == vertices(lo) ? lo : hi) = mid;
                }
                for (const bool tessellation : {true, false}) {
                    const auto a = integrate(moved(lo), tessellation), b = integrate(moved(hi), tessellation);
                    if (!a.used || !b.used) continue;
                    const double jump = std::max((a.operators.D - b.operators.D).cwiseAbs().maxCoeff(),
                                                 (a.operators.M - b.operators.M).cwiseAbs().maxCoeff());
                    (tessellation ? worst_centroid : worst_first_vertex) =
                        std::max(tessellation ? worst_centroid : worst_first_vertex, jump);
                }
                ++events;
            }
        }
        std::printf("[ cells    ] %d vertex changes: largest jump of D, M %.2e (area-centroid fan), %.2e (first-vertex fan)\n",
                    events, worst_centroid, worst_first_vertex);
        EXPECT_GT(events, 20);
        EXPECT_LT(worst_centroid, 1e-9);       // continuous (the bisection interval is 1e-13)
        if constexpr (NS == 4 || NM == 4) {     // bilinear integrands: the order-2 rule is not exact
            EXPECT_GT(worst_first_vertex, 1e-6);  // what the default avoids
        }
    }
}

TYPED_TEST(MortarOperatorsTest, test_dual_basis_is_biorthogonal) {
    std::mt19937 rng(4);
    for (int sample = 0; sample < 30; ++sample) {
        const auto pair = testing::MakeRandomPair<TypeParam>(rng, 0.5);
        const auto standard = TestFixture::Integrate(pair, false, 3);
        const auto dual = TestFixture::Integrate(pair, true, 3);
        if (!dual.used) continue;
        ASSERT_TRUE(dual.dual.dual);
        // ∫Φ_j N_k = D_jk is diagonal, and D_jj = ∫N_j (Σ_k Φ_j… row sums are preserved by Ae).
        const auto& d = dual.operators.D;
        const double scale = d.cwiseAbs().maxCoeff();
        EXPECT_LT((d - Eigen::Matrix<double, TestFixture::NS, TestFixture::NS>(d.diagonal().asDiagonal())).cwiseAbs().maxCoeff(), 1e-10 * scale);
        EXPECT_LT((d.diagonal() - standard.operators.D.rowwise().sum()).cwiseAbs().maxCoeff(), 1e-10 * scale);
    }
}

TYPED_TEST(MortarOperatorsTest, test_dual_basis_falls_back_on_a_degenerate_pair) {
    using Integrator = MortarIntegrator<TestFixture::D, TestFixture::NS, TestFixture::NM, double>;
    std::vector<typename Integrator::GaussPoint> points;  // no integration points: Me = 0
    auto result = Integrator::ComputeDualBasis(points);
    EXPECT_FALSE(result.dual);
    EXPECT_TRUE(result.Ae.isIdentity());
    typename Integrator::GaussPoint p;  // a single point: Me = w N Nᵀ has rank 1
    p.N1.setConstant(1.0 / TestFixture::NS);
    p.N2.setConstant(1.0 / TestFixture::NM);
    p.weight = 0.5;
    points.assign(1, p);
    result = Integrator::ComputeDualBasis(points);
    EXPECT_FALSE(result.dual);
    EXPECT_TRUE(result.Ae.isIdentity());
    const auto operators = Integrator::ComputeOperators(points, result);  // standard multipliers
    EXPECT_NEAR(operators.D.sum(), 0.5, 1e-15);
}

TYPED_TEST(MortarOperatorsTest, test_gauss_orders_integrate_their_degree_on_the_cells) {
    constexpr int D = TestFixture::D, NS = TestFixture::NS, NM = TestFixture::NM;
    // Slave = reference face in the plane (z = 0 / y = 0), master = a larger copy: the cells tile the slave.
    testing::RandomPair<TypeParam> pair;
    if constexpr (D == 2) {
        pair.slave << 1.0, 0.0, -1.0, 0.0;
        pair.master << -3.0, 0.1, 3.0, 0.1;
    } else {
        if constexpr (NS == 3) pair.slave << 0, 0, 0, 1, 0, 0, 0, 1, 0;
        else pair.slave << -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0;
        if constexpr (NM == 3) pair.master << -5, -5, 0.1, -5, 15, 0.1, 15, -5, 0.1;
        else pair.master << -5, -5, 0.1, -5, 5, 0.1, 5, 5, 0.1, 5, -5, 0.1;
    }
    for (int order = 0; order <= 6; ++order) {
        MortarIntegrationSettings settings;
        settings.integration_order = order;
        const MortarIntegrator<D, NS, NM, double> integrator(settings);
        MortarCells<double, D> cells;
        const auto normals = FaceNodalUnitNormals<D, NS, double>(pair.slave);
        ASSERT_TRUE(integrator.GetSegmentation().ComputeCells(pair.slave, FaceCenterUnitNormal<D, NS, double>(pair.slave), pair.master, cells));
        std::vector<typename MortarIntegrator<D, NS, NM, double>::GaussPoint> points;
        integrator.ComputeGaussPoints(pair.slave, FaceCenterUnitNormal<D, NS, double>(pair.slave), pair.master, normals, cells, points);
        const int effective = order >= 1 && order <= 5 ? order : 2;
        const int degree = GaussRuleDegree(D == 2 ? GeometryFamily::Linear : GeometryFamily::Triangle, effective);
        EXPECT_EQ(points.size() / cells.size(), MortarCellGaussRule(D, order).size());
        for (int a = 0; a <= degree; ++a) {
            for (int b = 0; b <= (D == 3 ? degree - a : 0); ++b) {
                double value = 0.0;
                for (const auto& p : points) value += p.weight * std::pow(p.x1[0], a) * (D == 3 ? std::pow(p.x1[1], b) : 1.0);
                double exact;
                if constexpr (D == 2) exact = (a % 2 == 0) ? 2.0 / (a + 1) : 0.0;  // ∫_{-1}^{1} x^a
                else if constexpr (NS == 3) exact = std::tgamma(a + 1) * std::tgamma(b + 1) / std::tgamma(a + b + 3);
                else exact = ((a % 2 == 0) ? 2.0 / (a + 1) : 0.0) * ((b % 2 == 0) ? 2.0 / (b + 1) : 0.0);
                EXPECT_NEAR(value, exact, 1e-12) << "order " << order << " monomial " << a << "," << b;
            }
        }
    }
}

TYPED_TEST(MortarOperatorsTest, test_ad_derivatives_match_central_finite_differences) {
    std::mt19937 rng(5);
    for (bool nv : {false, true}) {
        double worst = 0.0;
        int tested = 0, with_edges = 0;
        for (int sample = 0; sample < 40 && tested < 12; ++sample) {
            const auto pair = testing::MakeRandomPair<TypeParam>(rng, 0.4);
            if (!TestFixture::Integrate(pair, true).used) continue;
            bool has_edge = false;
            const double error = TestFixture::RelativeError(pair, nv, &has_edge);
            EXPECT_LT(error, 1e-6) << "sample " << sample << " nv " << nv;
            worst = std::max(worst, error);
            ++tested;
            with_edges += has_edge;
        }
        EXPECT_GE(tested, 10);
        if (TestFixture::D == 3) EXPECT_GE(with_edges, 5);
        std::printf("[ AD vs FD ] %s nv=%d worst relative error %.3e over %d pairs (%d with edge-intersection vertices)\n",
                    testing::PairKindName::GetName<TypeParam>(0).c_str(), nv, worst, tested, with_edges);
    }
}

// The normal pass of the conditions (docs/theory/mortar.md §7 "Normals that follow the iterate"): the pair integrated
// in double, and M with its derivatives in the nodal normals, which only M reads. Values are those of IntegrateMortarPair,
// derivatives its central differences in the normals (unnormalised, as ν normalises their interpolation).
TYPED_TEST(MortarOperatorsTest, test_operators_over_the_nodal_normals_match_finite_differences) {
    constexpr int D = TestFixture::D, NS = TestFixture::NS, N = TestFixture::N;
    using AD = typename TestFixture::AD;
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> u(-0.2, 0.2);
    const MortarIntegrator<D, NS, TestFixture::NM, double> integrator;
    const auto integrate = [&](const auto& pair, const NodeCoordinates<double, D, NS>& normals) {
        return IntegrateMortarPair(integrator, pair.slave, FaceCenterUnitNormal<D, NS, double>(pair.slave), pair.master,
                                   normals, true);
    };
    int tested = 0;
    double worst = 0.0;
    for (int sample = 0; sample < 40 && tested < 10; ++sample) {
        const auto pair = testing::MakeRandomPair<TypeParam>(rng, 0.4);
        NodeCoordinates<double, D, NS> normals = FaceNodalUnitNormals<D, NS, double>(pair.slave);
        for (int i = 0; i < NS; ++i) {  // nodal normals of a curved surface: each tilted off the face's
            for (int c = 0; c < D; ++c) normals(i, c) += u(rng);
            normals.row(i).normalize();
        }
        const auto reference = integrate(pair, normals);
        if (!reference.used) continue;
        Eigen::Matrix<AD, NS, TestFixture::NM> m;
        const auto result = IntegrateMortarPairOverNormals(integrator, pair.slave,
                                                           FaceCenterUnitNormal<D, NS, double>(pair.slave), pair.master,
                                                           Seed<N>(normals, 0), true, m);
        ASSERT_TRUE(result.used);
        EXPECT_EQ(result.operators.D, reference.operators.D);
        EXPECT_EQ(result.operators.M, reference.operators.M);
        EXPECT_LT((Values(m) - reference.operators.M).cwiseAbs().maxCoeff(), 1e-15);
        const double h = 1.0e-6;
        double error = 0.0, scale = 0.0;
        for (int q = 0; q < D * NS; ++q) {
            auto plus = normals, minus = normals;
            plus(q / D, q % D) += h;
            minus(q / D, q % D) -= h;
            const auto fd = ((integrate(pair, plus).operators.M - integrate(pair, minus).operators.M) / (2.0 * h)).eval();
            for (int j = 0; j < NS; ++j)
                for (int l = 0; l < TestFixture::NM; ++l) {
                    error = std::max(error, std::abs(m(j, l).Derivatives()[q] - fd(j, l)));
                    scale = std::max(scale, std::abs(fd(j, l)));
                }
            for (int q2 = D * NS; q2 < N; ++q2)  // the coordinates are held
                for (int j = 0; j < NS; ++j)
                    for (int l = 0; l < TestFixture::NM; ++l) EXPECT_EQ(m(j, l).Derivatives()[q2], 0.0);
        }
        EXPECT_GT(scale, 1e-4);  // M does move with the normals (by the gap times the tilt)
        EXPECT_LT(error, 1e-6 * scale) << "sample " << sample;
        worst = std::max(worst, error / scale);
        ++tested;
    }
    EXPECT_GE(tested, 10);
    std::printf("[ M over normals ] %s worst relative error %.3e over %d pairs\n",
                testing::PairKindName::GetName<TypeParam>(0).c_str(), worst, tested);
}

}  // namespace
}  // namespace contact_app

namespace contact_app {
namespace {

TEST(MortarOperators, test_axisymmetric_weight_is_two_pi_r_over_thickness) {
    // Slave line from r = 2 to r = 1 (normal +y), master covering it: ΣD = ∫ 2π r / t dr = π (2² − 1²) / t.
    NodeCoordinates<double, 2, 2> slave, master;
    slave << 2.0, 0.0, 1.0, 0.0;
    master << 0.5, 0.1, 3.0, 0.1;
    MortarIntegrationSettings settings;
    settings.axisymmetric_thickness = 0.5;
    const MortarIntegrator<2, 2, 2, double> integrator(settings);
    NodeCoordinates<double, 2, 2> normals;
    normals << 0.0, 1.0, 0.0, 1.0;
    const auto result = IntegrateMortarPair(integrator, slave, SpatialVector<double, 2>(0.0, 1.0), master, normals, true);
    ASSERT_TRUE(result.used);
    ASSERT_TRUE(result.dual.dual);
    EXPECT_NEAR(result.operators.D.sum(), M_PI * 3.0 / 0.5, 1e-12);
    EXPECT_NEAR(result.operators.M.sum(), M_PI * 3.0 / 0.5, 1e-12);
    const MortarOperators<double, 2, 2> previous = result.operators;  // "previous" operators: a plain copy
    EXPECT_EQ(previous.D, result.operators.D);
}

}  // namespace
}  // namespace contact_app
