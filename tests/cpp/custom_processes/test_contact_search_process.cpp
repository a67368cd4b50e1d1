// SPDX-License-Identifier: BSD-3-Clause
/// ContactSearchProcess / MPCContactSearchProcess: pairs on hand-built 2D and 3D interfaces, pair reuse, the
/// active set, condition names and settings errors.
#include <cmath>
#include <functional>
#include <set>
#include <utility>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/model.h"
#include "contact_app/kernel/registry.h"
#include "custom_conditions/contact_condition_registration.h"
#include "custom_conditions/paired_condition.h"
#include "custom_processes/contact_search_process.h"
#include "custom_processes/mpc_contact_search_process.h"
#include "custom_strategies/contact_master_slave_constraint.h"
#include "custom_utilities/index_map.h"
#include "tests/cpp/error_test_utilities.h"

namespace contact_app {
namespace {

using testing::ExpectError;

using PairSet = std::set<std::pair<IndexType, IndexType>>;  // (slave face id, master face id)

/// A "Structure" model part with the ALM frictionless variables, its "Contact" part, and face builders.
class SearchModel {
public:
    SearchModel() {
        RegisterContactApplication();
        RegisterContactConditions();
        main = &model.CreateModelPart("Structure");
        for (const VariableData* v : {static_cast<const VariableData*>(&DISPLACEMENT), static_cast<const VariableData*>(&NORMAL),
                                      static_cast<const VariableData*>(&WEIGHTED_GAP), static_cast<const VariableData*>(&NODAL_H),
                                      static_cast<const VariableData*>(&VELOCITY),
                                      static_cast<const VariableData*>(&LAGRANGE_MULTIPLIER_CONTACT_PRESSURE)})
            main->AddNodalSolutionStepVariable(*v);
        main->SetBufferSize(2);
        contact = &main->CreateSubModelPart("Contact");
        properties = main->CreateNewProperties(1);
    }

    Node& AddNode(double x, double y, double z, double h) {
        auto node = main->CreateNewNode(main->Nodes().MaxId() + 1, x, y, z);
        node->FastGetSolutionStepValue(NODAL_H) = h;
        node->AddDof(DISPLACEMENT_X);
        node->AddDof(DISPLACEMENT_Y);
        node->AddDof(DISPLACEMENT_Z);
        node->AddDof(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE);
        contact->AddNode(node);
        return *node;
    }

    /// A face on existing node ids; role SLAVE (true) or MASTER (false) on the face and its nodes.
    IndexType AddFace(const std::vector<IndexType>& nodes, bool slave) {
        const std::string name = nodes.size() == 2 ? "LineCondition2D2N" : "SurfaceCondition3D" + std::to_string(nodes.size()) + "N";
        auto face = main->CreateNewCondition(name, main->Conditions().MaxId() + 1, nodes, properties);
        contact->AddCondition(face);
        face->Set(SLAVE, slave);
        face->Set(MASTER, !slave);
        for (const IndexType id : nodes) {
            main->GetNode(id).Set(SLAVE, slave);
            main->GetNode(id).Set(MASTER, !slave);
        }
        return face->Id();
    }

    /// A polyline of @p n segments from @p a to @p b (Line2D2 normal = tangent turned clockwise); face ids.
    std::vector<IndexType> Line(const Array3& a, const Array3& b, int n, bool slave, double h) {
        std::vector<IndexType> node_ids, faces;
        for (int i = 0; i <= n; ++i) {
            const Array3 x = a + (b - a) * (double(i) / n);
            node_ids.push_back(AddNode(x[0], x[1], x[2], h).Id());
        }
        for (int i = 0; i < n; ++i) faces.push_back(AddFace({node_ids[i], node_ids[i + 1]}, slave));
        return faces;
    }

    /// A structured nx × ny grid of quads (or of triangles, two per cell) of the map (s, t) ∈ [0,1]² → x(s, t);
    /// @p flip reverses the orientation.
    std::vector<IndexType> Surface(const std::function<Array3(double, double)>& x, int nx, int ny, bool triangles,
                                   bool flip, bool slave, double h) {
        std::vector<std::vector<IndexType>> ids(nx + 1, std::vector<IndexType>(ny + 1));
        for (int i = 0; i <= nx; ++i)
            for (int j = 0; j <= ny; ++j) {
                const Array3 p = x(double(i) / nx, double(j) / ny);
                ids[i][j] = AddNode(p[0], p[1], p[2], h).Id();
            }
        std::vector<IndexType> faces;
        const auto add = [&](std::vector<IndexType> n) {
            if (flip) std::reverse(n.begin(), n.end());
            faces.push_back(AddFace(n, slave));
        };
        for (int i = 0; i < nx; ++i)
            for (int j = 0; j < ny; ++j) {
                if (triangles) {
                    add({ids[i][j], ids[i + 1][j], ids[i + 1][j + 1]});
                    add({ids[i][j], ids[i + 1][j + 1], ids[i][j + 1]});
                } else {
                    add({ids[i][j], ids[i + 1][j], ids[i + 1][j + 1], ids[i][j + 1]});
                }
            }
        return faces;
    }

    PairSet Pairs() const {
        PairSet pairs;
        for (const auto& face : contact->Conditions())
            if (auto map = face->GetValue(INDEX_MAP))
                for (const auto& [master, pair] : *map) pairs.emplace(face->Id(), master);
        return pairs;
    }

    /// What the Python SearchBaseProcess does around every search.
    void ResetNodeMarkers() {
        for (const auto& node : contact->Nodes()) node->Set(MARKER, false);
    }

    void RigidMotion(const Eigen::Matrix3d& rotation, const Array3& translation) {
        for (const auto& node : main->Nodes()) node->Coordinates() = rotation * node->Coordinates() + translation;
    }

    Model model;
    ModelPart* main = nullptr;
    ModelPart* contact = nullptr;
    Properties::Pointer properties;
};

ContactSearchSettings Settings(const std::string& type, const std::string& check) {
    ContactSearchSettings settings;
    settings.type_search = ParseSearchTreeType(type);
    settings.check_gap = ParseCheckGap(check);
    return settings;
}

/// Candidates of a slave face by the definition of in_radius (all masters, no tree): master centre within
/// search_factor × max |centre − node| and opposite orientation.
PairSet BruteForceInRadius(const SearchModel& m, const std::vector<IndexType>& slaves,
                           const std::vector<IndexType>& masters, double factor) {
    PairSet pairs;
    for (const IndexType s : slaves) {
        const Geometry& g = m.main->GetCondition(s).GetGeometry();
        double radius = 0.0;
        for (std::size_t i = 0; i < g.PointsNumber(); ++i) radius = std::max(radius, (g[i].Coordinates() - g.Center()).norm());
        const Array3 n_s = g.UnitNormal(Array3::Zero() + (g.PointsNumber() == 3 ? Array3(1.0 / 3, 1.0 / 3, 0) : Array3::Zero()));
        for (const IndexType mid : masters) {
            const Geometry& gm = m.main->GetCondition(mid).GetGeometry();
            const Array3 n_m = gm.UnitNormal(gm.PointsNumber() == 3 ? Array3(1.0 / 3, 1.0 / 3, 0) : Array3::Zero());
            if ((gm.Center() - g.Center()).norm() <= factor * radius && (n_s - n_m).norm() >= 0.1) pairs.emplace(s, mid);
        }
    }
    return pairs;
}

/// Pairs whose x-intervals overlap with positive length (faces along x).
PairSet OverlapInX(const SearchModel& m, const std::vector<IndexType>& slaves, const std::vector<IndexType>& masters) {
    const auto interval = [&](IndexType id) {
        const Geometry& g = m.main->GetCondition(id).GetGeometry();
        return std::make_pair(std::min(g[0].X(), g[1].X()), std::max(g[0].X(), g[1].X()));
    };
    PairSet pairs;
    for (const IndexType s : slaves)
        for (const IndexType mid : masters) {
            const auto [a0, a1] = interval(s);
            const auto [b0, b1] = interval(mid);
            if (std::min(a1, b1) - std::max(a0, b0) > 1e-9) pairs.emplace(s, mid);
        }
    return pairs;
}

Eigen::Matrix3d Rotation() {
    return (Eigen::AngleAxisd(0.7, Array3(0.0, 0.0, 1.0)) * Eigen::AngleAxisd(0.3, Array3(1.0, 0.0, 0.0))).toRotationMatrix();
}

// -- Pairs on hand-built interfaces --

TEST(ContactSearch, Matching2DFindsTheNeighbours) {
    // h = 0.1, gap 0.01: radius 3.5·0.05 = 0.175 reaches the facing master and its two neighbours (centre
    // distances 0.01 and ≈0.1005), not the next ones (≈0.2).
    SearchModel m;
    const auto slaves = m.Line(Array3(1, 0, 0), Array3(0, 0, 0), 10, true, 0.1);       // normal +y
    const auto masters = m.Line(Array3(0, 0.01, 0), Array3(1, 0.01, 0), 10, false, 0.1);  // normal −y
    ContactSearchProcess search(*m.main, Settings("in_radius", "check_mapping"));
    search.ExecuteInitialize();
    search.ExecuteInitializeSolutionStep();
    PairSet expected;
    for (int i = 0; i < 10; ++i)        // slave i spans [0.9 − 0.1 i, 1 − 0.1 i], master j [0.1 j, 0.1 j + 0.1]
        for (int j = 0; j < 10; ++j)
            if (std::abs((9 - i) - j) <= 1) expected.emplace(slaves[i], masters[j]);
    EXPECT_EQ(m.Pairs(), expected);
    EXPECT_EQ(m.Pairs(), BruteForceInRadius(m, slaves, masters, 3.5));
    EXPECT_EQ(search.GetComputingModelPart().NumberOfConditions(), 0u);  // no condition_name: pairs recorded only
}

TEST(ContactSearch, NonMatching2DWithOBB) {
    // OBB half-thickness 0.1·max h = 0.01 ≥ gap/2: exactly the faces overlapping in x (octree_with_obb is the
    // same tree + OBB filter). A thinner box (factor 0.02: 2·0.002 < gap) finds nothing.
    for (const auto& [type, factor] : {std::pair<std::string, double>{"in_radius_with_obb", 0.1},
                                       {"octree_with_obb", 0.1}, {"in_radius_with_obb", 0.02}}) {
        SearchModel m;
        const auto slaves = m.Line(Array3(1, 0, 0), Array3(0, 0, 0), 10, true, 0.1);
        const auto masters = m.Line(Array3(0, 0.005, 0), Array3(1, 0.005, 0), 7, false, 0.1);
        ContactSearchSettings settings = Settings(type, "check_mapping");
        settings.bounding_box_factor = factor;
        ContactSearchProcess search(*m.main, settings);
        search.ExecuteInitialize();
        search.ExecuteInitializeSolutionStep();
        EXPECT_EQ(m.Pairs(), factor > 0.05 ? OverlapInX(m, slaves, masters) : PairSet{}) << type << " " << factor;
    }
}

TEST(ContactSearch, NonMatching2DInBox) {
    // in_box: the slave's box swept ±L = 3.5·h along its normal (no in-plane growth, as the reference): the
    // masters whose centre lies above the slave face's x-range.
    SearchModel m;
    const auto slaves = m.Line(Array3(1, 0, 0), Array3(0, 0, 0), 10, true, 0.1);
    const auto masters = m.Line(Array3(0, 0.005, 0), Array3(1, 0.005, 0), 7, false, 0.1);
    ContactSearchProcess box(*m.main, Settings("in_box_with_obb", "no_check"));
    box.ExecuteInitialize();
    box.ExecuteInitializeSolutionStep();
    PairSet expected;
    for (const IndexType s : slaves)
        for (const IndexType mid : masters) {
            const Geometry& g = m.main->GetCondition(s).GetGeometry();
            const double x = m.main->GetCondition(mid).GetGeometry().Center()[0];
            if (x >= std::min(g[0].X(), g[1].X()) && x <= std::max(g[0].X(), g[1].X())) expected.emplace(s, mid);
        }
    EXPECT_EQ(expected.size(), 8u);  // 7 centres, the one at x = 0.5 on the shared end of two slaves
    EXPECT_EQ(m.Pairs(), expected);
}

TEST(ContactSearch, TiltedAndRigidMotion2D) {
    SearchModel m;
    const auto slaves = m.Line(Array3(1, 0, 0), Array3(0, 0, 0), 10, true, 0.1);
    const auto masters = m.Line(Array3(0, 0.01, 0), Array3(1, 0.2, 0), 9, false, 0.1);  // tilted by ≈11°
    ContactSearchProcess search(*m.main, Settings("in_radius", "check_mapping"));
    search.ExecuteInitialize();
    search.ExecuteInitializeSolutionStep();
    const PairSet pairs = m.Pairs();
    EXPECT_EQ(pairs, BruteForceInRadius(m, slaves, masters, 3.5));
    EXPECT_GT(pairs.size(), 3u);
    EXPECT_LT(pairs.size(), 30u);
    // Translation + rotation in the plane: same pairs.
    search.ExecuteFinalizeSolutionStep();
    const Eigen::Matrix3d rotation = Eigen::AngleAxisd(2.1, Array3(0, 0, 1)).toRotationMatrix();
    m.RigidMotion(rotation, Array3(3.0, -7.0, 0.0));
    for (const auto& face : m.contact->Conditions()) face->GetValue(INDEX_MAP)->clear();
    search.ExecuteInitializeSolutionStep();
    EXPECT_EQ(m.Pairs(), pairs);
}

TEST(ContactSearch, FarApartFindsNothing) {
    SearchModel m;
    m.Line(Array3(1, 0, 0), Array3(0, 0, 0), 10, true, 0.1);
    m.Line(Array3(0, 0.5, 0), Array3(1, 0.5, 0), 10, false, 0.1);
    ContactSearchSettings settings = Settings("in_radius", "check_mapping");
    settings.condition_name = "ALMFrictionlessMortarContact";
    ContactSearchProcess search(*m.main, settings, m.properties);
    search.ExecuteInitialize();
    search.ExecuteInitializeSolutionStep();
    EXPECT_TRUE(m.Pairs().empty());
    EXPECT_EQ(search.GetComputingModelPart().NumberOfConditions(), 0u);
    for (const auto& node : m.contact->Nodes()) EXPECT_FALSE(node->Is(ACTIVE));
}

TEST(ContactSearch, InitialPenetrationWithinReachIsPairedAndActive) {
    // Slave nodes 0.15 inside the master body: deeper than the OBB slab (0.1 × h = 0.01) and than direct_check's
    // −h, within the reach (in_radius 3.5 × 0.05 = 0.175, in_box 3.5 × 0.1). They used to be left unpaired.
    for (const std::string type : {"in_radius", "in_radius_with_obb", "in_box_with_obb"})
        for (const std::string check : {"check_mapping", "direct_check"}) {
            SCOPED_TRACE(type + " " + check);
            SearchModel m;
            m.Line(Array3(1, 0, 0), Array3(0, 0, 0), 10, true, 0.1);           // normal +y
            m.Line(Array3(0, -0.15, 0), Array3(1, -0.15, 0), 10, false, 0.1);  // normal −y, body above it
            ContactSearchSettings settings = Settings(type, check);
            settings.condition_name = "ALMFrictionlessMortarContact";
            ContactSearchProcess search(*m.main, settings, m.properties);
            search.ExecuteInitialize();
            search.ExecuteInitializeSolutionStep();
            EXPECT_FALSE(m.Pairs().empty());
            for (const auto& node : m.contact->Nodes()) {
                if (!node->Is(SLAVE)) continue;
                EXPECT_TRUE(node->Is(ACTIVE)) << "node " << node->Id();
                if (check == "check_mapping") EXPECT_NEAR(node->GetValue(NORMAL_GAP), -0.15, 1e-12);
            }
        }
}

TEST(ContactSearch, InitialPenetrationBeyondReachIsAnInputError) {
    SearchModel m;
    m.Line(Array3(1, 0, 0), Array3(0, 0, 0), 10, true, 0.1);
    m.Line(Array3(0, -0.5, 0), Array3(1, -0.5, 0), 10, false, 0.1);
    ContactSearchSettings settings = Settings("in_radius_with_obb", "check_mapping");
    settings.condition_name = "ALMFrictionlessMortarContact";
    ContactSearchProcess search(*m.main, settings, m.properties);
    search.ExecuteInitialize();
    // Slave nodes 0.5 inside the master body, beyond the search's reach.
    ExpectError<InputError>([&] { search.ExecuteInitializeSolutionStep(); },
                            {"11 slave node(s)", "node 1 at depth 0.5", "search_factor = 3.5",
                             "raise search_factor to at least 10.5"});
    // The suggested factor makes the same configuration a paired, active one.
    SearchModel again;
    again.Line(Array3(1, 0, 0), Array3(0, 0, 0), 10, true, 0.1);
    again.Line(Array3(0, -0.5, 0), Array3(1, -0.5, 0), 10, false, 0.1);
    settings.search_factor = 10.5;
    ContactSearchProcess wider(*again.main, settings, again.properties);
    wider.ExecuteInitialize();
    wider.ExecuteInitializeSolutionStep();
    for (const auto& node : again.contact->Nodes())
        if (node->Is(SLAVE)) EXPECT_TRUE(node->Is(ACTIVE)) << "node " << node->Id();
}

TEST(ContactSearch, SameOrientationIsNotPaired) {
    SearchModel m;
    m.Line(Array3(1, 0, 0), Array3(0, 0, 0), 10, true, 0.1);        // normal +y
    m.Line(Array3(1, 0.01, 0), Array3(0, 0.01, 0), 10, false, 0.1);  // normal +y too
    ContactSearchProcess search(*m.main, Settings("in_radius", "check_mapping"));
    search.ExecuteInitialize();
    search.ExecuteInitializeSolutionStep();
    EXPECT_TRUE(m.Pairs().empty());
}

TEST(ContactSearch, Matching3DQuadsAndRigidMotion) {
    SearchModel m;
    const auto slaves = m.Surface([](double s, double t) { return Array3(s, t, 0.0); }, 6, 5, false, false, true, 0.2);
    const auto masters = m.Surface([](double s, double t) { return Array3(s, t, 0.02); }, 6, 5, false, true, false, 0.2);
    ContactSearchProcess search(*m.main, Settings("in_radius", "check_mapping"));
    search.ExecuteInitialize();
    m.main->GetProcessInfo().SetValue(ACTIVE_CHECK_FACTOR, 0.2);  // L = 0.2·0.2 = 0.04 > gap 0.02: all active
    search.ExecuteInitializeSolutionStep();
    const PairSet pairs = m.Pairs();
    EXPECT_EQ(pairs, BruteForceInRadius(m, slaves, masters, 3.5));
    // Every slave pairs with its facing master.
    for (std::size_t i = 0; i < slaves.size(); ++i) EXPECT_EQ(pairs.count({slaves[i], masters[i]}), 1u);
    // The mapped gap is the distance of the planes.
    for (const auto& node : m.contact->Nodes())
        if (node->Is(SLAVE)) {
            EXPECT_TRUE(node->Is(ACTIVE));
            EXPECT_NEAR(node->GetValue(NORMAL_GAP), 0.02, 1e-14);
        }
    search.ExecuteFinalizeSolutionStep();
    m.RigidMotion(Rotation(), Array3(1.0, 2.0, 3.0));
    for (const auto& face : m.contact->Conditions()) face->GetValue(INDEX_MAP)->clear();
    search.ExecuteInitializeSolutionStep();
    EXPECT_EQ(m.Pairs(), pairs);
}

TEST(ContactSearch, NonMatching3DWithOBBAndMixedNames) {
    SearchModel m;
    const auto slaves = m.Surface([](double s, double t) { return Array3(s, t, 0.0); }, 4, 4, true, false, true, 0.25);
    const auto masters = m.Surface([](double s, double t) { return Array3(1.2 * s - 0.1, t, 0.01); }, 3, 3, false, true, false, 0.25);
    ContactSearchSettings settings = Settings("in_radius_with_obb", "check_mapping");
    settings.condition_name = "ALMFrictionlessMortarContact";
    settings.final_string = "4N";
    ContactSearchProcess search(*m.main, settings, m.properties);
    EXPECT_EQ(search.PairConditionName(3, 3), "ALMFrictionlessMortarContactCondition3D3N4N");
    search.ExecuteInitialize();
    search.ExecuteInitializeSolutionStep();
    const PairSet pairs = m.Pairs();
    // Pairs ⊆ in-radius candidates, and each pair's projections overlap in the plane (the OBB filter).
    const PairSet candidates = BruteForceInRadius(m, slaves, masters, 3.5);
    EXPECT_FALSE(pairs.empty());
    EXPECT_LT(pairs.size(), candidates.size());
    for (const auto& pair : pairs) EXPECT_EQ(candidates.count(pair), 1u);
    EXPECT_EQ(search.GetComputingModelPart().NumberOfConditions(), pairs.size());
    const Condition& prototype = Registry<Condition>::Instance().Get("ALMFrictionlessMortarContactCondition3D3N4N");
    for (const auto& pair : search.GetComputingModelPart().Conditions()) {
        EXPECT_EQ(typeid(*pair), typeid(prototype));
        const auto& paired = dynamic_cast<const PairedCondition&>(*pair);
        EXPECT_EQ(paired.GetPairedGeometry().PointsNumber(), 4u);
        EXPECT_TRUE(pair->GetValue(NORMAL).isApprox(Array3(0, 0, 1)));
    }
}

TEST(ContactSearch, CurvedArcAndCylinderGaps) {
    // 2D: slave arc r = 1 (normal outward), master arc r = 1.01 (normal inward), non-matching.
    {
        SearchModel m;
        std::vector<IndexType> s_nodes, m_nodes, slaves, masters;
        const auto arc = [](double r, double a) { return Array3(r * std::cos(a), r * std::sin(a), 0.0); };
        // Counter-clockwise slave: outward normal; clockwise master: inward normal.
        for (int i = 0; i <= 20; ++i) s_nodes.push_back(m.AddNode(arc(1.0, M_PI / 2 * i / 20)[0], arc(1.0, M_PI / 2 * i / 20)[1], 0, 0.08).Id());
        for (int i = 0; i <= 15; ++i) m_nodes.push_back(m.AddNode(arc(1.01, M_PI / 2 * (15 - i) / 15)[0], arc(1.01, M_PI / 2 * (15 - i) / 15)[1], 0, 0.1).Id());
        for (int i = 0; i < 20; ++i) slaves.push_back(m.AddFace({s_nodes[i], s_nodes[i + 1]}, true));
        for (int i = 0; i < 15; ++i) masters.push_back(m.AddFace({m_nodes[i], m_nodes[i + 1]}, false));
        ContactSearchSettings settings = Settings("in_radius", "check_mapping");
        ContactSearchProcess search(*m.main, settings);
        search.ExecuteInitialize();
        m.main->GetProcessInfo().SetValue(ACTIVE_CHECK_FACTOR, 0.2);  // L = 0.1·0.2 = 0.02 > gap: all active
        search.ExecuteInitializeSolutionStep();
        EXPECT_EQ(m.Pairs(), BruteForceInRadius(m, slaves, masters, 3.5));
        // Radial gap 0.01 less the chord sagitta of the master, 1.01(1 − cos(π/60)) ≈ 0.0014.
        const double sagitta = 1.01 * (1 - std::cos(M_PI / 60));
        for (const IndexType id : s_nodes) {
            EXPECT_TRUE(m.main->GetNode(id).Is(ACTIVE));
            EXPECT_LE(m.main->GetNode(id).GetValue(NORMAL_GAP), 0.01 + 1e-12);
            EXPECT_GE(m.main->GetNode(id).GetValue(NORMAL_GAP), 0.01 - sagitta - 1e-12);
        }
    }
    // 3D: cylinder patch, slave quads r = 1, master triangles r = 1.01 (3D4N3N).
    {
        SearchModel m;
        const auto cylinder = [](double r) {
            return [r](double s, double t) { return Array3(r * std::cos(s * M_PI / 4), r * std::sin(s * M_PI / 4), 0.5 * t); };
        };
        const auto slaves = m.Surface(cylinder(1.0), 8, 4, false, false, true, 0.12);    // outward
        const auto masters = m.Surface(cylinder(1.01), 6, 3, true, true, false, 0.15);   // inward
        ContactSearchSettings settings = Settings("in_radius", "check_mapping");
        settings.condition_name = "ALMFrictionlessMortarContact";
        settings.final_string = "3N";
        ContactSearchProcess search(*m.main, settings, m.properties);
        search.ExecuteInitialize();
        m.main->GetProcessInfo().SetValue(ACTIVE_CHECK_FACTOR, 0.2);
        search.ExecuteInitializeSolutionStep();
        EXPECT_EQ(m.Pairs(), BruteForceInRadius(m, slaves, masters, 3.5));
        EXPECT_EQ(search.GetComputingModelPart().NumberOfConditions(), m.Pairs().size());
        const double sagitta = 1.01 * (1 - std::cos(M_PI / 48));
        std::size_t checked = 0;
        for (const auto& node : m.contact->Nodes()) {
            if (!node->Is(SLAVE)) continue;
            EXPECT_TRUE(node->Is(ACTIVE));
            EXPECT_LE(node->GetValue(NORMAL_GAP), 0.01 + 1e-9);
            EXPECT_GE(node->GetValue(NORMAL_GAP), 0.01 - sagitta - 1e-9);
            ++checked;
        }
        EXPECT_EQ(checked, 9u * 5u);
    }
}

TEST(ContactSearch, SelfContactFoldedStrip) {
    // One strip folded into a C: top sheet y = 0.05 (x ∈ [0,1], normal −y), loop to the right, bottom sheet
    // y = 0 (x from 1.25 back to 0.25, normal +y). Only the facing sheets overlapping in x may pair.
    SearchModel m;
    std::vector<Array3> path = {Array3(0, 0.05, 0), Array3(1, 0.05, 0), Array3(1, 1, 0), Array3(1.5, 1, 0),
                                Array3(1.5, -1, 0), Array3(1.25, -1, 0), Array3(1.25, 0, 0), Array3(0.25, 0, 0)};
    const std::vector<int> segments = {7, 10, 5, 20, 3, 10, 10};
    std::vector<IndexType> nodes = {m.AddNode(0, 0.05, 0, 0.1).Id()};
    std::vector<std::vector<IndexType>> legs;
    for (std::size_t leg = 0; leg + 1 < path.size(); ++leg) {
        legs.emplace_back();
        for (int i = 1; i <= segments[leg]; ++i) {
            const Array3 x = path[leg] + (path[leg + 1] - path[leg]) * (double(i) / segments[leg]);
            nodes.push_back(m.AddNode(x[0], x[1], 0, 0.1).Id());
            legs.back().push_back(m.AddFace({nodes[nodes.size() - 2], nodes.back()}, false));
        }
    }
    for (const auto& face : m.contact->Conditions()) {
        face->Reset(SLAVE);
        face->Reset(MASTER);
    }
    ContactSearchSettings settings = Settings("in_radius_with_obb", "check_mapping");
    settings.predefined_master_slave = false;
    settings.bounding_box_factor = 0.3;  // half-thickness 0.03: 2·0.03 > 0.05
    ContactSearchProcess search(*m.main, settings);
    search.ExecuteInitialize();
    search.ExecuteInitializeSolutionStep();
    const PairSet expected = OverlapInX(m, legs.front(), legs.back());  // top sheet first in id order: slaves
    EXPECT_EQ(m.Pairs(), expected);
    EXPECT_GT(expected.size(), 10u);
    for (const auto& [slave, master] : expected) {
        EXPECT_TRUE(m.main->GetCondition(slave).Is(SLAVE));
        EXPECT_TRUE(m.main->GetCondition(master).Is(MASTER));
    }
}

// -- Pair reuse, removal, activation --

TEST(ContactSearch, PairsAreReusedAndRemovedWhenInactive) {
    SearchModel m;
    m.Line(Array3(1, 0, 0), Array3(0, 0, 0), 10, true, 0.1);
    const auto masters = m.Line(Array3(0, -0.0005, 0), Array3(1, -0.0005, 0), 10, false, 0.1);  // penetrating
    ContactSearchSettings settings = Settings("in_radius", "check_mapping");
    settings.condition_name = "ALMFrictionlessMortarContact";
    ContactSearchProcess search(*m.main, settings, m.properties);
    search.ExecuteInitialize();
    search.ExecuteInitializeSolutionStep();
    std::map<std::pair<IndexType, IndexType>, const Condition*> first;
    for (const auto& face : m.contact->Conditions())
        if (auto map = face->GetValue(INDEX_MAP))
            for (const auto& [master, pair] : *map) first[{face->Id(), master}] = &m.main->GetCondition(pair);
    ASSERT_EQ(first.size(), 28u);  // 10 facing + 18 neighbours
    for (const auto& node : m.contact->Nodes())
        if (node->Is(SLAVE)) EXPECT_TRUE(node->Is(ACTIVE));
    search.ExecuteFinalizeSolutionStep();
    m.ResetNodeMarkers();
    search.ExecuteInitializeSolutionStep();
    std::size_t same = 0;
    for (const auto& face : m.contact->Conditions())
        if (auto map = face->GetValue(INDEX_MAP))
            for (const auto& [master, pair] : *map) same += first.at({face->Id(), master}) == &m.main->GetCondition(pair);
    EXPECT_EQ(same, first.size());
    EXPECT_EQ(search.GetComputingModelPart().NumberOfConditions(), first.size());
    // The master leaves: the pairs survive the search but their nodes go inactive; the next clear erases them.
    search.ExecuteFinalizeSolutionStep();
    m.ResetNodeMarkers();
    for (const IndexType id : masters)
        for (std::size_t i = 0; i < 2; ++i) m.main->GetCondition(id).GetGeometry()[i].Coordinates()[1] = 0.3;
    for (const auto& node : m.contact->Nodes())
        if (node->Is(MASTER)) node->Coordinates()[1] = 0.3;
    search.ExecuteInitializeSolutionStep();
    for (const auto& node : m.contact->Nodes())
        if (node->Is(SLAVE)) EXPECT_FALSE(node->Is(ACTIVE));
    search.ExecuteFinalizeSolutionStep();
    EXPECT_EQ(search.GetComputingModelPart().NumberOfConditions(), 0u);
    EXPECT_TRUE(m.Pairs().empty());
}

TEST(ContactSearch, RemeshedPartErasesEverything) {
    SearchModel m;
    m.Line(Array3(1, 0, 0), Array3(0, 0, 0), 4, true, 0.25);
    m.Line(Array3(0, 0, 0), Array3(1, 0, 0), 4, false, 0.25);
    ContactSearchSettings settings = Settings("in_radius", "no_check");
    settings.condition_name = "ALMFrictionlessMortarContact";
    ContactSearchProcess search(*m.main, settings, m.properties);
    search.ExecuteInitialize();
    search.ExecuteInitializeSolutionStep();
    EXPECT_GT(search.GetComputingModelPart().NumberOfConditions(), 0u);
    m.main->Set(MODIFIED, true);
    search.ResetContactOperators();
    EXPECT_EQ(search.GetComputingModelPart().NumberOfConditions(), 0u);
    EXPECT_TRUE(m.Pairs().empty());
}

TEST(ContactSearch, ActivationByGapAgainstL) {
    // L = DISTANCE_THRESHOLD × ACTIVE_CHECK_FACTOR = 0.1 × 0.01 = 1e−3.
    for (const double gap : {0.0009, 0.0011}) {
        SearchModel m;
        m.Line(Array3(1, 0, 0), Array3(0, 0, 0), 10, true, 0.1);
        m.Line(Array3(0, gap, 0), Array3(1, gap, 0), 10, false, 0.1);
        ContactSearchProcess search(*m.main, Settings("in_radius", "check_mapping"));
        search.ExecuteInitialize();
        search.ExecuteInitializeSolutionStep();
        EXPECT_DOUBLE_EQ(m.main->GetProcessInfo().GetValue(DISTANCE_THRESHOLD), 0.1);
        for (const auto& node : m.contact->Nodes()) {
            if (!node->Is(SLAVE)) continue;
            EXPECT_EQ(node->Is(ACTIVE), gap < 1e-3);
            if (gap < 1e-3) {
                EXPECT_NEAR(node->GetValue(NORMAL_GAP), gap, 1e-14);
                EXPECT_TRUE(node->Is(SLIP));  // frictionless: slip initialised
            }
        }
    }
}

TEST(ContactSearch, ActiveNodesStayActiveBySmallWeightedGap) {
    // The master bulges over slave node x = 0.6 (mapped gap 0.0011 > L = 1e-3) but touches around it, so its weighted
    // gap per area g̃/NODAL_AREA (dual basis, both from the pairs) ≈ 8e-4 < L: an already ACTIVE node stays active
    // (advanced rule), but not with simple_search. Over x ≤ 0.45 the master stays 0.002
    // away: the inactive node x = 0.4 stays inactive.
    for (const bool simple : {false, true}) {
        SearchModel m;
        const auto slaves = m.Line(Array3(1, 0, 0), Array3(0, 0, 0), 10, true, 0.1);
        std::vector<IndexType> master;
        for (int i = 0; i <= 20; ++i) {
            const double x = 0.05 * i;
            const double y = x < 0.451 ? 0.002 : std::abs(x - 0.6) < 1e-9 ? 0.0011 : 0.0;
            master.push_back(m.AddNode(x, y, 0.0, 0.1).Id());
        }
        for (int i = 0; i < 20; ++i) m.AddFace({master[i], master[i + 1]}, false);
        ContactSearchSettings settings = Settings("in_radius", "check_mapping");
        settings.condition_name = "ALMFrictionlessMortarContact";
        settings.simple_search = simple;
        ContactSearchProcess search(*m.main, settings, m.properties);
        search.ExecuteInitialize();
        Node& was_active = m.main->GetCondition(slaves[4]).GetGeometry()[0];
        Node& was_inactive = m.main->GetCondition(slaves[6]).GetGeometry()[0];
        ASSERT_NEAR(was_active.X(), 0.6, 1e-12);
        ASSERT_NEAR(was_inactive.X(), 0.4, 1e-12);
        for (const auto& node : m.contact->Nodes()) node->SetValue(INITIAL_PENALTY, 1.0);
        was_active.Set(ACTIVE, true);
        search.ExecuteInitializeSolutionStep();
        const double area = was_active.GetValue(NODAL_AREA);
        ASSERT_GT(area, 0.0);
        EXPECT_LT(was_active.FastGetSolutionStepValue(WEIGHTED_GAP) / area, 1e-3);  // computed by the pairs
        EXPECT_EQ(was_active.Is(ACTIVE), !simple);
        EXPECT_FALSE(was_inactive.Is(ACTIVE));
    }
}

TEST(ContactSearch, DirectCheckAndNoCheck) {
    for (const double gap : {0.0005, 0.005}) {
        SearchModel m;
        m.Line(Array3(1, 0, 0), Array3(0, 0, 0), 10, true, 0.1);
        m.Line(Array3(0, gap, 0), Array3(1, gap, 0), 10, false, 0.1);
        ContactSearchProcess direct(*m.main, Settings("in_radius", "direct_check"));
        direct.ExecuteInitialize();
        direct.ExecuteInitializeSolutionStep();
        // Threshold NODAL_H × 0.01 = 1e−3: pairs (with all their slave nodes active) only for the close sheet.
        EXPECT_EQ(m.Pairs().size(), gap < 1e-3 ? 28u : 0u);
        for (const auto& node : m.contact->Nodes())
            if (node->Is(SLAVE)) EXPECT_EQ(node->Is(ACTIVE), gap < 1e-3);
    }
    SearchModel m;
    m.Line(Array3(1, 0, 0), Array3(0, 0, 0), 10, true, 0.1);
    m.Line(Array3(0, 0.05, 0), Array3(1, 0.05, 0), 10, false, 0.1);
    ContactSearchProcess none(*m.main, Settings("InRadius", "NoCheck"));
    none.ExecuteInitialize();
    none.ExecuteInitializeSolutionStep();
    EXPECT_EQ(m.Pairs().size(), 28u);
    for (const auto& node : m.contact->Nodes())
        if (node->Is(SLAVE)) EXPECT_TRUE(node->Is(ACTIVE));
}

TEST(ContactSearch, DynamicSearchUsesPredictedPositions) {
    for (const bool dynamic : {false, true}) {
        SearchModel m;
        m.Line(Array3(1, 0, 0), Array3(0, 0, 0), 10, true, 0.1);
        const auto masters = m.Line(Array3(0, 0.3, 0), Array3(1, 0.3, 0), 10, false, 0.1);
        for (const auto& node : m.contact->Nodes())
            if (node->Is(MASTER)) node->FastGetSolutionStepValue(VELOCITY) = Array3(0, -2.9995, 0);
        m.main->GetProcessInfo().SetValue(DELTA_TIME, 0.1);  // predicted gap 0.3 − 0.29995 = 5e−5
        ContactSearchSettings settings = Settings("in_radius", "check_mapping");
        settings.dynamic_search = dynamic;
        ContactSearchProcess search(*m.main, settings);
        search.ExecuteInitialize();
        search.ExecuteInitializeSolutionStep();
        EXPECT_EQ(m.Pairs().size(), dynamic ? 28u : 0u);
        for (const auto& node : m.contact->Nodes()) {
            if (node->Is(SLAVE)) EXPECT_EQ(node->Is(ACTIVE), dynamic);
            if (node->Is(MASTER)) EXPECT_DOUBLE_EQ(node->Y(), 0.3);  // moved back after the search
        }
    }
}

TEST(ContactSearch, InvertedSearchSwapsRoles) {
    SearchModel m;
    const auto lower = m.Line(Array3(1, 0, 0), Array3(0, 0, 0), 4, true, 0.25);
    const auto upper = m.Line(Array3(0, 0.01, 0), Array3(1, 0.01, 0), 4, false, 0.25);
    ContactSearchSettings settings = Settings("in_radius", "no_check");
    settings.inverted_search = true;
    ContactSearchProcess search(*m.main, settings);
    search.ExecuteInitialize();
    search.ExecuteInitializeSolutionStep();
    const PairSet pairs = m.Pairs();
    EXPECT_EQ(pairs, BruteForceInRadius(m, upper, lower, 3.5));
    search.InvertSearch();
    for (const auto& face : m.contact->Conditions()) face->GetValue(INDEX_MAP)->clear();
    search.ExecuteInitializeSolutionStep();
    EXPECT_EQ(m.Pairs(), BruteForceInRadius(m, lower, upper, 3.5));
}

TEST(ContactSearch, ClaimedFacesAreCloned) {
    SearchModel m;
    m.Line(Array3(1, 0, 0), Array3(0, 0, 0), 4, true, 0.25);
    m.Line(Array3(0, 0.01, 0), Array3(1, 0.01, 0), 4, false, 0.25);
    auto& sub = m.contact->CreateSubModelPart("ContactSub1");
    for (const auto& face : m.contact->Conditions()) sub.AddCondition(face);
    for (const auto& node : m.contact->Nodes()) sub.AddNode(node);
    for (const auto& face : sub.Conditions()) face->Set(MARKER, true);  // claimed by another search
    ContactSearchSettings settings = Settings("in_radius", "no_check");
    settings.id_name = "1";
    ContactSearchProcess search(*m.main, settings);
    search.ExecuteInitialize();
    EXPECT_EQ(sub.NumberOfConditions(), 8u);
    for (const auto& face : sub.Conditions()) EXPECT_GT(face->Id(), 8u);
    EXPECT_EQ(m.main->NumberOfConditions(), 16u);
    EXPECT_TRUE(m.main->HasSubModelPart("ComputingContact"));
    EXPECT_TRUE(m.main->GetSubModelPart("ComputingContact").HasSubModelPart("ComputingContactSub1"));
}

// -- MPC --

TEST(ContactSearch, MPCCreatesOneConstraintPerPair) {
    RegisterContactMasterSlaveConstraints();
    SearchModel m;
    m.Line(Array3(1, 0, 0), Array3(0, 0, 0), 4, true, 0.25);
    const auto masters = m.Line(Array3(0, -0.001, 0), Array3(1, -0.001, 0), 4, false, 0.25);
    m.main->Set(RIGID, true);
    // NODAL_PAUX = number of slave faces holding the node (what the MPC strategy computes).
    for (const auto& node : m.contact->Nodes())
        if (node->Is(SLAVE)) node->SetValue(NODAL_PAUX, node->X() > 0.0 && node->X() < 1.0 ? 2.0 : 1.0);
    ContactSearchSettings settings = Settings("in_radius", "check_mapping");
    settings.condition_name = "MPCMortarContact";  // MPCMortarContactCondition2D2N
    MPCContactSearchProcess search(*m.main, settings, m.properties);
    search.ExecuteInitialize();
    search.ExecuteInitializeSolutionStep();
    ModelPart& computing = search.GetComputingModelPart();
    ASSERT_EQ(computing.NumberOfConditions(), 10u);
    EXPECT_EQ(computing.NumberOfMasterSlaveConstraints(), 10u);
    std::set<IndexType> constraint_ids;
    std::size_t filled = 0;
    for (const auto& pair : computing.Conditions()) {
        const auto constraint = pair->GetValue(CONSTRAINT_POINTER);
        ASSERT_TRUE(constraint);
        EXPECT_TRUE(constraint->Is(ACTIVE));
        EXPECT_TRUE(pair->Is(RIGID));
        EXPECT_NE(dynamic_cast<const ContactMasterSlaveConstraint*>(constraint.get()), nullptr);
        // The condition fills the constraint it holds once its nodes are active.
        pair->InitializeSolutionStep(m.main->GetProcessInfo());
        filled += !constraint->GetSlaveDofsVector().empty();
        constraint_ids.insert(constraint->Id());
    }
    EXPECT_EQ(constraint_ids.size(), 10u);
    EXPECT_EQ(filled, 4u);  // the facing pairs; neighbours touch at one point only (isolated, no relation)
    // Pairs gone inactive take their constraints with them.
    search.ExecuteFinalizeSolutionStep();
    for (const auto& node : m.contact->Nodes()) {
        node->Set(MARKER, false);
        if (node->Is(MASTER)) {  // moved as the solver moves a node: displacement and mesh coordinates
            node->FastGetSolutionStepValue(DISPLACEMENT_Y) = 0.2 - node->InitialCoordinates()[1];
            node->Coordinates()[1] = 0.2;
        }
    }
    search.ExecuteInitializeSolutionStep();
    search.ExecuteFinalizeSolutionStep();
    EXPECT_EQ(computing.NumberOfConditions(), 0u);
    EXPECT_EQ(m.main->NumberOfMasterSlaveConstraints(), 0u);
}

// -- Settings --

TEST(ContactSearch, SettingsSpellingsAndErrors) {
    EXPECT_EQ(ParseSearchTreeType("in_radius_with_obb"), SearchTreeType::InRadiusWithOBB);
    EXPECT_EQ(ParseSearchTreeType("OctreeWithOBB"), SearchTreeType::OctreeWithOBB);
    EXPECT_EQ(ParseCheckGap("check_mapping"), CheckGap::MappingCheck);
    EXPECT_EQ(ParseCheckGap("DirectCheck"), CheckGap::DirectCheck);
    EXPECT_EQ(SearchTreeTypeName(SearchTreeType::InBox), "in_box");
    ExpectError<InputError>([] { ParseSearchTreeType("in_radus"); },
                            {"in_radus", "\"in_box_with_obb\"", "did you mean \"in_radius\""});
    EXPECT_THROW(ParseSearchTreeType("KDOP"), InputError);
    EXPECT_THROW(ParseCheckGap("mapping"), InputError);
    ContactSearchSettings settings;
    settings.search_factor = -1.0;
    EXPECT_THROW(settings.Validate(), InputError);
    settings = ContactSearchSettings{};
    settings.OBB_intersection_type = "Direct";
    EXPECT_THROW(settings.Validate(), InputError);

    SearchModel m;
    ContactSearchSettings predict;
    predict.predict_correct_lagrange_multiplier = true;
    EXPECT_THROW(ContactSearchProcess(*m.main, predict), ConfigurationError);
    ContactSearchSettings keyed;
    keyed.id_name = "3";
    EXPECT_THROW(ContactSearchProcess(*m.main, keyed), InputError);
    Model model;
    auto& bare = model.CreateModelPart("Bare");
    bare.AddNodalSolutionStepVariable(NORMAL);
    EXPECT_THROW(ContactSearchProcess(bare, ContactSearchSettings{}), InputError);
    // An unknown condition stem fails when the first pair is created, naming the full name.
    m.Line(Array3(1, 0, 0), Array3(0, 0, 0), 2, true, 0.5);
    m.Line(Array3(0, 0, 0), Array3(1, 0, 0), 2, false, 0.5);
    ContactSearchSettings wrong = Settings("in_radius", "no_check");
    wrong.condition_name = "ALMFrictionlesMortarContact";
    ContactSearchProcess search(*m.main, wrong);
    search.ExecuteInitialize();
    ExpectError<InputError>([&] { search.ExecuteInitializeSolutionStep(); },
                            {"ALMFrictionlesMortarContactCondition2D2N"});
}

}  // namespace
}  // namespace contact_app
