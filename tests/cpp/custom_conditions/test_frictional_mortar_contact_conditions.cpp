// SPDX-License-Identifier: BSD-3-Clause
/// Frictional mortar conditions (ALM frictional and penalty frictional, plane and axisymmetric): sizes, DoF order,
/// the Σ s_i 3^i encoding, FD tangent in every branch (inactive / slip / stick × objective / non-objective), the
/// MODIFIED flag, the start-of-step operators, stick and slip tractions on a flat pair, Check() messages.
#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <random>

#include "../custom_utilities/mortar_test_utilities.h"
#include "contact_app/kernel/serializer.h"
#include "contact_condition_test_utilities.h"
#include "custom_conditions/mortar_contact_condition.h"
#include "custom_utilities/mortar_normals.h"
#include "custom_utilities/mortar_operators.h"

namespace contact_app::testing {
namespace {

/// The contact model of the fixtures plus WEIGHTED_SLIP and a buffer of 2 (start-of-step displacement).
struct FrictionalModel : ContactPairModel {
    FrictionalModel() {
        part->AddNodalSolutionStepVariable(WEIGHTED_SLIP);
        part->SetBufferSize(2);
    }
};

/// Moves every node to X0 + d(0) with the step start at X0 + d(1): d(1) random (0.02), d(0) = d(1) + a random
/// perturbation (0.01) + @p slide on the master nodes.
void SetStep(PairedCondition& pair, int dim, std::mt19937& rng, const Array3& slide) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    auto move = [&](Node& node, bool master) {
        Array3 d1 = Array3::Zero(), d0 = Array3::Zero();
        for (int c = 0; c < dim; ++c) {
            d1[c] = 0.02 * u(rng);
            d0[c] = d1[c] + 0.01 * u(rng) + (master ? slide[c] : 0.0);
        }
        node.FastGetSolutionStepValue(DISPLACEMENT, 1) = d1;
        node.FastGetSolutionStepValue(DISPLACEMENT) = d0;
        node.Coordinates() = node.InitialCoordinates() + d0;
    };
    auto& slave = const_cast<Geometry&>(pair.GetParentGeometry());
    auto& master = const_cast<Geometry&>(pair.GetPairedGeometry());
    for (std::size_t j = 0; j < slave.size(); ++j) move(slave[j], false);
    for (std::size_t l = 0; l < master.size(); ++l) move(master[l], true);
}

/// A unit tangent of the slave face (its first edge).
Array3 SlaveTangent(const PairedCondition& pair) {
    const Geometry& slave = pair.GetParentGeometry();
    return (slave[1].Coordinates() - slave[0].Coordinates()).normalized();
}

/// Node j: 0 inactive, 1 active-slip, 2 active-stick.
void SetNodeState(Node& node, int state) {
    node.Set(ACTIVE, state != 0);
    node.Set(SLIP, state == 1);
}

/// A pair in a sliding step with random nodal data; @p states[j] the state of slave node j.
struct SlidingPair {
    std::shared_ptr<PairedCondition> pair;
    ProcessInfo info;
};

SlidingPair MakeSlidingPair(FrictionalModel& model, const std::string& name, std::mt19937& rng,
                            const std::vector<int>& states, double threshold) {
    const auto& row = DecodedName(name);
    Eigen::MatrixXd s, m;
    RandomPairCoordinates(row, rng, s, m);
    SlidingPair result;
    result.pair = model.MakePair(name, s, m);
    model.properties->SetValue(INTEGRATION_ORDER_CONTACT, 3);
    model.properties->SetValue(THICKNESS, 1.5);
    SetStep(*result.pair, row.dim, rng, 0.06 * SlaveTangent(*result.pair));
    UpdateNormals(*result.pair, row.dim);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    result.info.SetValue(SCALE_FACTOR, 1.5);
    result.info.SetValue(TANGENT_FACTOR, 0.4);
    result.info.SetValue(OPERATOR_THRESHOLD, threshold);
    result.info.SetValue(CONSIDER_NORMAL_VARIATION, row.normal_variation ? 2 : 0);
    auto& slave = const_cast<Geometry&>(result.pair->GetParentGeometry());
    for (std::size_t j = 0; j < slave.size(); ++j) {
        SetNodeState(slave[j], states[j % states.size()]);
        slave[j].SetValue(INITIAL_PENALTY, 5.0 + 10.0 * u(rng));
        slave[j].SetValue(FRICTION_COEFFICIENT, 0.2 + 0.3 * u(rng));
        if (j % 2 == 1) slave[j].SetValue(DYNAMIC_FACTOR, 0.5 + 0.5 * u(rng));
        const Array3 n = slave[j].FastGetSolutionStepValue(NORMAL);
        Array3 t = SlaveTangent(*result.pair);
        t = (t - n * n.dot(t)).normalized();
        slave[j].SetValue(TANGENT_XI, t);
        Array3 tangential = Array3::Zero();
        tangential.head(row.dim) = Eigen::VectorXd::NullaryExpr(row.dim, [&] { return 0.2 * u(rng) - 0.1; });
        slave[j].FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) =
            -u(rng) * n + (tangential - n * n.dot(tangential));
    }
    result.pair->Initialize(result.info);
    result.pair->InitializeSolutionStep(result.info);
    return result;
}

bool HasValidNodalShare(const Condition& c) {
    return WithMortarBase(&c, [](const auto& p) { return p.NodalShare().valid ? 1 : 0; }) == 1;
}

/// The start-of-step operators as the condition saves them (Serializer layout of the frictional families).
struct SavedPrevious {
    bool initialized = false, overlap = false;
    Matrix D, M;
};

SavedPrevious ReadPrevious(const PairedCondition& pair) {
    Serializer out;
    pair.Save(out);
    Serializer in(out.Data());
    std::size_t id = 0, defined = 0, values = 0;
    Array3 normal;
    in.Load("Id", id);
    in.Load("FlagsDefined", defined);
    in.Load("FlagsValues", values);
    in.Load("PairedNormal", normal);
    bool valid = false;
    Matrix area, gap, slip;
    in.Load("NodalShareValid", valid);
    in.Load("NodalShareArea", area);
    in.Load("NodalShareGap", gap);
    in.Load("NodalShareSlip", slip);
    SavedPrevious p;
    in.Load("PreviousMortarOperatorsInitialized", p.initialized);
    in.Load("PreviousMortarOperatorsOverlap", p.overlap);
    in.Load("PreviousD", p.D);
    in.Load("PreviousM", p.M);
    EXPECT_TRUE(in.AtEnd());
    return p;
}

/// max |Ae_ij| of the pair's dual basis in the current configuration (0 if the dual basis failed).
template <int D, int NS, int NM>
double DualBasisSize(const PairedCondition& pair) {
    const MortarIntegrator<D, NS, NM, double> integrator;
    const auto& slave = pair.GetParentGeometry();
    NodeCoordinates<double, D, NS> x1, normals;
    NodeCoordinates<double, D, NM> x2;
    for (int i = 0; i < NS; ++i) {
        x1.row(i) = slave[i].Coordinates().head(D).transpose();
        normals.row(i) = slave[i].FastGetSolutionStepValue(NORMAL).head(D).transpose();
    }
    for (int i = 0; i < NM; ++i) x2.row(i) = pair.GetPairedGeometry()[i].Coordinates().head(D).transpose();
    const SpatialVector<double, D> n = pair.GetValue(NORMAL).head(D);
    const auto result = IntegrateMortarPair<D, NS, NM>(integrator, x1, n, x2, normals, true);
    return result.dual.dual ? result.dual.Ae.cwiseAbs().maxCoeff() : 0.0;
}

double DualBasisSize(const PairedCondition& pair, const ContactConditionName& row) {
    if (row.dim == 2) return DualBasisSize<2, 2, 2>(pair);
    if (row.num_slave == 3 && row.num_master == 3) return DualBasisSize<3, 3, 3>(pair);
    if (row.num_slave == 4 && row.num_master == 4) return DualBasisSize<3, 4, 4>(pair);
    if (row.num_slave == 3) return DualBasisSize<3, 3, 4>(pair);
    return DualBasisSize<3, 4, 3>(pair);
}

class FrictionalMortarNames : public ::testing::TestWithParam<std::string> {};

TEST_P(FrictionalMortarNames, LocalSystemSizesDofOrderAndStateEncodingMatchTheSpec) {
    const auto& row = DecodedName(GetParam());
    FrictionalModel model;
    std::mt19937 rng(7);
    auto sliding = MakeSlidingPair(model, GetParam(), rng, {2}, 1e-3);
    auto& pair = *sliding.pair;
    ExpectSpecLocalSystem(pair, GetParam(), sliding.info);
    // Σ s_i 3^i for every combination of states of the slave nodes.
    auto& slave = const_cast<Geometry&>(pair.GetParentGeometry());
    const int n = static_cast<int>(slave.size());
    int combinations = 1;
    for (int j = 0; j < n; ++j) combinations *= 3;
    for (int code = 0; code < combinations; ++code) {
        for (int j = 0, c = code; j < n; ++j, c /= 3) SetNodeState(slave[j], c % 3);
        EXPECT_EQ(ActiveInactiveValue(&pair), code);
    }
}

/// The explicit pass of the pair, then nodal sums as if other pairs shared its slave nodes (ω < 1, nonzero offsets
/// of the transmitted gap and of the slip): the residual then goes through NodalInterfaceMap.
void ShareNodesWithOtherPairs(PairedCondition& pair, const ProcessInfo& info, std::mt19937& rng) {
    auto& slave = const_cast<Geometry&>(pair.GetParentGeometry());
    for (std::size_t j = 0; j < slave.size(); ++j) {
        slave[j].FastGetSolutionStepValue(WEIGHTED_GAP) = 0.0;
        slave[j].FastGetSolutionStepValue(WEIGHTED_SLIP) = Array3::Zero();
        slave[j].SetValue(NODAL_AREA, 0.0);
        slave[j].SetValue(AREA_WEIGHTED_PAIR_GAP, 0.0);
    }
    pair.AddExplicitContribution(info);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (std::size_t j = 0; j < slave.size(); ++j) {
        const double other_area = 0.3 + 0.5 * (u(rng) + 1.0);
        const double other_gap = 0.01 * u(rng);
        slave[j].SetValue(NODAL_AREA, slave[j].GetValue(NODAL_AREA) + other_area);
        slave[j].FastGetSolutionStepValue(WEIGHTED_GAP) += other_gap;
        slave[j].SetValue(AREA_WEIGHTED_PAIR_GAP, slave[j].GetValue(AREA_WEIGHTED_PAIR_GAP) + other_area * other_gap);
        const Array3 n = slave[j].FastGetSolutionStepValue(NORMAL);
        Array3 other_slip(0.01 * u(rng), 0.01 * u(rng), 0.01 * u(rng));
        slave[j].FastGetSolutionStepValue(WEIGHTED_SLIP) += other_slip - n * n.dot(other_slip);
    }
}

TEST_P(FrictionalMortarNames, TangentIsTheCentralDifferenceOfMinusRhsInEveryBranch) {
    const auto& row = DecodedName(GetParam());
    const std::vector<std::vector<int>> patterns = {{0, 1, 2, 1}, {2, 0, 1, 2}, {1}, {2}};
    double worst = 0.0;
    for (const bool shared : {false, true}) {  // the same random pairs alone, then sharing their nodes
    int seed = 100;
    for (const double threshold : {0.0, 1e10}) {
        for (const auto& states : patterns) {
            // FD round-off on the rows that vanish analytically (D diagonal) grows with the dual basis Ae: states
            // with a near-singular dual basis (max |Ae_ij| > 100, a slave node barely covered) are replaced.
            std::unique_ptr<FrictionalModel> model;
            SlidingPair sliding;
            do {
                model = std::make_unique<FrictionalModel>();
                std::mt19937 rng(seed++);
                sliding = MakeSlidingPair(*model, GetParam(), rng, states, threshold);
            } while (DualBasisSize(*sliding.pair, row) > 100.0 && seed < 1000);
            auto& pair = *sliding.pair;
            if (shared) {
                std::mt19937 rng(seed);
                ShareNodesWithOtherPairs(pair, sliding.info, rng);
                ASSERT_TRUE(HasValidNodalShare(pair)) << GetParam();
            }
            Matrix lhs;
            Vector rhs;
            pair.CalculateLocalSystem(lhs, rhs, sliding.info);
            ASSERT_FALSE(pair.Is(ISOLATED)) << GetParam();
            // Threshold 0: objective (MODIFIED false); huge: non-objective (MODIFIED true).
            EXPECT_EQ(pair.Is(MODIFIED), threshold > 0.0) << GetParam();
            Vector rhs_only;
            pair.CalculateRightHandSide(rhs_only, sliding.info);
            EXPECT_LT((rhs_only - rhs).norm(), 1e-12 * (1.0 + rhs.norm()));
            const auto dofs = LocalDofs(pair, row);
            // Central differences at h and h/2 combined by Richardson (O(h^4)): the unit slip direction of the
            // trial traction curves strongly where the trial is short, and plain O(h^2) differences measured
            // 6e-5 there while converging as h^2 to the AD tangent.
            const auto central = [&](int q, double h) {
                Vector plus, minus;
                Perturb(dofs[q], h);
                if (row.normal_variation) UpdateNormals(pair, row.dim);
                pair.CalculateRightHandSide(plus, sliding.info);
                Perturb(dofs[q], -2.0 * h);
                if (row.normal_variation) UpdateNormals(pair, row.dim);
                pair.CalculateRightHandSide(minus, sliding.info);
                Perturb(dofs[q], h);
                if (row.normal_variation) UpdateNormals(pair, row.dim);
                return Vector(-(plus - minus) / (2.0 * h));
            };
            // h balances O(h^4) truncation and round-off: with the cells fanned around the area centroid the worst
            // 3D4N3N error was 3.0e-7 / 7.2e-7 / 1.4e-6 / 2.2e-6 at h = 4e-5 / 2e-5 / 1e-5 / 5e-6 (growing as 1/h:
            // round-off of the rows that vanish analytically).
            const double h = 2e-5;
            Matrix fd(row.matrix_size, row.matrix_size);
            for (int q = 0; q < row.matrix_size; ++q) fd.col(q) = (4.0 * central(q, 0.5 * h) - central(q, h)) / 3.0;
            EXPECT_EQ(pair.Is(MODIFIED), threshold > 0.0) << GetParam();
            ASSERT_GT(lhs.norm(), 0.0);
            const double error = RowwiseRelativeError(lhs, fd);
            worst = std::max(worst, error);
            EXPECT_LT(error, 1e-6) << GetParam() << " threshold " << threshold << " pattern " << states[0]
                                   << (shared ? " with a nodal share" : "");
        }
    }
    }
    std::printf("[ FD       ] %-52s worst row-wise relative error %.2e\n", GetParam().c_str(), worst);
    ::testing::Test::RecordProperty("worst_fd_error", std::to_string(worst));
}

TEST_P(FrictionalMortarNames, PreviousOperatorsAreComputedOncePerStepAndNeverStale) {
    const auto& row = DecodedName(GetParam());
    FrictionalModel model;
    std::mt19937 rng(31);
    auto sliding = MakeSlidingPair(model, GetParam(), rng, {2}, 0.0);
    auto& pair = *sliding.pair;
    const SavedPrevious first = ReadPrevious(pair);
    EXPECT_TRUE(first.initialized);
    EXPECT_TRUE(first.overlap);
    ASSERT_EQ(first.D.rows(), row.num_slave);
    ASSERT_EQ(first.M.cols(), row.num_master);
    EXPECT_GT(first.D.norm(), 0.0);
    // A second InitializeSolutionStep in the same step does not recompute (start of step moved on purpose).
    auto& master = const_cast<Geometry&>(pair.GetPairedGeometry());
    for (std::size_t l = 0; l < master.size(); ++l)
        master[l].FastGetSolutionStepValue(DISPLACEMENT, 1) += 0.05 * SlaveTangent(pair);
    pair.InitializeSolutionStep(sliding.info);
    const SavedPrevious same = ReadPrevious(pair);
    EXPECT_EQ((same.D - first.D).norm(), 0.0);
    EXPECT_EQ((same.M - first.M).norm(), 0.0);
    // After FinalizeSolutionStep the next step recomputes them from the new start of step.
    pair.FinalizeSolutionStep(sliding.info);
    EXPECT_FALSE(ReadPrevious(pair).initialized);
    pair.InitializeSolutionStep(sliding.info);
    const SavedPrevious next = ReadPrevious(pair);
    EXPECT_TRUE(next.initialized);
    EXPECT_GT((next.M - first.M).norm(), 1e-6);
    // No overlap at the start of the step: zeros, flagged, and the slip falls back to the non-objective measure.
    pair.FinalizeSolutionStep(sliding.info);
    for (std::size_t l = 0; l < master.size(); ++l)
        master[l].FastGetSolutionStepValue(DISPLACEMENT, 1) += 50.0 * SlaveTangent(pair);
    pair.InitializeSolutionStep(sliding.info);
    const SavedPrevious none = ReadPrevious(pair);
    EXPECT_TRUE(none.initialized);
    EXPECT_FALSE(none.overlap);
    EXPECT_EQ(none.D.norm() + none.M.norm(), 0.0);
    Vector rhs;
    sliding.info.SetValue(OPERATOR_THRESHOLD, 0.0);
    pair.CalculateRightHandSide(rhs, sliding.info);
    EXPECT_TRUE(pair.Is(MODIFIED));
    // Initialize (a rebuilt pair) resets them.
    pair.Initialize(sliding.info);
    EXPECT_FALSE(ReadPrevious(pair).initialized);
}

/// The stick rows and the explicit WEIGHTED_SLIP measure the same slip (objective and non-objective, the latter with
/// the true step increment x − (X0 + d(1)), B1): for ALM, RHS_λj = k g̃_j n_j + k P_j s_j with g̃_j = WEIGHTED_GAP_j
/// and s_j = WEIGHTED_SLIP_j of the single pair.
class FrictionalMortarALMNames : public ::testing::TestWithParam<std::string> {};

TEST_P(FrictionalMortarALMNames, StickRowsAndExplicitWeightedSlipUseTheSameSlip) {
    const auto& row = DecodedName(GetParam());
    for (const double threshold : {0.0, 1e10}) {
        FrictionalModel model;
        std::mt19937 rng(57);
        auto sliding = MakeSlidingPair(model, GetParam(), rng, {2}, threshold);
        auto& pair = *sliding.pair;
        Vector rhs;
        pair.CalculateRightHandSide(rhs, sliding.info);
        ASSERT_EQ(pair.Is(MODIFIED), threshold > 0.0);
        auto& slave = const_cast<Geometry&>(pair.GetParentGeometry());
        for (std::size_t j = 0; j < slave.size(); ++j) {
            slave[j].FastGetSolutionStepValue(WEIGHTED_GAP) = 0.0;
            slave[j].FastGetSolutionStepValue(WEIGHTED_SLIP) = Array3::Zero();
        }
        pair.AddExplicitContribution(sliding.info);
        const double k = sliding.info.GetValue(SCALE_FACTOR);
        const int nu = row.dim * (row.num_slave + row.num_master);
        double slip_norm = 0.0;
        for (int j = 0; j < row.num_slave; ++j) {
            const Array3 n = slave[j].FastGetSolutionStepValue(NORMAL);
            const Array3 slip = slave[j].FastGetSolutionStepValue(WEIGHTED_SLIP);
            const double gap = slave[j].FastGetSolutionStepValue(WEIGHTED_GAP);
            slip_norm += slip.norm();
            for (int c = 0; c < row.dim; ++c)
                EXPECT_NEAR(rhs[nu + j * row.dim + c], k * gap * n[c] + k * slip[c], 1e-12) << j << " " << c;
        }
        EXPECT_GT(slip_norm, 1e-4) << "the step slides";
    }
}

/// Every Check() failure of the frictional families, with its message.
TEST_P(FrictionalMortarNames, CheckAndAssemblyFailuresExplainTheFix) {
    const auto& row = DecodedName(GetParam());
    {
        FrictionalModel model;
        std::mt19937 rng(5);
        auto sliding = MakeSlidingPair(model, GetParam(), rng, {2}, 1e-3);
        EXPECT_EQ(sliding.pair->Check(sliding.info), 0);
        // κ needed by every active node (the stick penalty, the slip trial traction; ALM also inactive ones) but
        // TANGENT_FACTOR missing.
        ProcessInfo no_kappa;  // the same values without TANGENT_FACTOR
        no_kappa.SetValue(SCALE_FACTOR, sliding.info.GetValue(SCALE_FACTOR));
        no_kappa.SetValue(OPERATOR_THRESHOLD, sliding.info.GetValue(OPERATOR_THRESHOLD));
        Vector rhs;
        try {
            sliding.pair->CalculateRightHandSide(rhs, no_kappa);
            ADD_FAILURE() << "no error without TANGENT_FACTOR";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("TANGENT_FACTOR is not set"), std::string::npos) << e.what();
        }
        if (!IsPenalty(row)) {
            ProcessInfo no_scale;
            no_scale.SetValue(TANGENT_FACTOR, sliding.info.GetValue(TANGENT_FACTOR));
            EXPECT_THROW(sliding.pair->CalculateRightHandSide(rhs, no_scale), InputError);
        }
        // All slip: κ still needed (the slip direction is that of the trial traction, docs/theory/mortar.md §8).
        auto& slave = const_cast<Geometry&>(sliding.pair->GetParentGeometry());
        for (std::size_t j = 0; j < slave.size(); ++j) SetNodeState(slave[j], 1);
        try {
            sliding.pair->CalculateRightHandSide(rhs, no_kappa);
            ADD_FAILURE() << "no error without TANGENT_FACTOR in slip";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("(slip) uses it"), std::string::npos) << e.what();
        }
        slave[0].SetValue(INITIAL_PENALTY, 0.0);
        EXPECT_THROW(sliding.pair->CalculateRightHandSide(rhs, sliding.info), InputError);
    }
    auto expect_check = [&](auto&& prepare, const std::string& needle) {
        ContactPairModel model;
        prepare(model);
        std::mt19937 rng(5);
        Eigen::MatrixXd s, m;
        RandomPairCoordinates(row, rng, s, m);
        auto pair = model.MakePair(GetParam(), s, m);
        model.properties->SetValue(THICKNESS, 1.0);
        try {
            pair->Check(ProcessInfo());
            ADD_FAILURE() << "Check passed, expected: " << needle;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("fix:"), std::string::npos) << e.what();
        }
    };
    expect_check([](ContactPairModel& m) { m.part->SetBufferSize(2); }, "WEIGHTED_SLIP");
    expect_check([](ContactPairModel& m) { m.part->AddNodalSolutionStepVariable(WEIGHTED_SLIP); }, "buffer of 1");
    if (!IsPenalty(row)) {  // slave nodes without VECTOR_LAGRANGE_MULTIPLIER (variable and DoFs)
        Model bare_model;
        ModelPart& part = bare_model.CreateModelPart("Bare");
        for (const VariableData* v :
             {static_cast<const VariableData*>(&DISPLACEMENT), static_cast<const VariableData*>(&NORMAL),
              static_cast<const VariableData*>(&WEIGHTED_GAP), static_cast<const VariableData*>(&WEIGHTED_SLIP)})
            part.AddNodalSolutionStepVariable(*v);
        part.SetBufferSize(2);
        std::mt19937 rng(5);
        Eigen::MatrixXd s, m;
        RandomPairCoordinates(row, rng, s, m);
        Geometry::PointsArrayType slave_points, master_points;
        auto add = [&](IndexType id, const Eigen::VectorXd& x, Geometry::PointsArrayType& points) {
            auto node = part.CreateNewNode(id, x[0], x[1], row.dim == 3 ? x[2] : 0.0);
            for (const auto* v : {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z}) node->AddDof(*v);
            points.push_back(node);
        };
        for (int i = 0; i < s.rows(); ++i) add(i + 1, s.row(i).transpose(), slave_points);
        for (int i = 0; i < m.rows(); ++i) add(s.rows() + i + 1, m.row(i).transpose(), master_points);
        const auto& prototype = dynamic_cast<const PairedCondition&>(Registry<Condition>::Instance().Get(GetParam()));
        auto pair = prototype.Create(1, CreateGeometry(FaceGeometryName(row.dim, row.num_slave), slave_points), nullptr,
                                     CreateGeometry(FaceGeometryName(row.dim, row.num_master), master_points));
        try {
            pair->Check(ProcessInfo());
            ADD_FAILURE() << "Check passed without VECTOR_LAGRANGE_MULTIPLIER";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("VECTOR_LAGRANGE_MULTIPLIER"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("ALMContactFrictional"), std::string::npos) << e.what();
        }
    }
    {  // unpaired (.mdpa) condition
        ContactPairModel model;
        const auto& prototype = Registry<Condition>::Instance().Get(GetParam());
        Geometry::PointsArrayType points;
        for (int i = 0; i < row.num_slave; ++i) points.push_back(model.part->CreateNewNode(i + 1, i, 0.5 * i * i, 0.0));
        auto unpaired = prototype.Create(1, points, model.properties);
        try {
            unpaired->Check(ProcessInfo());
            ADD_FAILURE() << "unpaired condition passed Check";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("PAIR GEOMETRY"), std::string::npos) << e.what();
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Registered, FrictionalMortarNames, ::testing::ValuesIn(FrictionalNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

std::vector<std::string> ALMFrictionalNames() {
    std::vector<std::string> names;
    for (const auto& name : FrictionalNames())
        if (!IsPenalty(DecodedName(name))) names.push_back(name);
    return names;
}

INSTANTIATE_TEST_SUITE_P(Registered, FrictionalMortarALMNames, ::testing::ValuesIn(ALMFrictionalNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

/// Flat matching pairs at a uniform gap with no motion in the step (zero slip, both slip measures).
class FrictionalMortarFlatPair : public ::testing::TestWithParam<std::string> {};

std::vector<std::string> MatchingFrictionalNames() {
    std::vector<std::string> names;
    for (const auto& row : RegisteredContactConditionNames())
        if ((row.family == "ALMFrictional" || row.family == "PenaltyFrictional") && row.num_slave == row.num_master)
            names.push_back(row.name);
    return names;
}

std::shared_ptr<PairedCondition> FlatPair(ContactPairModel& model, const std::string& name, double g) {
    Eigen::MatrixXd s, m;
    FlatMatchingPair(DecodedName(name), g, s, m);
    return model.MakeNormalPair(name, s, m, 1.0);
}

/// The frictionless counterpart: same method, scalar multiplier for ALM.
std::string FrictionlessName(const std::string& name) {
    std::string result = name;
    result.replace(result.find("Frictional"), 10, "Frictionless");
    return result;
}

TEST_P(FrictionalMortarFlatPair, StickWithZeroSlipTransfersTheFrictionlessPressure) {
    const auto& row = DecodedName(GetParam());
    const double g = -0.01, k = 2.0, eps = 30.0;
    for (const double threshold : {-1.0, 1e10}) {  // −1: objective even though D = D_old here
        FrictionalModel model;
        auto pair = FlatPair(model, GetParam(), g);
        ContactPairModel reference_model;
        auto reference = FlatPair(reference_model, FrictionlessName(GetParam()), g);
        ProcessInfo info;
        info.SetValue(SCALE_FACTOR, k);
        info.SetValue(TANGENT_FACTOR, 0.5);
        info.SetValue(OPERATOR_THRESHOLD, threshold);
        for (auto* p : {pair.get(), reference.get()}) {
            auto& slave = const_cast<Geometry&>(p->GetParentGeometry());
            for (int j = 0; j < row.num_slave; ++j) {
                SetNodeState(slave[j], 2);
                slave[j].SetValue(INITIAL_PENALTY, eps);
                slave[j].SetValue(FRICTION_COEFFICIENT, 0.3);
                const double lambda_n = -0.1 * (j + 1);
                slave[j].FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) = lambda_n;
                slave[j].FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) =
                    lambda_n * slave[j].FastGetSolutionStepValue(NORMAL);
            }
            p->Initialize(info);
            p->InitializeSolutionStep(info);
        }
        Vector rhs, expected;
        pair->CalculateRightHandSide(rhs, info);
        reference->CalculateRightHandSide(expected, info);
        EXPECT_EQ(pair->Is(MODIFIED), threshold > 0.0);
        const int nu = row.dim * (row.num_slave + row.num_master);
        ASSERT_GT(expected.head(nu).norm(), 0.0);
        EXPECT_LT((rhs.head(nu) - expected.head(nu)).norm(), 1e-12 * expected.head(nu).norm()) << threshold;
        if (!IsPenalty(row))  // λ rows: k g̃ n_j against the scalar k g̃_j
            for (int j = 0; j < row.num_slave; ++j) {
                const Array3 n = pair->GetParentGeometry()[j].FastGetSolutionStepValue(NORMAL);
                for (int c = 0; c < row.dim; ++c)
                    EXPECT_NEAR(rhs[nu + j * row.dim + c], expected[nu + j] * n[c], 1e-12) << j << " " << c;
            }
    }
}

TEST_P(FrictionalMortarFlatPair, SlipTractionIsMuTimesTheNormalPressure) {
    const auto& row = DecodedName(GetParam());
    const double g = -0.01, k = 2.0, eps = 30.0, mu = 0.3;
    FrictionalModel model;
    auto pair = FlatPair(model, GetParam(), g);
    ProcessInfo info;
    info.SetValue(SCALE_FACTOR, k);
    info.SetValue(TANGENT_FACTOR, 0.5);  // the slip direction of the trial traction needs κ; no slip here, so t
    auto& slave = const_cast<Geometry&>(pair->GetParentGeometry());
    std::vector<double> augmented(row.num_slave);
    Vector gaps = Vector::Zero(row.num_slave);
    pair->Initialize(info);
    pair->InitializeSolutionStep(info);
    for (int j = 0; j < row.num_slave; ++j) slave[j].FastGetSolutionStepValue(WEIGHTED_GAP) = 0.0;
    pair->AddExplicitContribution(info);
    for (int j = 0; j < row.num_slave; ++j) {
        SetNodeState(slave[j], 1);
        slave[j].SetValue(INITIAL_PENALTY, eps);
        slave[j].SetValue(FRICTION_COEFFICIENT, mu);  // TANGENT_XI unset: the fallback tangent of n
        const Array3 n = slave[j].FastGetSolutionStepValue(NORMAL);
        const double lambda_n = -0.1 * (j + 1);
        gaps[j] = slave[j].FastGetSolutionStepValue(WEIGHTED_GAP);
        augmented[j] = (IsPenalty(row) ? 0.0 : k * lambda_n) + eps * gaps[j];
        ASSERT_LT(augmented[j], 0.0);
        // The multiplier that satisfies the slip law k λ_τ = −μ λ̄_n t (t = fallback of n: 2D (n_y, −n_x)).
        Array3 t = row.dim == 2 ? Array3(n[1], -n[0], 0.0) : Array3(0.0, -n[2], n[1]).normalized();
        if (row.dim == 3 && std::abs(n[0]) > std::abs(n[2])) t = Array3(-n[1], n[0], 0.0).normalized();
        slave[j].FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = lambda_n * n - mu * augmented[j] / k * t;
    }
    Vector rhs;
    pair->CalculateRightHandSide(rhs, info);
    const int nm = row.num_master, nu = row.dim * (row.num_slave + nm);
    for (int j = 0; j < row.num_slave; ++j) {  // matching flat faces: node j receives D_jj times its traction
        const Array3 n = slave[j].FastGetSolutionStepValue(NORMAL);
        Array3 force = Array3::Zero();
        force.head(row.dim) = rhs.segment(row.dim * nm + j * row.dim, row.dim);
        const double normal = force.dot(n), tangential = (force - normal * n).norm();
        EXPECT_NEAR(tangential, mu * std::abs(normal), 1e-12 * std::abs(normal)) << j;
        EXPECT_GT(std::abs(normal), 0.0);
        if (!IsPenalty(row))  // the λ row only keeps k g̃ n: the tangential (slip-law) part vanishes
            for (int c = 0; c < row.dim; ++c)
                EXPECT_NEAR(rhs[nu + j * row.dim + c], k * gaps[j] * n[c], 1e-12) << j << " " << c;
    }
    EXPECT_LT(std::abs(rhs.head(nu).sum()), 1e-12 * rhs.head(nu).norm());  // action = reaction
}

INSTANTIATE_TEST_SUITE_P(Registered, FrictionalMortarFlatPair, ::testing::ValuesIn(MatchingFrictionalNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace contact_app::testing
