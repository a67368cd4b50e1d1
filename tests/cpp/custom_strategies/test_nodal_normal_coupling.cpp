// SPDX-License-Identifier: BSD-3-Clause
/// Nodal normals that follow the iterate (docs/theory/mortar.md §7 "Normals that follow the iterate"): with
/// CONSIDER_NORMAL_VARIATION ≠ 0 the criteria recompute the mean nodal NORMAL (ComputeNodesMeanNormalModelPart over the
/// "Contact" part) before every build. On a curved slave surface whose nodes are shared by two faces, the pairs' local
/// tangents plus the NodalPenaltyCoupling and NodalNormalCoupling blocks must equal the central finite differences of
/// the assembled residual with the normals, the face-centre NORMAL and the nodal sums recomputed at every perturbed
/// state, nothing held. 2D chain of three slave lines, 3D ridge of two slave quadrilaterals, both on non-matching
/// masters; the penalty families, frictionless and frictional (stick and slip). The ALM families hold the normals.
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "../custom_conditions/contact_condition_test_utilities.h"
#include "assembled_tangent_test_utilities.h"
#include "contact_app/solving/schemes/scheme.h"
#include "custom_conditions/nodal_normal_coupling.h"
#include "custom_strategies/mortar_convergence_criteria.h"
#include "custom_strategies/nodal_normal_coupling.h"
#include "custom_strategies/nodal_penalty_coupling.h"
#include "custom_utilities/contact_utilities.h"

namespace contact_app::testing {
namespace {

struct NormalModel {
    ContactPairModel model;
    ModelPart* contact = nullptr;    // the surface faces whose normals make the nodal NORMAL
    ModelPart* computing = nullptr;  // the pairs
    std::vector<Condition::Pointer> pairs;
    std::vector<Dof*> dofs;  // every unknown, numbered 0..n−1
    int dim = 2;
    ProcessInfo info;
};

/// Slave surface z (3D) or y (2D) over the plane: curved, so the faces through a node disagree on its normal.
double SlaveSurface(double x, double y) { return 0.08 * (x - 0.7) * (x - 0.7) + 0.03 * x * y; }

void AddFace(NormalModel& m, IndexType id, const std::vector<IndexType>& ids) {
    Geometry::PointsArrayType points;
    for (IndexType node : ids) points.push_back(m.model.part->pGetNode(node));
    const char* name = m.dim == 2 ? "LineCondition2D2N" : "SurfaceCondition3D4N";
    auto face = Registry<Condition>::Instance().Get(name).Create(
        id, CreateGeometry(FaceGeometryName(m.dim, static_cast<int>(ids.size())), points), m.model.properties);
    m.contact->AddCondition(face);
}

/// Builds the model of @p family ("ALMFrictional", ...) in @p dim; every slave node active, slipping if @p slip.
void Build(NormalModel& m, const std::string& family, int dim, bool slip) {
    m.dim = dim;
    ModelPart& root = *m.model.part;
    const bool frictional = family.find("Frictional") != std::string::npos;
    if (frictional) {
        root.AddNodalSolutionStepVariable(WEIGHTED_SLIP);
        root.SetBufferSize(2);
    }
    m.contact = &root.CreateSubModelPart("Contact");
    m.computing = &root.CreateSubModelPart("ComputingContact");
    const std::string name = family + "MortarContactCondition" + (dim == 2 ? "2D2N" : "3D4N");
    const auto& prototype = dynamic_cast<const PairedCondition&>(Registry<Condition>::Instance().Get(name));
    auto geometry = [&](const std::vector<IndexType>& ids) {
        Geometry::PointsArrayType points;
        for (IndexType id : ids) points.push_back(root.pGetNode(id));
        return CreateGeometry(FaceGeometryName(dim, static_cast<int>(ids.size())), points);
    };
    std::vector<IndexType> slave_ids;
    // (slave face, master face) of every overlapping couple
    std::vector<std::pair<std::vector<IndexType>, std::vector<IndexType>>> couples;
    if (dim == 2) {
        const double xs[] = {1.5, 1.0, 0.5, 0.0};  // faces run right to left: normal +y
        for (int i = 0; i < 4; ++i) m.model.AddNode(1 + i, Eigen::Vector2d(xs[i], SlaveSurface(xs[i], 0.0)));
        const double xm[] = {-0.2, 0.35, 0.8, 1.3, 1.8};
        for (int i = 0; i < 5; ++i)
            m.model.AddNode(11 + i, Eigen::Vector2d(xm[i], SlaveSurface(xm[i], 0.0) - 0.01 - 0.006 * xm[i]));
        for (int f = 0; f < 3; ++f) {
            AddFace(m, 100 + f, {IndexType(1 + f), IndexType(2 + f)});
            for (int g = 0; g < 4; ++g)
                if (xm[g] < xs[f] && xm[g + 1] > xs[f + 1])
                    couples.push_back({{IndexType(1 + f), IndexType(2 + f)}, {IndexType(12 + g), IndexType(11 + g)}});
        }
        slave_ids = {1, 2, 3, 4};
    } else {
        const double xs[] = {0.0, 0.5, 1.0}, ys[] = {0.0, 1.0};
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 3; ++i)
                m.model.AddNode(1 + 3 * j + i, Eigen::Vector3d(xs[i], ys[j], SlaveSurface(xs[i], ys[j])));
        const double xm[] = {-0.2, 0.6, 1.3}, ym[] = {-0.1, 1.1};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 2; ++j)
                m.model.AddNode(11 + 2 * i + j,
                                Eigen::Vector3d(xm[i], ym[j], SlaveSurface(xm[i], ym[j]) - 0.01 - 0.004 * xm[i]));
        for (int f = 0; f < 2; ++f) {
            const std::vector<IndexType> slave{IndexType(1 + f), IndexType(2 + f), IndexType(5 + f), IndexType(4 + f)};
            AddFace(m, 100 + f, slave);
            for (int g = 0; g < 2; ++g) {
                const IndexType a = 11 + 2 * g;
                if (xm[g] < xs[f + 1] && xm[g + 1] > xs[f])
                    couples.push_back({slave, {a, IndexType(a + 1), IndexType(a + 3), IndexType(a + 2)}});
            }
        }
        slave_ids = {1, 2, 3, 4, 5, 6};
    }
    IndexType id = 1;
    for (const auto& [slave, master] : couples)
        m.pairs.push_back(prototype.Create(id++, geometry(slave), m.model.properties, geometry(master)));

    m.info.SetValue(CONSIDER_NORMAL_VARIATION, 3);
    m.info.SetValue(SCALE_FACTOR, 1.5);
    m.info.SetValue(TANGENT_FACTOR, 0.4);
    m.info.SetValue(DOMAIN_SIZE, dim);
    for (IndexType node_id : slave_ids) {
        Node& node = root.GetNode(node_id);
        node.Set(ACTIVE, true);
        node.Set(SLAVE, true);
        node.Set(INTERFACE, true);
        node.Set(SLIP, slip);
        node.SetValue(INITIAL_PENALTY, 1.0e3);
        node.SetValue(FRICTION_COEFFICIENT, 0.3);
        node.SetValue(TANGENT_XI, Array3(1.0, 0.0, 0.0));
        m.contact->AddNode(root.pGetNode(node_id));
    }
    for (auto& pair : m.pairs) m.computing->AddCondition(pair);
    UpdateContactNormals(root);
    for (auto& pair : m.pairs) {
        pair->Initialize(m.info);
        if (frictional) pair->InitializeSolutionStep(m.info);
    }
    const Variable<double>* displacement[] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
    const Variable<double>* vector_multiplier[] = {&VECTOR_LAGRANGE_MULTIPLIER_X, &VECTOR_LAGRANGE_MULTIPLIER_Y,
                                                   &VECTOR_LAGRANGE_MULTIPLIER_Z};
    for (const auto& node : root.Nodes()) {
        for (int c = 0; c < dim; ++c) m.dofs.push_back(&node->GetDof(*displacement[c]));
        if (!node->Is(SLAVE)) continue;
        // The multipliers: a compressive normal part and a tangential one, inside the cone.
        const Array3 n = node->FastGetSolutionStepValue(NORMAL);
        if (family == "ALMFrictional") {
            const Array3 t = (Array3(1.0, 0.3, 0.0) - n * n.dot(Array3(1.0, 0.3, 0.0))).normalized();
            node->FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = -0.5 * n + 0.05 * t;
            for (int c = 0; c < dim; ++c) m.dofs.push_back(&node->GetDof(*vector_multiplier[c]));
        } else if (family == "ALMFrictionless") {
            node->FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) = -0.5;
            m.dofs.push_back(&node->GetDof(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE));
        }
    }
    for (std::size_t i = 0; i < m.dofs.size(); ++i) m.dofs[i]->SetEquationId(i);
}

/// What the strategy and the criteria do before every build: normals, then the nodal sums.
void Refresh(NormalModel& m) {
    if (m.info.GetValue(CONSIDER_NORMAL_VARIATION) != 0) UpdateContactNormals(*m.model.part);  // else held
    ContactUtilities::ComputeExplicitContributionConditions(*m.computing);
}

Eigen::VectorXd Residual(NormalModel& m) {
    Refresh(m);
    return AssembledResidual(m.pairs, m.dofs.size(), m.info);
}

/// The assembled LHS: pairs, the nodal penalty coupling, and (if @p normal_coupling) the normal coupling.
Eigen::MatrixXd Tangent(NormalModel& m, bool normal_coupling) {
    Refresh(m);
    Eigen::MatrixXd total = AssembledLocalTangents(m.pairs, m.dofs.size(), m.info);
    const auto sink = DenseSink(total);
    NodalPenaltyCoupling().AddLHS(*m.model.part, m.info, sink);
    if (normal_coupling) NodalNormalCoupling().AddLHS(*m.model.part, m.info, sink);
    return total;
}

struct TangentErrors {
    double with_normals = 0.0, without = 0.0;
};

/// Largest |assembled LHS − central differences| over the largest |central difference|, at a deformed state off every
/// symmetry (the masters also slid tangentially since the step start).
TangentErrors MeasureTangent(NormalModel& m) {
    for (std::size_t i = 0; i < m.dofs.size(); ++i) {
        const bool displacement = &m.dofs[i]->GetVariable() == &DISPLACEMENT_X ||
                                  &m.dofs[i]->GetVariable() == &DISPLACEMENT_Y ||
                                  &m.dofs[i]->GetVariable() == &DISPLACEMENT_Z;
        if (displacement) SetUnknown(m.dofs[i], 2e-3 * std::sin(1.0 + 3.7 * i) + (i % m.dim == 0 ? 0.01 : 0.0));
    }
    const Eigen::MatrixXd lhs = Tangent(m, true);
    const Eigen::MatrixXd held = Tangent(m, false);
    const Eigen::MatrixXd fd = CentralDifferenceLhs(m.dofs, [&] { return Residual(m); });
    const double scale = fd.cwiseAbs().maxCoeff();
    return {(lhs - fd).cwiseAbs().maxCoeff() / scale, (held - fd).cwiseAbs().maxCoeff() / scale};
}

/// The derivative of the mean nodal normal against central differences of ComputeNodesMeanNormalModelPart.
TEST(MeanNormalDerivatives, MatchCentralDifferencesOfTheMeanNormal) {
    for (const int dim : {2, 3}) {
        SCOPED_TRACE(dim);
        NormalModel m;
        Build(m, "ALMFrictionless", dim, false);
        for (std::size_t i = 0; i < m.dofs.size(); ++i) SetUnknown(m.dofs[i], 3e-3 * std::cos(0.3 + 1.9 * i));
        ComputeNodesMeanNormalModelPart(*m.contact, true);
        const MeanNormalDerivatives derivatives(*m.contact);
        std::vector<const Node*> nodes;
        Matrix jacobian;
        int checked = 0;
        for (const auto& node : m.contact->Nodes()) {
            ASSERT_TRUE(derivatives.Compute(*node, nodes, jacobian));
            ASSERT_EQ(jacobian.rows(), dim);
            ASSERT_EQ(jacobian.cols(), dim * static_cast<Eigen::Index>(nodes.size()));
            for (std::size_t k = 0; k < nodes.size(); ++k)
                for (int c = 0; c < dim; ++c) {
                    Node& moved = const_cast<Node&>(*nodes[k]);
                    const double x = moved.Coordinates()[c], h = 1e-7;
                    moved.Coordinates()[c] = x + h;
                    ComputeNodesMeanNormalModelPart(*m.contact, false);
                    const Array3 plus = node->FastGetSolutionStepValue(NORMAL);
                    moved.Coordinates()[c] = x - h;
                    ComputeNodesMeanNormalModelPart(*m.contact, false);
                    const Array3 minus = node->FastGetSolutionStepValue(NORMAL);
                    moved.Coordinates()[c] = x;
                    const Eigen::VectorXd fd = ((plus - minus) / (2.0 * h)).head(dim);
                    EXPECT_LT((jacobian.col(dim * static_cast<Eigen::Index>(k) + c) - fd).norm(), 1e-7);
                    ++checked;
                }
        }
        ComputeNodesMeanNormalModelPart(*m.contact, false);
        EXPECT_GT(checked, 0);
    }
}

struct Case {
    std::string family;
    bool slip;
};

class NodalNormalTangent : public ::testing::TestWithParam<Case> {};

/// The assembled tangent is the derivative of the residual the Newton loop sees. Holding the normals instead (what the
/// tangent did before) leaves an error of a few per cent of the largest entry.
TEST_P(NodalNormalTangent, IsTheDerivativeOfTheAssembledResidualWithNormalsRecomputed) {
    for (const int dim : {2, 3}) {
        SCOPED_TRACE(dim);
        NormalModel m;
        Build(m, GetParam().family, dim, GetParam().slip);
        ASSERT_GE(m.pairs.size(), 3u);
        const TangentErrors e = MeasureTangent(m);
        EXPECT_GT(e.without, 5e-3);
        EXPECT_LT(e.with_normals, 1e-6);
        for (const auto& node : m.contact->Nodes())
            if (node->Is(SLAVE)) EXPECT_EQ(node->Is(SLIP), GetParam().slip);
    }
}

/// The ALM families hold the normals (docs/theory/mortar.md §7 "Normals that follow the iterate": measured no gain, and
/// the 3D press fit's first step lost): they record nothing and their assembled tangent is the held one.
TEST(NodalNormalGate, TheALMFamiliesHoldTheNormals) {
    for (const char* family : {"ALMFrictionless", "ALMFrictional"}) {
        SCOPED_TRACE(family);
        NormalModel m;
        Build(m, family, 3, false);
        for (const auto& pair : m.pairs)
            EXPECT_FALSE(dynamic_cast<const NodalNormalCouplingSource&>(*pair).CouplesNodalNormals(m.info));
        EXPECT_EQ((Tangent(m, true) - Tangent(m, false)).cwiseAbs().maxCoeff(), 0.0);
    }
}

/// With the normals held (CONSIDER_NORMAL_VARIATION = 0) the ALM families' assembled tangent is exact on these
/// non-matching pairs, the frictional slip law included: its transmitted gap Q̂ varies this pair's share in the weights
/// a^c / A too (pair_nodal_share.h; with Q + g̃ − g̃⁰ the slip case was off by 1.05e-5 in 2D and 1.8e-5 in 3D).
TEST(NodalSlipLaw, ALMTangentIsExactWithTheNormalsHeld) {
    for (const auto& [family, slip] : {std::pair{"ALMFrictionless", false}, std::pair{"ALMFrictional", false},
                                       std::pair{"ALMFrictional", true}})
        for (const int dim : {2, 3}) {
            SCOPED_TRACE(std::string(family) + (slip ? " slip " : " ") + std::to_string(dim) + "D");
            NormalModel m;
            Build(m, family, dim, slip);
            m.info.SetValue(CONSIDER_NORMAL_VARIATION, 0);
            EXPECT_LT(MeasureTangent(m).with_normals, 1e-8);
        }
}

/// While the last set update changed a set the tangent holds the normals (NormalsInTangent): no record, no blocks.
TEST(NodalNormalGate, HoldsTheNormalsWhileTheSetsMove) {
    for (const Variable<bool>* flag : {&ACTIVE_SET_CONVERGED, &SLIP_SET_CONVERGED}) {
        NormalModel m;
        Build(m, "PenaltyFrictional", 2, true);
        m.info.SetValue(*flag, false);
        const Eigen::MatrixXd lhs = Tangent(m, true);
        const Eigen::MatrixXd held = Tangent(m, false);
        EXPECT_EQ((lhs - held).cwiseAbs().maxCoeff(), 0.0);
        Matrix record;
        for (const auto& pair : m.pairs)
            EXPECT_FALSE(dynamic_cast<const NodalNormalCouplingSource&>(*pair).GetNodalNormalCoupling(0, record));
        m.info.SetValue(*flag, true);
        EXPECT_GT((Tangent(m, true) - Tangent(m, false)).cwiseAbs().maxCoeff(), 0.0);
    }
}

/// A penalty pair without an active slave node adds nothing to the residual: it skips the normal pass.
TEST(NodalNormalGate, APairWithoutActiveNodesRecordsNothing) {
    NormalModel m;
    Build(m, "PenaltyFrictional", 3, false);
    for (const auto& node : m.contact->Nodes()) node->Set(ACTIVE, false);
    Tangent(m, true);
    Matrix record;
    for (const auto& pair : m.pairs)
        EXPECT_FALSE(dynamic_cast<const NodalNormalCouplingSource&>(*pair).GetNodalNormalCoupling(0, record));
    m.contact->GetNode(2).Set(ACTIVE, true);  // shared by both slave faces: every pair records
    Tangent(m, true);
    for (const auto& pair : m.pairs)
        EXPECT_TRUE(dynamic_cast<const NodalNormalCouplingSource&>(*pair).GetNodalNormalCoupling(0, record));
}

INSTANTIATE_TEST_SUITE_P(Families, NodalNormalTangent,
                         ::testing::Values(Case{"PenaltyFrictionless", false},
                                           Case{"PenaltyFrictional", false}, Case{"PenaltyFrictional", true}),
                         [](const auto& info) { return info.param.family + (info.param.slip ? "Slip" : "Stick"); });

}  // namespace
}  // namespace contact_app::testing
