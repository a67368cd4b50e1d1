// SPDX-License-Identifier: BSD-3-Clause
/// Condition-level patch test on non-matching flat faces: one slave face pressed against two master faces whose
/// nodes do not match it. With every slave node active at zero gap and k λ = −p on each, the assembled contact
/// forces must be exactly the consistent nodal forces of a uniform pressure p: slave ∫ p N_k n, master −∫ p N_l n
/// over the overlap (the dual basis reproduces constants and D_kk = ∫ N_k). ALM and ALM components families, 2D
/// lines and 3D quadrilaterals. The penalty families are not exact here by construction: their force ε g̃ᶜ Dᶜ uses
/// the weighted gap of each pair (docs/theory/contact_residuals.md §2), so a node shared by two pairs gets ε g (Dᶜ)²
/// summed
/// over the pairs, not ε g D — the reference's convention, kept.
#include <map>

#include "contact_condition_test_utilities.h"
#include "custom_conditions/mortar_contact_condition.h"

namespace contact_app::testing {
namespace {

struct Face {
    std::vector<IndexType> nodes;
};

/// ∫ over [a, b] of the linear hat of node x_i on the segment [x0, x1] (i = 0 or 1).
double IntegrateHat(double x0, double x1, int i, double a, double b) {
    a = std::max(a, std::min(x0, x1));
    b = std::min(b, std::max(x0, x1));
    if (b <= a) return 0.0;
    auto hat = [&](double x) { return i == 0 ? (x1 - x) / (x1 - x0) : (x - x0) / (x1 - x0); };
    return 0.5 * (hat(a) + hat(b)) * (b - a);
}

class NonMatchingPatch : public ::testing::TestWithParam<std::string> {};

/// Assembles the RHS of every pair into (node id, DoF variable name) → value.
std::map<std::pair<IndexType, std::string>, double> Assemble(const std::vector<Condition::Pointer>& pairs,
                                                             const ProcessInfo& info) {
    std::map<std::pair<IndexType, std::string>, double> total;
    for (const auto& pair : pairs) {
        Vector rhs;
        pair->CalculateRightHandSide(rhs, info);
        DofsVectorType dofs;
        pair->GetDofList(dofs, info);
        for (std::size_t i = 0; i < dofs.size(); ++i)
            total[{dofs[i]->GetNode().Id(), dofs[i]->GetVariable().Name()}] += rhs[static_cast<Eigen::Index>(i)];
    }
    return total;
}

TEST_P(NonMatchingPatch, UniformPressureIsTransferredExactly) {
    const std::string prefix = GetParam();
    const bool components = prefix.find("Components") != std::string::npos;
    const double p = 3.0, k = 2.0, eps = 50.0;
    for (const std::string suffix : {"2D2N", "3D4N"}) {
        const std::string name = prefix + "MortarContactCondition" + suffix;
        const auto& row = DecodedName(name);
        ContactPairModel model;
        const double gap = 0.0;  // touching: the pressure is k λ
        std::vector<Condition::Pointer> pairs;
        ProcessInfo info;
        info.SetValue(SCALE_FACTOR, k);
        std::map<IndexType, double> slave_expected, master_expected;  // ∫ N over the slave / overlap
        const auto& prototype = dynamic_cast<const PairedCondition&>(Registry<Condition>::Instance().Get(name));
        auto make_geometry = [&](const std::vector<IndexType>& ids) {
            Geometry::PointsArrayType points;
            for (IndexType id : ids) points.push_back(model.part->pGetNode(id));
            return CreateGeometry(FaceGeometryName(row.dim, static_cast<int>(ids.size())), points);
        };
        Array3 n = Array3::Zero();
        if (row.dim == 2) {
            // Slave [0, 1] at y = 0 ordered right → left (normal +y); masters [−0.3, 0.4], [0.4, 1.3] at y = gap.
            model.AddNode(1, Eigen::Vector2d(1.0, 0.0));
            model.AddNode(2, Eigen::Vector2d(0.0, 0.0));
            const double xm[] = {-0.3, 0.4, 1.3};
            for (int i = 0; i < 3; ++i) model.AddNode(11 + i, Eigen::Vector2d(xm[i], gap));
            n = Array3(0.0, 1.0, 0.0);
            auto slave = make_geometry({1, 2});
            for (int f = 0; f < 2; ++f)
                pairs.push_back(prototype.Create(f + 1, slave, model.properties,
                                                 make_geometry({IndexType(11 + f), IndexType(12 + f)})));
            slave_expected = {{1, 0.5}, {2, 0.5}};
            for (int f = 0; f < 2; ++f)
                for (int i = 0; i < 2; ++i) master_expected[11 + f + i] += IntegrateHat(xm[f], xm[f + 1], i, 0.0, 1.0);
        } else {
            // Slave quad [0, 1]² at z = 0 (normal +z); masters [−0.2, 0.6] and [0.6, 1.3] × [−0.1, 1.1] at z = gap.
            const double xs[][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
            for (int i = 0; i < 4; ++i) model.AddNode(1 + i, Eigen::Vector3d(xs[i][0], xs[i][1], 0.0));
            const double xm[] = {-0.2, 0.6, 1.3}, ym[] = {-0.1, 1.1};
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 2; ++j) model.AddNode(11 + 2 * i + j, Eigen::Vector3d(xm[i], ym[j], gap));
            n = Array3(0.0, 0.0, 1.0);
            auto slave = make_geometry({1, 2, 3, 4});
            for (int f = 0; f < 2; ++f) {
                // Master nodes (x_f, y0), (x_f, y1), (x_f+1, y1), (x_f+1, y0): normal −z.
                const IndexType a = 11 + 2 * f;
                pairs.push_back(
                    prototype.Create(f + 1, slave, model.properties,
                                     make_geometry({a, IndexType(a + 1), IndexType(a + 3), IndexType(a + 2)})));
                for (int i = 0; i < 2; ++i)
                    for (int j = 0; j < 2; ++j)
                        master_expected[a + 2 * i + j] +=
                            IntegrateHat(xm[f], xm[f + 1], i, 0.0, 1.0) * IntegrateHat(ym[0], ym[1], j, 0.0, 1.0);
            }
            slave_expected = {{1, 0.25}, {2, 0.25}, {3, 0.25}, {4, 0.25}};
        }
        for (const auto& [id, measure] : slave_expected) {
            Node& node = model.part->GetNode(id);
            node.FastGetSolutionStepValue(NORMAL) = n;
            node.Set(ACTIVE, true);
            node.SetValue(INITIAL_PENALTY, eps);
            if (components)
                node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = -p / k * n;
            else
                node.FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) = -p / k;
        }
        for (auto& pair : pairs) {
            pair->SetValue(NORMAL, n);
            pair->Initialize(info);
        }
        const auto total = Assemble(pairs, info);
        const char* components_names[] = {"DISPLACEMENT_X", "DISPLACEMENT_Y", "DISPLACEMENT_Z"};
        double worst = 0.0;
        for (const auto& [id, measure] : slave_expected)
            for (int c = 0; c < row.dim; ++c)
                worst = std::max(worst, std::abs(total.at({id, components_names[c]}) - (-p * measure * n[c])));
        for (const auto& [id, measure] : master_expected)
            for (int c = 0; c < row.dim; ++c)
                worst = std::max(worst, std::abs(total.at({id, components_names[c]}) - (p * measure * n[c])));
        EXPECT_LT(worst, 1e-12 * p) << name;
    }
}

INSTANTIATE_TEST_SUITE_P(Families, NonMatchingPatch,
                         ::testing::Values("ALMFrictionless", "ALMFrictionlessComponents"));

}  // namespace
}  // namespace contact_app::testing
