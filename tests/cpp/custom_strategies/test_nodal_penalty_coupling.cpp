// SPDX-License-Identifier: BSD-3-Clause
/// The nodal penalty's global tangent (docs/theory/mortar.md §7 "Nodal penalty"): a slave face against two
/// non-matching master faces, every slave node shared by both pairs and penetrating by a non-uniform gap, and a 2D chain
/// of three slave faces on four master faces. The pairs' local tangents plus the NodalPenaltyCoupling blocks must equal
/// the central finite differences of the assembled residual, with nothing held: the nodal sums (WEIGHTED_GAP,
/// NODAL_AREA, SQUARED_PAIR_AREA, AREA_WEIGHTED_PAIR_SLIP) recomputed at every perturbed state as the strategy does, so
/// η = Σ_c a_c² / A², A and the transmitted slip T = Σ_c a_c s_c / A vary. Frictional families: every node sticks, or
/// every node slips (its direction reads T of all pairs); also with a triangular slave face on quadrilaterals.
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "../custom_conditions/contact_condition_test_utilities.h"
#include "assembled_tangent_test_utilities.h"
#include "contact_app/solving/schemes/scheme.h"
#include "custom_conditions/nodal_gap_coupling.h"
#include "custom_strategies/nodal_penalty_coupling.h"
#include "custom_utilities/contact_utilities.h"

namespace contact_app::testing {
namespace {

struct CouplingModel {
    ContactPairModel model;
    ModelPart* computing = nullptr;
    std::vector<Condition::Pointer> pairs;
    std::vector<Dof*> dofs;  // the displacement DoFs, numbered 0..n−1
    int dim = 2;
    bool normal_variation = false;
    ProcessInfo info;
};

/// The family's prototype for @p name; frictional families get WEIGHTED_SLIP, a start-of-step buffer and κ = 0.4 (the
/// slip of the step from the undeformed start: κ ε s per pair in stick, its direction in slip).
const PairedCondition& Start(CouplingModel& m, const std::string& name, int dim) {
    m.dim = dim;
    m.computing = &m.model.part->CreateSubModelPart("ComputingContact");
    const auto& row = DecodedName(name);
    if (row.family == "PenaltyFrictional") {
        m.model.part->AddNodalSolutionStepVariable(WEIGHTED_SLIP);
        m.model.part->SetBufferSize(2);
        m.info.SetValue(TANGENT_FACTOR, 0.4);
    }
    m.normal_variation = row.normal_variation;
    return dynamic_cast<const PairedCondition&>(Registry<Condition>::Instance().Get(name));
}

/// The slave nodes' flags and values (normal @p n, ACTIVE but @p inactive, SLIP if @p slip), the pairs initialised
/// into "ComputingContact", the displacement DoFs numbered 0..n−1.
void Finish(CouplingModel& m, const std::vector<IndexType>& slave_ids, const Array3& n, bool slip,
            IndexType inactive = 0) {
    for (IndexType id : slave_ids) {
        Node& node = m.model.part->GetNode(id);
        node.FastGetSolutionStepValue(NORMAL) = n;
        node.Set(ACTIVE, id != inactive);
        node.Set(SLAVE, true);
        node.SetValue(INITIAL_PENALTY, 1.0e3);
        node.SetValue(FRICTION_COEFFICIENT, 0.3);
        node.SetValue(TANGENT_XI, Array3(1.0, 0.0, 0.0));
        node.Set(SLIP, slip);
    }
    const bool frictional = m.model.part->HasNodalSolutionStepVariable(WEIGHTED_SLIP);
    for (auto& pair : m.pairs) {
        pair->SetValue(NORMAL, n);
        pair->Initialize(m.info);
        if (frictional) pair->InitializeSolutionStep(m.info);
        m.computing->AddCondition(pair);
    }
    const Variable<double>* components[] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
    for (const auto& node : m.model.part->Nodes())
        for (int c = 0; c < m.dim; ++c) {
            Dof* dof = &node->GetDof(*components[c]);
            dof->SetEquationId(m.dofs.size());
            m.dofs.push_back(dof);
        }
}

/// 2D: slave [0, 1] at y = 0 (normal +y) against masters [−0.3, 0.4], [0.4, 1.3] sagging below it (penetration
/// 0.01 ... 0.02). 3D: slave quad [0, 1]² (or the triangle of its first three corners, @p triangle) against two quads
/// split at x = 0.6 with a tilted, penetrating surface. Frictional families: every slave node slips when @p slip.
void Build(CouplingModel& m, const std::string& family, int dim, bool slip = false, bool triangle = false) {
    const std::string name = family + (dim == 2 ? "2D2N" : triangle ? "3D3N4N" : "3D4N");
    const auto& row = DecodedName(name);
    const auto& prototype = Start(m, name, dim);
    auto geometry = [&](const std::vector<IndexType>& ids) {
        Geometry::PointsArrayType points;
        for (IndexType id : ids) points.push_back(m.model.part->pGetNode(id));
        return CreateGeometry(FaceGeometryName(row.dim, static_cast<int>(ids.size())), points);
    };
    Array3 n = Array3::Zero();
    std::vector<IndexType> slave_ids;
    if (dim == 2) {
        m.model.AddNode(1, Eigen::Vector2d(1.0, 0.0));
        m.model.AddNode(2, Eigen::Vector2d(0.0, 0.0));
        const double xm[] = {-0.3, 0.4, 1.3}, ym[] = {-0.01, -0.02, -0.012};
        for (int i = 0; i < 3; ++i) m.model.AddNode(11 + i, Eigen::Vector2d(xm[i], ym[i]));
        n = Array3(0.0, 1.0, 0.0);
        auto slave = geometry({1, 2});
        for (int f = 0; f < 2; ++f)
            m.pairs.push_back(prototype.Create(f + 1, slave, m.model.properties,
                                               geometry({IndexType(11 + f), IndexType(12 + f)})));
        slave_ids = {1, 2};
    } else {
        const double xs[][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        const int num_slave = triangle ? 3 : 4;
        for (int i = 0; i < num_slave; ++i) m.model.AddNode(1 + i, Eigen::Vector3d(xs[i][0], xs[i][1], 0.0));
        const double xm[] = {-0.2, 0.6, 1.3}, ym[] = {-0.1, 1.1};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 2; ++j)
                m.model.AddNode(11 + 2 * i + j, Eigen::Vector3d(xm[i], ym[j], -0.01 - 0.01 * xm[i] * xm[i] + 0.005 * ym[j]));
        n = Array3(0.0, 0.0, 1.0);
        slave_ids = triangle ? std::vector<IndexType>{1, 2, 3} : std::vector<IndexType>{1, 2, 3, 4};
        auto slave = geometry(slave_ids);
        for (int f = 0; f < 2; ++f) {
            const IndexType a = 11 + 2 * f;
            m.pairs.push_back(prototype.Create(f + 1, slave, m.model.properties,
                                               geometry({a, IndexType(a + 1), IndexType(a + 3), IndexType(a + 2)})));
        }
    }
    Finish(m, slave_ids, n, slip);
}

/// 2D chain: slave nodes at x = 0, 0.5, 1, 1.5 (y = 0, normal +y) against a sagging non-matching master chain; every
/// overlapping face couple is a pair, so the inner slave nodes hold pairs of both their faces. @p first_inactive leaves
/// slave node 4 (x = 0) out of the active set (an edge of the contact zone).
void BuildChain(CouplingModel& m, const std::string& family, bool slip, bool first_inactive) {
    const auto& prototype = Start(m, family + "2D2N", 2);
    auto geometry = [&](IndexType a, IndexType b) {
        Geometry::PointsArrayType points;
        points.push_back(m.model.part->pGetNode(a));
        points.push_back(m.model.part->pGetNode(b));
        return CreateGeometry(FaceGeometryName(2, 2), points);
    };
    const double xs[] = {0.0, 0.5, 1.0, 1.5};
    for (int i = 0; i < 4; ++i) m.model.AddNode(1 + i, Eigen::Vector2d(xs[3 - i], 0.0));  // faces run right to left
    const double xm[] = {-0.2, 0.35, 0.8, 1.3, 1.8}, ym[] = {-0.01, -0.02, -0.018, -0.012, -0.005};
    for (int i = 0; i < 5; ++i) m.model.AddNode(11 + i, Eigen::Vector2d(xm[i], ym[i]));
    const Array3 n(0.0, 1.0, 0.0);
    IndexType id = 1;
    for (int f = 0; f < 3; ++f) {
        auto slave = geometry(IndexType(1 + f), IndexType(2 + f));
        const double left = xs[2 - f], right = xs[3 - f];
        for (int g = 0; g < 4; ++g)
            if (xm[g] < right && xm[g + 1] > left)
                m.pairs.push_back(prototype.Create(id++, slave, m.model.properties,
                                                   geometry(IndexType(12 + g), IndexType(11 + g))));
    }
    Finish(m, {1, 2, 3, 4}, n, slip, first_inactive ? 4 : 0);
}

/// The explicit pass (nodal sums) at the current state, as the strategy runs it before each build.
/// With normal variation the nodal normals follow the slave face (one face: its own nodal normals), as the search
/// and the criteria set them.
void ExplicitPass(CouplingModel& m) {
    if (m.normal_variation) UpdateNormals(dynamic_cast<PairedCondition&>(*m.pairs[0]), m.dim);
    for (auto& pair : m.pairs) pair->SetValue(NORMAL, m.pairs[0]->GetValue(NORMAL));
    ContactUtilities::ComputeExplicitContributionConditions(*m.computing);
}

Eigen::VectorXd Residual(CouplingModel& m) {
    ExplicitPass(m);
    return AssembledResidual(m.pairs, m.dofs.size(), m.info);
}

enum class Coupling { None, GapOnly, Full };

/// The assembled LHS: the pairs' local tangents, plus the coupling blocks (Full: NodalPenaltyCoupling; GapOnly: its
/// normal part −b^c (η∂g̃^d)ᵀ alone, what it added before the slip terms).
Eigen::MatrixXd Tangent(CouplingModel& m, Coupling coupling_kind) {
    ExplicitPass(m);
    const ProcessInfo& info = m.info;
    Eigen::MatrixXd total = AssembledLocalTangents(m.pairs, m.dofs.size(), info);
    if (coupling_kind == Coupling::GapOnly) {
        std::vector<EquationIdVectorType> pair_ids(m.pairs.size());
        for (std::size_t c = 0; c < m.pairs.size(); ++c) m.pairs[c]->EquationIdVector(pair_ids[c], info);
        for (std::size_t c = 0; c < m.pairs.size(); ++c)
            for (std::size_t d = 0; d < m.pairs.size(); ++d) {
                if (c == d) continue;
                const auto& source_c = dynamic_cast<const NodalGapCouplingSource&>(*m.pairs[c]);
                const auto& source_d = dynamic_cast<const NodalGapCouplingSource&>(*m.pairs[d]);
                const Geometry& slave_c = m.pairs[c]->GetGeometry();
                const Geometry& slave_d = m.pairs[d]->GetGeometry();
                for (std::size_t jc = 0; jc < slave_c.size(); ++jc)
                    for (std::size_t jd = 0; jd < slave_d.size(); ++jd) {
                        if (slave_c[jc].Id() != slave_d[jd].Id()) continue;
                        NodalGapCouplingTerms tc, td;
                        if (!source_c.GetNodalGapCoupling(static_cast<int>(jc), tc) ||
                            !source_d.GetNodalGapCoupling(static_cast<int>(jd), td))
                            continue;
                        const Matrix block = -tc.force_per_gap * td.gap_gradient.transpose();
                        for (std::size_t a = 0; a < pair_ids[c].size(); ++a)
                            for (std::size_t b = 0; b < pair_ids[d].size(); ++b)
                                total(pair_ids[c][a], pair_ids[d][b]) += block(a, b);
                    }
            }
    }
    if (coupling_kind == Coupling::Full) {
        NodalPenaltyCoupling coupling;
        coupling.AddLHS(*m.model.part, info, DenseSink(total));
    }
    return total;
}

/// Largest |assembled LHS − central differences| over the largest |central difference|, for each coupling kind, at a
/// deformed state off every symmetry.
struct TangentErrors {
    double full = 0.0, gap_only = 0.0, none = 0.0;
};

TangentErrors MeasureTangent(CouplingModel& m) {
    for (std::size_t i = 0; i < m.dofs.size(); ++i) SetUnknown(m.dofs[i], 1e-3 * std::sin(1.0 + 3.7 * i));
    const Eigen::MatrixXd lhs = Tangent(m, Coupling::Full);
    const Eigen::MatrixXd gap_only = Tangent(m, Coupling::GapOnly);
    const Eigen::MatrixXd pairs_only = Tangent(m, Coupling::None);
    const Eigen::MatrixXd fd = CentralDifferenceLhs(m.dofs, [&] { return Residual(m); });
    const double scale = fd.cwiseAbs().maxCoeff();
    // Every active slave node penetrates.
    for (const auto& node : m.model.part->Nodes())
        if (node->Is(SLAVE) && node->Is(ACTIVE)) EXPECT_LT(node->FastGetSolutionStepValue(WEIGHTED_GAP), 0.0);
    return {(lhs - fd).cwiseAbs().maxCoeff() / scale, (gap_only - fd).cwiseAbs().maxCoeff() / scale,
            (pairs_only - fd).cwiseAbs().maxCoeff() / scale};
}

class NodalPenaltyTangent : public ::testing::TestWithParam<std::string> {};

/// Nothing is held: with η and A held by the tangent (before η̂ and Â varied with the pair's own area), the error was
/// 2.3e-2 (2D) and 1.2e-2 (3D) of the largest entry, in stick and in slip; it is now below 1e-9.
TEST_P(NodalPenaltyTangent, PairsPlusCouplingAreTheDerivativeOfTheAssembledResidual) {
    for (const int dim : {2, 3}) {
        SCOPED_TRACE(dim);
        CouplingModel m;
        Build(m, GetParam(), dim);
        const TangentErrors e = MeasureTangent(m);
        EXPECT_LT(e.full, 1e-6);
        // The coupling is what makes it exact: the pairs alone miss the cross-pair blocks.
        EXPECT_GT(e.none, 1e-2);
    }
}

class NodalPenaltySlipTangent : public ::testing::TestWithParam<std::string> {};

/// Slipping nodes: the direction t = (P e + T)/|P e + T| of every pair reads the other pairs' a_d s_d through T. In 3D
/// the coupling's slip terms B^c ∂T/∂q_d are what makes the tangent exact: with the normal coupling alone (what it
/// added before) the error is 0.44 (quadrilateral slave) and 0.29 (triangle on quadrilaterals) of the largest entry,
/// with them 2e-8. In 2D the tangent space is a line: t = ±(tangent of n), so without normal variation t does not depend on
/// T at all and the slip terms vanish (the normal coupling alone is exact, 9e-11); with normal variation P = I − n nᵀ
/// turns with the face and they are 3e-3 of the largest entry.
TEST_P(NodalPenaltySlipTangent, PairsPlusCouplingAreTheDerivativeOfTheAssembledResidual) {
    const bool normal_variation = GetParam().find("NV") != std::string::npos;
    for (const auto& [dim, triangle] : {std::pair{2, false}, std::pair{3, false}, std::pair{3, true}}) {
        SCOPED_TRACE(std::to_string(dim) + (triangle ? "D3N4N" : "D"));
        CouplingModel m;
        Build(m, GetParam(), dim, true, triangle);
        const TangentErrors e = MeasureTangent(m);
        EXPECT_LT(e.full, 1e-6);
        if (dim == 3)
            EXPECT_GT(e.gap_only, 1e-1);
        else if (normal_variation)
            EXPECT_GT(e.gap_only, 1e-3);
        else
            EXPECT_LT(e.gap_only, 1e-6);
        EXPECT_GT(e.none, 1e-1);
        for (const auto& node : m.model.part->Nodes())
            if (node->Is(SLAVE)) EXPECT_TRUE(node->Is(SLIP));
    }
}

class NodalPenaltyChainTangent : public ::testing::TestWithParam<std::string> {};

/// A slave chain: its inner nodes hold pairs of two slave faces, the pairs of one face see different local indices of
/// the node, and an inactive edge node shares pairs with active ones. Stick and slip, with and without the edge node.
TEST_P(NodalPenaltyChainTangent, PairsPlusCouplingAreTheDerivativeOfTheAssembledResidual) {
    for (const bool slip : {false, true})
        for (const bool edge_inactive : {false, true}) {
            SCOPED_TRACE(std::string(slip ? "slip" : "stick") + (edge_inactive ? ", edge inactive" : ""));
            CouplingModel m;
            BuildChain(m, GetParam(), slip, edge_inactive);
            ASSERT_EQ(m.pairs.size(), 6u);
            const TangentErrors e = MeasureTangent(m);
            EXPECT_LT(e.full, 1e-6);
            EXPECT_GT(e.none, 1e-1);
        }
}

INSTANTIATE_TEST_SUITE_P(Families, NodalPenaltyChainTangent,
                         ::testing::Values("PenaltyFrictionlessMortarContactCondition",
                                           "PenaltyFrictionalMortarContactCondition"));

INSTANTIATE_TEST_SUITE_P(Families, NodalPenaltySlipTangent,
                         ::testing::Values("PenaltyFrictionalMortarContactCondition",
                                           "PenaltyNVFrictionalMortarContactCondition"));

INSTANTIATE_TEST_SUITE_P(Families, NodalPenaltyTangent,
                         ::testing::Values("PenaltyFrictionlessMortarContactCondition",
                                           "PenaltyNVFrictionlessMortarContactCondition",
                                           "PenaltyFrictionalMortarContactCondition",
                                           "PenaltyNVFrictionalMortarContactCondition"));

}  // namespace
}  // namespace contact_app::testing
