// SPDX-License-Identifier: BSD-3-Clause
/// MPCMortarContactCondition: zero local system on the displacement DoFs, the relation matrix of the three
/// branches (frictionless, frictional stick/slip, tying) on matching and non-matching flat pairs, Q with its negative
/// filter, the constant vector, pruning and the constraint DoF lists, the hooks that refresh the constraint, the
/// test rows of the slipping nodes (Coulomb force), the slip direction's tangent against central differences and
/// the explicit weighted gap / slip.
#include <cstdio>
#include <map>
#include <random>
#include <tuple>

#include "contact_app/kernel/serializer.h"
#include "custom_conditions/mpc_mortar_contact_condition.h"
#include "tests/cpp/error_test_utilities.h"
#include "tying_test_utilities.h"

namespace contact_app::testing {
namespace {

std::string MPCName(const PairKind& kind) { return std::string("MPCMortarContactCondition") + kind.suffix; }

const PairKind& Kind(const std::string& suffix) {
    for (const auto& kind : AllPairKinds())
        if (suffix == kind.suffix) return kind;
    throw std::runtime_error(suffix);
}

/// Matching flat faces: the master is the slave with its nodes reversed, so master node j = slave node n−1−j
/// and Q = D⁻¹M is that permutation.
void MatchingPair(const PairKind& kind, Eigen::MatrixXd& slave, Eigen::MatrixXd& master) {
    if (kind.dim == 2) {
        slave.resize(2, 2);
        slave << 1, 0, 0, 0;
    } else if (kind.num_slave == 3) {
        slave.resize(3, 3);
        slave << 0, 0, 0, 1, 0, 0, 0, 1, 0;
    } else {
        slave.resize(4, 3);
        slave << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
    }
    master = slave.colwise().reverse();
}

/// A pair of @p kind with a ContactMasterSlaveConstraint in CONSTRAINT_POINTER and NODAL_PAUX = @p paux.
struct MPCPair {
    explicit MPCPair(const PairKind& kind, bool matching = true, double paux = 2.0, unsigned seed = 1) {
        Eigen::MatrixXd s, m;
        if (matching) {
            MatchingPair(kind, s, m);
        } else {
            std::mt19937 rng(seed);
            FlatNonMatchingPair(kind, rng, s, m);
        }
        pair = model.MakePair(MPCName(kind), s, m);
        constraint = std::make_shared<ContactMasterSlaveConstraint>(1);
        pair->SetValue(CONSTRAINT_POINTER, std::shared_ptr<MasterSlaveConstraint>(constraint));
        SetPaux(paux);
        dim = kind.dim;
    }
    void SetPaux(double paux) {
        for (std::size_t i = 0; i < Slave().size(); ++i) Slave()[i].SetValue(NODAL_PAUX, paux);
    }
    Geometry& Slave() { return const_cast<Geometry&>(pair->GetParentGeometry()); }
    Geometry& Master() { return const_cast<Geometry&>(pair->GetPairedGeometry()); }
    MPCConstraintRelation Relation(const ProcessInfo& info = ProcessInfo()) const {
        if (dim == 2) return dynamic_cast<const MPCMortarContactCondition<2, 2, 2>&>(*pair).ComputeConstraintRelation(info);
        const int ns = static_cast<int>(pair->GetParentGeometry().size());
        const int nm = static_cast<int>(pair->GetPairedGeometry().size());
        if (ns == 3 && nm == 3)
            return dynamic_cast<const MPCMortarContactCondition<3, 3, 3>&>(*pair).ComputeConstraintRelation(info);
        if (ns == 4 && nm == 4)
            return dynamic_cast<const MPCMortarContactCondition<3, 4, 4>&>(*pair).ComputeConstraintRelation(info);
        if (ns == 3) return dynamic_cast<const MPCMortarContactCondition<3, 3, 4>&>(*pair).ComputeConstraintRelation(info);
        return dynamic_cast<const MPCMortarContactCondition<3, 4, 3>&>(*pair).ComputeConstraintRelation(info);
    }
    Eigen::VectorXd Normal(int i) { return Slave()[i].FastGetSolutionStepValue(NORMAL).head(dim); }

    TyingPairModel model;
    std::shared_ptr<PairedCondition> pair;
    std::shared_ptr<ContactMasterSlaveConstraint> constraint;
    int dim = 0;
};

/// The permutation Q of MatchingPair.
Eigen::MatrixXd MatchingQ(int n) { return Eigen::MatrixXd::Identity(n, n).rowwise().reverse(); }

/// Expected full relation of a matching pair: per slave node i, full (w Q_ij I) or normal-only (w Q_ij n nᵀ).
Eigen::MatrixXd ExpectedRelation(MPCPair& p, const Eigen::MatrixXd& Q, double w, const std::vector<bool>& normal_only) {
    const int d = p.dim, ns = static_cast<int>(Q.rows()), nm = static_cast<int>(Q.cols());
    Eigen::MatrixXd T = Eigen::MatrixXd::Zero(d * ns, d * nm);
    for (int i = 0; i < ns; ++i) {
        const Eigen::MatrixXd block =
            normal_only[i] ? Eigen::MatrixXd(p.Normal(i) * p.Normal(i).transpose()) : Eigen::MatrixXd::Identity(d, d);
        for (int j = 0; j < nm; ++j) T.block(i * d, j * d, d, d) = w * Q(i, j) * block;
    }
    return T;
}

const std::vector<std::string> kMatchingSuffixes = {"2D2N", "3D3N", "3D4N"};

TEST(MPCMortarContactCondition, LocalSystemIsZeroOnTheDisplacementDofs) {
    const std::map<std::string, int> sizes = {{"2D2N", 8}, {"3D3N", 18}, {"3D4N", 24}, {"3D3N4N", 21}, {"3D4N3N", 21}};
    for (const auto& kind : AllPairKinds()) {
        MPCPair p(kind, false);
        ProcessInfo info;
        p.pair->Initialize(info);
        EXPECT_EQ(p.pair->Check(info), 0);
        Matrix lhs;
        Vector rhs;
        p.pair->CalculateLocalSystem(lhs, rhs, info);
        const int size = sizes.at(kind.suffix);
        EXPECT_EQ(DecodedName(MPCName(kind)).matrix_size, size);
        ASSERT_EQ(lhs.rows(), size);
        ASSERT_EQ(lhs.cols(), size);
        ASSERT_EQ(rhs.size(), size);
        EXPECT_EQ(lhs.norm(), 0.0);
        EXPECT_EQ(rhs.norm(), 0.0);
        Matrix mass, damping;
        p.pair->CalculateMassMatrix(mass, info);
        p.pair->CalculateDampingMatrix(damping, info);
        EXPECT_EQ(mass.size() + damping.size(), 0);
        std::vector<Array3> vectors;
        p.pair->CalculateOnIntegrationPoints(NORMAL, vectors, info);
        ASSERT_FALSE(vectors.empty());
        for (const auto& v : vectors) EXPECT_EQ(v.norm(), 0.0);
        DofsVectorType dofs;
        p.pair->GetDofList(dofs, info);
        ASSERT_EQ(static_cast<int>(dofs.size()), size);
        const Variable<double>* u[] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
        int q = 0;
        for (const Geometry* face : {&p.Master(), &p.Slave()})
            for (std::size_t k = 0; k < face->size(); ++k)
                for (int c = 0; c < kind.dim; ++c, ++q) {
                    EXPECT_EQ(&dofs[q]->GetNode(), &(*face)[k]) << kind.suffix << " " << q;
                    EXPECT_EQ(&dofs[q]->GetVariable(), u[c]) << kind.suffix << " " << q;
                }
    }
}

TEST(MPCMortarContactCondition, TyingRelationOnAMatchingFlatPairIsThePermutationQ) {
    for (const auto& suffix : kMatchingSuffixes) {
        const PairKind& kind = Kind(suffix);
        MPCPair p(kind);
        p.pair->Set(RIGID, true);
        const auto relation = p.Relation();
        const Eigen::MatrixXd expected =
            ExpectedRelation(p, MatchingQ(kind.num_slave), 0.5, std::vector<bool>(kind.num_slave, false));
        EXPECT_LT((relation.relation - expected).cwiseAbs().maxCoeff(), 1e-12) << suffix << "\n" << relation.relation;
    }
}

TEST(MPCMortarContactCondition, FrictionlessRelationConstrainsTheNormalComponentOnly) {
    for (const auto& suffix : kMatchingSuffixes) {
        const PairKind& kind = Kind(suffix);
        MPCPair p(kind);
        const auto relation = p.Relation();
        const Eigen::MatrixXd expected =
            ExpectedRelation(p, MatchingQ(kind.num_slave), 0.5, std::vector<bool>(kind.num_slave, true));
        EXPECT_LT((relation.relation - expected).cwiseAbs().maxCoeff(), 1e-12) << suffix;
        EXPECT_GT(relation.relation.cwiseAbs().maxCoeff(), 0.4);
    }
}

TEST(MPCMortarContactCondition, FrictionalRelationIsNormalOnlyOnSlipNodesAndFullOnStickNodes) {
    for (const auto& suffix : kMatchingSuffixes) {
        const PairKind& kind = Kind(suffix);
        MPCPair p(kind);
        p.pair->Set(SLIP, true);
        p.pair->Set(RIGID, true);  // SLIP decides before RIGID
        std::vector<bool> slip(kind.num_slave, false);
        slip[0] = true;
        p.Slave()[0].Set(SLIP, true);
        const auto relation = p.Relation();
        const Eigen::MatrixXd expected = ExpectedRelation(p, MatchingQ(kind.num_slave), 0.5, slip);
        EXPECT_LT((relation.relation - expected).cwiseAbs().maxCoeff(), 1e-12) << suffix;
    }
}

TEST(MPCMortarContactCondition, InactiveNodeRowsAreZero) {
    MPCPair p(Kind("3D3N"));
    p.pair->Set(RIGID, true);
    p.Slave()[1].Set(ACTIVE, false);
    p.Slave()[2].Set(ACTIVE, true);  // node 0 undefined: active (Kratos IsActive)
    const auto relation = p.Relation();
    EXPECT_EQ(relation.relation.middleRows(3, 3).norm(), 0.0);
    EXPECT_GT(relation.relation.topRows(3).norm(), 0.4);
    EXPECT_GT(relation.relation.bottomRows(3).norm(), 0.4);
}

TEST(MPCMortarContactCondition, QReproducesLinearFieldsOnFlatNonMatchingPairs) {
    // D x1 = M x2 for coplanar faces, so every row of Q = D⁻¹M of an overlapping pair maps the master coordinates
    // onto the slave ones and sums to 1, negative entries (frequent with dual multipliers on non-matching meshes)
    // included: the reference zeroes such rows, which dropped the node's constraint (docs/theory/mortar.md §9).
    int total_negative = 0, total_rows = 0;
    for (const auto& kind : AllPairKinds())
        for (unsigned seed = 1; seed <= 8; ++seed) {
            MPCPair p(kind, false, 1.0, seed);
            p.pair->Set(RIGID, true);
            const auto relation = p.Relation();
            const int d = kind.dim;
            Eigen::MatrixXd Q(kind.num_slave, kind.num_master);
            for (int i = 0; i < kind.num_slave; ++i)
                for (int j = 0; j < kind.num_master; ++j) Q(i, j) = relation.relation(i * d, j * d);
            Eigen::MatrixXd x1(kind.num_slave, d), x2(kind.num_master, d);
            for (int i = 0; i < kind.num_slave; ++i) x1.row(i) = p.Slave()[i].Coordinates().head(d).transpose();
            for (int j = 0; j < kind.num_master; ++j) x2.row(j) = p.Master()[j].Coordinates().head(d).transpose();
            for (int i = 0; i < kind.num_slave; ++i) {
                if (Q.row(i).norm() == 0.0) continue;  // the node is outside the overlap
                ++total_rows;
                if (Q.row(i).minCoeff() < 0.0) ++total_negative;
                EXPECT_NEAR(Q.row(i).sum(), 1.0, 1e-12) << kind.suffix << " row " << i;
                EXPECT_LT((Q.row(i) * x2 - x1.row(i)).norm(), 1e-12) << kind.suffix << " row " << i;
            }
        }
    std::printf("[ MPC ] rows of Q with a negative entry: %d of %d\n", total_negative, total_rows);
    EXPECT_GT(total_rows, 10);
    EXPECT_GT(total_negative, 0);
}

TEST(MPCMortarContactCondition, QIsTheInverseOfDTimesM) {
    using Condition22 = MPCMortarContactCondition<2, 2, 2>;
    Condition22::Operators operators;
    operators.D << 0.5, 0.0, 0.0, 0.25;
    operators.M << 0.6, -0.1, 0.3, -1e-9;
    Eigen::Matrix2d Q = Condition22::ComputeQ(operators, true);  // dual: D diagonal, negative entries kept
    EXPECT_NEAR(Q(0, 0), 1.2, 1e-15);
    EXPECT_NEAR(Q(0, 1), -0.2, 1e-15);
    EXPECT_NEAR(Q(1, 0), 1.2, 1e-15);
    EXPECT_NEAR(Q(1, 1), -4e-9, 1e-20);
    operators.D << 0.5, 0.1, 0.1, 0.5;  // standard basis: full inverse
    operators.M << 0.3, 0.2, 0.1, 0.4;
    Q = Condition22::ComputeQ(operators, false);
    const Eigen::Matrix2d expected = operators.D.inverse() * operators.M;
    EXPECT_LT((Q - expected).cwiseAbs().maxCoeff(), 1e-15);
    operators.D.setZero();  // isolated pair: no constraint
    EXPECT_EQ(Condition22::ComputeQ(operators, false).norm(), 0.0);
}

TEST(MPCMortarContactCondition, ConstantVectorCarriesTheGapAndThePreviousDisplacements) {
    for (const auto& suffix : kMatchingSuffixes) {
        const PairKind& kind = Kind(suffix);
        MPCPair p(kind);
        std::mt19937 rng(9);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        const int d = kind.dim, ns = kind.num_slave;
        std::vector<double> gap(ns), area(ns);
        for (int i = 0; i < ns; ++i) {
            gap[i] = 0.1 * u(rng);
            area[i] = 0.3 + 0.1 * u(rng);
            p.Slave()[i].FastGetSolutionStepValue(WEIGHTED_GAP) = gap[i];
            p.Slave()[i].SetValue(NODAL_AREA, area[i]);
            p.Slave()[i].FastGetSolutionStepValue(DISPLACEMENT, 1) = Array3(u(rng), u(rng), d == 3 ? u(rng) : 0.0);
            p.Master()[i].FastGetSolutionStepValue(DISPLACEMENT, 1) = Array3(u(rng), u(rng), d == 3 ? u(rng) : 0.0);
        }
        p.Slave()[0].Set(ACTIVE, false);  // the constant is computed for every node
        const auto relation = p.Relation();
        const Eigen::MatrixXd Q = MatchingQ(ns);
        for (int i = 0; i < ns; ++i) {
            Eigen::VectorXd relative = p.Slave()[i].FastGetSolutionStepValue(DISPLACEMENT, 1).head(d);
            for (int j = 0; j < ns; ++j) relative -= Q(i, j) * p.Master()[j].FastGetSolutionStepValue(DISPLACEMENT, 1).head(d);
            const Eigen::VectorXd n = p.Normal(i);
            // The pair's share of the node: D_ii / NODAL_AREA, D_ii = ∫N_i = face measure / nodes on these faces.
            const double share = std::abs(p.Slave().DomainSize()) / ns / area[i];
            const Eigen::VectorXd expected = share * (gap[i] / area[i] + n.dot(relative)) * n;
            EXPECT_LT((relation.constant.segment(i * d, d) - expected).norm(), 1e-12) << suffix << " node " << i;
        }
    }
}

TEST(MPCMortarContactCondition, StickRowsKeepTheStartOfStepTangentialOffsetAndARebuildTakesTheCurrentGap) {
    // A sticking node does not slip in the step: P(u_s − Q u_m) keeps its start-of-step value (buffer 1), whatever
    // the node did before (a node that touches in this step carries its earlier tangential motion). The normal part
    // closes the gap WEIGHTED_GAP from the displacement it was computed at: buffer 1 for the step's first build, the
    // current iterate for a rebuild inside the step (INTERACTION). Before: the stick rows tied P(u_s − Q u_m) to 0.
    for (const auto& suffix : kMatchingSuffixes) {
        const PairKind& kind = Kind(suffix);
        for (const bool rebuild : {false, true}) {
            MPCPair p(kind);
            p.pair->Set(SLIP, true);
            p.pair->Set(INTERACTION, rebuild);
            std::mt19937 rng(13);
            std::uniform_real_distribution<double> u(-1.0, 1.0);
            const int d = kind.dim, ns = kind.num_slave;
            auto random = [&] { return Array3(u(rng), u(rng), d == 3 ? u(rng) : 0.0); };
            // The current displacement is one translation of both faces (the pair's current geometry, Q and normals
            // stay those of the matching pair): u_s − Q u_m = 0 now, random at the start of the step.
            const Array3 translation = random();
            for (int i = 0; i < ns; ++i) {
                p.Slave()[i].FastGetSolutionStepValue(WEIGHTED_GAP) = 0.1 * u(rng);
                p.Slave()[i].SetValue(NODAL_AREA, 0.3 + 0.1 * u(rng));
                for (Node* node : {&p.Slave()[i], &p.Master()[i]}) {
                    node->FastGetSolutionStepValue(DISPLACEMENT, 1) = random();
                    node->FastGetSolutionStepValue(DISPLACEMENT) = translation;
                }
            }
            p.Slave()[0].Set(SLIP, true);  // normal-only: no tangential offset
            const auto relation = p.Relation();
            const Eigen::MatrixXd Q = MatchingQ(ns);
            auto relative = [&](int i, int buffer) {
                Eigen::VectorXd r = p.Slave()[i].FastGetSolutionStepValue(DISPLACEMENT, buffer).head(d);
                for (int j = 0; j < ns; ++j)
                    r -= Q(i, j) * p.Master()[j].FastGetSolutionStepValue(DISPLACEMENT, buffer).head(d);
                return r;
            };
            for (int i = 1; i < ns; ++i) {
                const Eigen::VectorXd n = p.Normal(i);
                const double area = p.Slave()[i].GetValue(NODAL_AREA);
                const double share = std::abs(p.Slave().DomainSize()) / ns / area;
                const double gap = p.Slave()[i].FastGetSolutionStepValue(WEIGHTED_GAP) / area;
                const Eigen::VectorXd previous = relative(i, 1);
                const Eigen::VectorXd expected =
                    share * ((gap + n.dot(relative(i, rebuild ? 0 : 1))) * n + previous - n.dot(previous) * n);
                EXPECT_LT((relation.constant.segment(i * d, d) - expected).norm(), 1e-12)
                    << suffix << " rebuild " << rebuild << " node " << i;
            }
            // The slipping node's single row carries the normal part only.
            const Eigen::VectorXd n0 = p.Normal(0);
            const double area0 = p.Slave()[0].GetValue(NODAL_AREA);
            const double normal0 = std::abs(p.Slave().DomainSize()) / ns / area0 *
                                   (p.Slave()[0].FastGetSolutionStepValue(WEIGHTED_GAP) / area0 +
                                    n0.dot(relative(0, rebuild ? 0 : 1)));
            Eigen::Index pivot = 0;
            n0.cwiseAbs().maxCoeff(&pivot);
            EXPECT_NEAR(relation.constant[pivot], normal0 / n0[pivot], 1e-12) << suffix;
        }
    }
}

TEST(MPCMortarContactCondition, PruningSetsTheConstraintDofListsAndReducedSystem) {
    MPCPair p(Kind("2D2N"));
    p.Slave()[0].FastGetSolutionStepValue(WEIGHTED_GAP) = 0.02;
    ProcessInfo info;
    p.pair->Initialize(info);
    // Normal (0, ±1): only the y rows / columns survive.
    ASSERT_LT(std::abs(p.Normal(0)[0]), 1e-15);
    DofsVectorType slaves, masters;
    p.constraint->GetDofList(slaves, masters, info);
    ASSERT_EQ(slaves.size(), 2u);
    ASSERT_EQ(masters.size(), 2u);
    EXPECT_EQ(&slaves[0]->GetNode(), &p.Slave()[0]);
    EXPECT_EQ(&slaves[1]->GetNode(), &p.Slave()[1]);
    EXPECT_EQ(&masters[0]->GetNode(), &p.Master()[0]);
    EXPECT_EQ(&masters[1]->GetNode(), &p.Master()[1]);
    for (const auto* dof : {slaves[0], slaves[1], masters[0], masters[1]}) EXPECT_EQ(&dof->GetVariable(), &DISPLACEMENT_Y);
    Matrix T;
    Vector c;
    p.constraint->CalculateLocalSystem(T, c, info);
    Eigen::Matrix2d expected;
    expected << 0.0, 0.5, 0.5, 0.0;  // w = 1/2, slave 0 ↔ master 1
    EXPECT_LT((T - expected).cwiseAbs().maxCoeff(), 1e-12);
    const double n_y = p.Normal(0)[1];
    EXPECT_NEAR(c[0], 0.5 * 0.02 * n_y, 1e-14);  // NODAL_AREA absent: A = 1
    EXPECT_NEAR(c[1], 0.0, 1e-14);

    // An inactive node loses its row; a relation below the pruning tolerance empties the constraint.
    p.Slave()[1].Set(ACTIVE, false);
    p.pair->InitializeSolutionStep(info);
    p.constraint->GetDofList(slaves, masters, info);
    ASSERT_EQ(slaves.size(), 1u);
    EXPECT_EQ(&slaves[0]->GetNode(), &p.Slave()[0]);
    ASSERT_EQ(masters.size(), 1u);
    EXPECT_EQ(&masters[0]->GetNode(), &p.Master()[1]);
    p.SetPaux(1.0e13);  // w = 1e−13 < 1e−12
    p.pair->InitializeSolutionStep(info);
    p.constraint->GetDofList(slaves, masters, info);
    EXPECT_TRUE(slaves.empty());
    EXPECT_TRUE(masters.empty());
    p.constraint->CalculateLocalSystem(T, c, info);
    EXPECT_EQ(T.size(), 0);
    EXPECT_EQ(c.size(), 0);
}

TEST(MPCMortarContactCondition, HooksRefreshTheConstraintAsDocumented) {
    MPCPair p(Kind("3D3N"));
    ProcessInfo info;
    auto weight = [&] {
        Matrix T;
        Vector c;
        p.constraint->CalculateLocalSystem(T, c, info);
        return T.size() ? T.cwiseAbs().maxCoeff() : 0.0;
    };
    EXPECT_EQ(weight(), 0.0);
    p.pair->Initialize(info);
    EXPECT_NEAR(weight(), 0.5, 1e-12);
    p.SetPaux(4.0);
    p.pair->InitializeNonLinearIteration(info);  // not INTERACTION: untouched
    EXPECT_NEAR(weight(), 0.5, 1e-12);
    p.pair->Set(INTERACTION, true);
    p.pair->InitializeNonLinearIteration(info);
    EXPECT_NEAR(weight(), 0.25, 1e-12);
    p.pair->Set(BLOCKED, true);
    p.SetPaux(1.0);
    p.pair->InitializeSolutionStep(info);  // BLOCKED: untouched
    EXPECT_NEAR(weight(), 0.25, 1e-12);
    p.pair->Set(BLOCKED, false);
    p.pair->InitializeSolutionStep(info);
    EXPECT_NEAR(weight(), 1.0, 1e-12);
    // Without a constraint the hooks are no-ops.
    p.pair->SetValue(CONSTRAINT_POINTER, std::shared_ptr<MasterSlaveConstraint>());
    EXPECT_NO_THROW(p.pair->InitializeSolutionStep(info));
    // A SLIP condition computes its previous operators in Initialize and at the end of the step.
    auto& mpc = dynamic_cast<MPCMortarContactCondition<3, 3, 3>&>(*p.pair);
    EXPECT_FALSE(mpc.PreviousMortarOperatorsInitialized());
    p.pair->Set(SLIP, true);
    p.pair->Initialize(info);
    EXPECT_TRUE(mpc.PreviousMortarOperatorsInitialized());
    EXPECT_NEAR(mpc.GetPreviousMortarOperators().D.trace(), 0.5, 1e-12);  // Σ D_jj = triangle area
}

TEST(MPCMortarContactCondition, ActiveNodeWithoutNodalWeightIsAnInputError) {
    MPCPair p(Kind("2D2N"), true, 0.0);
    try {
        p.pair->Initialize(ProcessInfo());
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("NODAL_PAUX"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("fix:"), std::string::npos);
    }
}

TEST(MPCMortarContactCondition, SlipRowsAreTestedAlongTheCoulombForceAndTheRightHandSideIsZero) {
    for (const auto& suffix : kMatchingSuffixes) {
        const PairKind& kind = Kind(suffix);
        MPCPair p(kind);
        const int d = kind.dim, ns = kind.num_slave, nm = kind.num_master;
        ProcessInfo info;
        p.pair->Set(SLIP, true);
        // Node 0 slips with friction along t0, node 1 slips without (μ = 0), the others stick.
        const double mu = 0.4;
        const Eigen::Vector3d t0 = d == 2 ? Eigen::Vector3d(1, 0, 0) : Eigen::Vector3d(0.6, 0.8, 0.0);
        for (int i = 0; i < 2; ++i) p.Slave()[i].Set(SLIP, true);
        p.Slave()[0].SetValue(FRICTION_COEFFICIENT, mu);
        p.Slave()[0].SetValue(TANGENT_XI, Array3(t0));
        p.Slave()[1].SetValue(FRICTION_COEFFICIENT, 0.0);
        p.Slave()[1].SetValue(TANGENT_XI, Array3(t0));
        const auto relation = p.Relation();
        ASSERT_EQ(relation.test_relation.rows(), relation.relation.rows()) << suffix;
        // Every row but node 0's pivot row (the normal component, d − 1 on these flat faces) is the relation's.
        const int pivot_row = d - 1;
        Eigen::MatrixXd other = relation.test_relation - relation.relation;
        Eigen::MatrixXd other_coupling = relation.test_slave_coupling - relation.slave_coupling;
        other.row(pivot_row).setZero();
        other_coupling.row(pivot_row).setZero();
        EXPECT_EQ(other.norm() + other_coupling.norm(), 0.0) << suffix;
        // Node 0's row: n replaced by v = n − μ t0 (w = 1/2, Q the permutation of MatchingPair).
        const Eigen::VectorXd n = p.Normal(0), v = n - mu * t0.head(d);
        const Eigen::MatrixXd Q = MatchingQ(ns);
        for (int j = 0; j < nm; ++j)
            for (int b = 0; b < d; ++b) {
                EXPECT_NEAR(relation.test_relation(pivot_row, j * d + b), 0.5 * Q(0, j) * v[b] / v[d - 1], 1e-14);
                EXPECT_NEAR(relation.relation(pivot_row, j * d + b), 0.5 * Q(0, j) * n[b] / n[d - 1], 1e-14);
            }
        for (int b = 0; b < d - 1; ++b)
            EXPECT_NEAR(relation.test_slave_coupling(pivot_row, b), -0.5 * v[b] / v[d - 1], 1e-14) << suffix;
        // The constraint keeps the tangential columns the test row needs and stores W.
        p.pair->Initialize(info);
        Matrix T, W;
        Vector c;
        p.constraint->CalculateLocalSystem(T, c, info);
        ASSERT_TRUE(p.constraint->CalculateTestRelation(W, info)) << suffix;
        ASSERT_EQ(W.rows(), T.rows());
        ASSERT_EQ(W.cols(), T.cols());
        EXPECT_NEAR((W - T).cwiseAbs().maxCoeff(), 0.5 * mu * t0.head(d).cwiseAbs().maxCoeff() / std::abs(n[d - 1]), 1e-14)
            << suffix;
        // No LHS without a slip and a normal force, and never a RHS: the force is in W.
        Matrix lhs;
        Vector rhs;
        p.pair->CalculateLocalSystem(lhs, rhs, info);
        EXPECT_EQ(lhs.norm(), 0.0);
        EXPECT_EQ(rhs.size(), d * (ns + nm));
        EXPECT_EQ(rhs.norm(), 0.0);
        // Without friction W = T.
        p.Slave()[0].SetValue(FRICTION_COEFFICIENT, 0.0);
        p.pair->InitializeSolutionStep(info);
        EXPECT_FALSE(p.constraint->CalculateTestRelation(W, info)) << suffix;
    }
}

/// Moves a node as the solver does: displacement and (moved mesh) coordinates; the contact reads X0 + u.
void Move(Node& node, int component, double delta) {
    node.Coordinates()[component] += delta;
    node.FastGetSolutionStepValue(DISPLACEMENT)[component] += delta;
}

TEST(MPCMortarContactCondition, ExplicitContributionAddsWeightedGapAreaAndSlip) {
    MPCPair p(Kind("2D2N"));
    ProcessInfo info;
    const double n_y = p.Normal(0)[1];
    // Master moved by g along the slave normal: g̃_j = D_jj g with D_jj = ½ (dual basis on a unit segment).
    const double g = 0.03;
    for (std::size_t j = 0; j < 2; ++j) {
        Move(p.Master()[j], 1, g * n_y);
        p.Slave()[j].SetValue(NODAL_AREA, 0.0);
    }
    p.pair->AddExplicitContribution(info);
    for (std::size_t j = 0; j < 2; ++j) {
        EXPECT_NEAR(p.Slave()[j].FastGetSolutionStepValue(WEIGHTED_GAP), 0.5 * g, 1e-14);
        EXPECT_NEAR(p.Slave()[j].GetValue(NODAL_AREA), 0.5, 1e-14);
        EXPECT_EQ(p.Slave()[j].FastGetSolutionStepValue(WEIGHTED_SLIP).norm(), 0.0);  // not SLIP
    }
    // SLIP: previous operators at the start, then the master slides tangentially.
    p.pair->Set(SLIP, true);
    p.pair->Initialize(info);
    for (std::size_t j = 0; j < 2; ++j) Move(p.Master()[j], 0, 0.1);
    p.pair->AddExplicitContribution(info);
    for (std::size_t j = 0; j < 2; ++j) {
        const Array3 slip = p.Slave()[j].FastGetSolutionStepValue(WEIGHTED_SLIP);
        EXPECT_GT(std::abs(slip[0]), 1e-3) << j;
        EXPECT_NEAR(slip.head(2).dot(p.Normal(j)), 0.0, 1e-14) << j;  // tangential
    }
}

/// The slip direction's tangent of CalculateLeftHandSide against central differences of the Coulomb force
/// f_i = μ|λ_i| ŝ_i(u) (ŝ from the weighted slip of the explicit pass, λ and n held), spread to the masters by the
/// pair's Q. One pair per node (NODAL_AREA its own), so the master rows are exact too. The pivot rows are the
/// constraint's and are left out. 2D: the direction cannot turn, the LHS is zero.
TEST(MPCMortarContactCondition, SlipDirectionTangentMatchesCentralDifferences) {
    for (const std::string suffix : {"2D2N", "3D3N", "3D4N", "3D4N3N", "3D3N4N"}) {
        const PairKind& kind = Kind(suffix);
        const bool matching = kind.num_slave == kind.num_master;
        MPCPair p(kind, matching, 1.0, 3);
        const int d = kind.dim, ns = kind.num_slave, nm = kind.num_master, size = d * (ns + nm);
        ProcessInfo info;
        p.pair->Set(SLIP, true);
        p.pair->Initialize(info);  // start-of-step operators
        const Eigen::Vector3d slide(0.02, d == 3 ? 0.011 : 0.0, 0.0);
        for (int j = 0; j < nm; ++j)
            for (int a = 0; a < d; ++a) Move(p.Master()[j], a, slide[a]);
        const double mu = 0.3;
        std::vector<Eigen::VectorXd> normals;
        for (int i = 0; i < ns; ++i) {
            normals.push_back(p.Normal(i));
            p.Slave()[i].Set(SLIP, true);
            p.Slave()[i].SetValue(FRICTION_COEFFICIENT, mu);
            Array3 reaction = Array3::Zero();
            reaction.head(d) = -(1.0 + i) * normals[i];  // λ_i = −(1 + i)
            p.Slave()[i].FastGetSolutionStepValue(REACTION) = reaction;
        }
        auto explicit_pass = [&] {
            for (int i = 0; i < ns; ++i) {
                p.Slave()[i].FastGetSolutionStepValue(WEIGHTED_SLIP) = Array3::Zero();
                p.Slave()[i].FastGetSolutionStepValue(WEIGHTED_GAP) = 0.0;
                p.Slave()[i].SetValue(NODAL_AREA, 0.0);
            }
            p.pair->AddExplicitContribution(info);
        };
        auto direction = [&](int i) {
            Eigen::VectorXd s = p.Slave()[i].FastGetSolutionStepValue(WEIGHTED_SLIP).head(d);
            s -= s.dot(normals[i]) * normals[i];
            return s.norm() > 1.0e-9 ? Eigen::VectorXd(s / s.norm()) : Eigen::VectorXd(Eigen::VectorXd::Zero(d));
        };
        explicit_pass();
        for (int i = 0; i < ns; ++i) {
            Array3 e = Array3::Zero();
            e.head(d) = direction(i);
            p.Slave()[i].SetValue(TANGENT_XI, e);
        }
        // Q of the pair: the full-tie relation (weight 1) of the same state.
        p.pair->Set(SLIP, false);
        p.pair->Set(RIGID, true);
        const auto tie = p.Relation();
        p.pair->Set(RIGID, false);
        p.pair->Set(SLIP, true);
        auto force = [&] {
            explicit_pass();
            Eigen::VectorXd F = Eigen::VectorXd::Zero(size);
            for (int i = 0; i < ns; ++i) {
                const Eigen::VectorXd f = mu * (1.0 + i) * direction(i);
                F.segment(d * nm + d * i, d) += f;
                for (int j = 0; j < nm; ++j) F.segment(d * j, d) -= tie.relation(i * d, j * d) * f;
            }
            return F;
        };
        explicit_pass();
        Matrix lhs;
        p.pair->CalculateLeftHandSide(lhs, info);
        ASSERT_EQ(lhs.rows(), size);
        if (d == 2) {
            EXPECT_EQ(lhs.norm(), 0.0);
            continue;
        }
        ASSERT_GT(lhs.norm(), 1.0) << suffix;
        const double h = 1.0e-7;
        Eigen::MatrixXd fd(size, size);
        for (int k = 0; k < size; ++k) {
            Node& node = k < d * nm ? p.Master()[k / d] : p.Slave()[(k - d * nm) / d];
            Move(node, k % d, h);
            const Eigen::VectorXd plus = force();
            Move(node, k % d, -2.0 * h);
            const Eigen::VectorXd minus = force();
            Move(node, k % d, h);
            fd.col(k) = -(plus - minus) / (2.0 * h);
        }
        for (int i = 0; i < ns; ++i) {  // the pivot: largest min(|n_a|, |v_a|), v = n − μe (here the largest |n_a|)
            const Eigen::VectorXd e = p.Slave()[i].GetValue(TANGENT_XI).head(d);
            Eigen::Index pivot = 0;
            normals[i].cwiseAbs().cwiseMin((normals[i] - mu * e).cwiseAbs()).maxCoeff(&pivot);
            fd.row(d * nm + d * i + pivot) = lhs.row(d * nm + d * i + pivot);
        }
        const double error = (fd - lhs).cwiseAbs().maxCoeff();
        EXPECT_LT(error, 1.0e-6 * lhs.cwiseAbs().maxCoeff()) << suffix << ": max |LHS - FD| = " << error;
    }
}

TEST(MPCMortarContactCondition, SaveLoadRestoresThePreviousMortarOperators) {
    MPCPair saved(Kind("3D4N3N"), false);
    saved.pair->Set(SLIP, true);
    saved.pair->Initialize(ProcessInfo());
    const auto& source = dynamic_cast<const MPCMortarContactCondition<3, 4, 3>&>(*saved.pair);
    ASSERT_GT(source.GetPreviousMortarOperators().D.norm(), 0.1);
    Serializer archive;
    saved.pair->Save(archive);
    MPCPair loaded(Kind("3D4N3N"), false, 2.0, 7);
    Serializer reader(archive.Data());
    loaded.pair->Load(reader);
    EXPECT_TRUE(reader.AtEnd());
    const auto& target = dynamic_cast<const MPCMortarContactCondition<3, 4, 3>&>(*loaded.pair);
    EXPECT_TRUE(target.PreviousMortarOperatorsInitialized());
    EXPECT_EQ(target.GetPreviousMortarOperators().D, source.GetPreviousMortarOperators().D);
    EXPECT_EQ(target.GetPreviousMortarOperators().M, source.GetPreviousMortarOperators().M);
}

TEST(MPCMortarContactCondition, CheckReportsEveryMissingPiece) {
    {
        MPCPair p(Kind("3D3N"));
        EXPECT_EQ(CheckMessage(*p.pair), "");
        const auto unpaired = p.pair->Create(5, p.pair->pGetParentGeometry(), p.model.properties, nullptr);
        EXPECT_NE(CheckMessage(*unpaired).find("YOU HAVE NOT INITIALIZED THE PAIR GEOMETRY"), std::string::npos);
        const auto& quad = dynamic_cast<const PairedCondition&>(
            Registry<Condition>::Instance().Get("MPCMortarContactCondition3D4N3N"));
        const auto wrong = quad.Create(6, p.pair->pGetParentGeometry(), p.model.properties, p.pair->pGetPairedGeometry());
        EXPECT_NE(CheckMessage(*wrong).find("expected: 4 and 3 nodes"), std::string::npos) << CheckMessage(*wrong);
    }
    const std::vector<std::tuple<std::string, std::string, std::string>> missing = {
        {"DISPLACEMENT", "", "does not store DISPLACEMENT"},
        {"NORMAL", "", "does not store NORMAL"},
        {"WEIGHTED_GAP", "", "does not store WEIGHTED_GAP"},
        {"", "DISPLACEMENT_Z", "has no DISPLACEMENT_Z DoF"},
    };
    for (const auto& [variable, dof, fragment] : missing) {
        std::set<std::string> variables, dofs;
        if (!variable.empty()) variables.insert(variable);
        if (!dof.empty()) dofs.insert(dof);
        TyingPairModel model(variables, dofs);
        Eigen::MatrixXd s, m;
        MatchingPair(Kind("3D3N"), s, m);
        const std::string message = CheckMessage(*model.MakePair("MPCMortarContactCondition3D3N", s, m));
        EXPECT_NE(message.find(fragment), std::string::npos) << fragment << " / got: " << message;
        EXPECT_NE(message.find("fix:"), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace contact_app::testing
