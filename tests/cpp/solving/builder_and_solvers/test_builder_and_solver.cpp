// SPDX-License-Identifier: BSD-3-Clause
/// The parallel assembly of BuilderAndSolver (docs/architecture.md, "Threading model"): on a frictional 3D contact
/// model (two blocks of hexahedra, a non-matching interface of ALM or penalty frictional 3D4N pairs with inactive,
/// slipping and sticking slave nodes) the system assembled with 1 and 2 threads is bit-identical, and equal to the
/// bit to the serial scatter of every local system in entity order; a failing entity's error reaches the caller.
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../custom_conditions/contact_condition_test_utilities.h"
#include "contact_app/kernel/constitutive_law.h"
#include "contact_app/solving/builder_and_solvers/block_builder_and_solver.h"
#include "contact_app/solving/linear_solvers/linear_solver_factory.h"
#include "contact_app/solving/parallel_utilities.h"
#include "contact_app/solving/schemes/scheme.h"
#include "custom_strategies/nodal_penalty_coupling.h"
#include "custom_utilities/contact_utilities.h"

namespace contact_app::testing {
namespace {

/// Restores the thread count of the test binary when a test ends.
class ThreadCountGuard {
public:
    ThreadCountGuard() : mThreads(ParallelUtilities::GetNumThreads()) {}
    ~ThreadCountGuard() { ParallelUtilities::SetNumThreads(mThreads); }
    ThreadCountGuard(const ThreadCountGuard&) = delete;
    ThreadCountGuard& operator=(const ThreadCountGuard&) = delete;

private:
    int mThreads;
};

/// Two blocks of hexahedra: the lower one (n_l × n_l × 2 on [0, 1]² × [−0.5, 0], master top face) and the upper one
/// (n_u × n_u × 2, shifted by 0.03 in x and y and 0.01 into the lower one, slave bottom face), a pair for every
/// overlapping (slave face, master face), random step displacements, and the explicit pass done.
struct FrictionalBlocks {
    Model model;
    ModelPart* part = nullptr;
    ProcessInfo* info = nullptr;
    bool penalty = false;

    explicit FrictionalBlocks(const std::string& family) : penalty(family == "PenaltyFrictional") {
        RegisterContactApplication();
        RegisterContactConditions();
        part = &model.CreateModelPart("Structure", 2);
        for (const VariableData* v : std::initializer_list<const VariableData*>{
                 &DISPLACEMENT, &REACTION, &NORMAL, &WEIGHTED_GAP, &WEIGHTED_SLIP, &VECTOR_LAGRANGE_MULTIPLIER,
                 &LAGRANGE_MULTIPLIER_CONTACT_PRESSURE})
            part->AddNodalSolutionStepVariable(*v);
        info = &part->GetProcessInfo();
        info->SetValue(DOMAIN_SIZE, 3);
        info->SetValue(SCALE_FACTOR, 1.5);
        info->SetValue(TANGENT_FACTOR, 0.4);
        info->SetValue(CONSIDER_NORMAL_VARIATION, 0);
        auto properties = part->CreateNewProperties(1);
        properties->SetValue(YOUNG_MODULUS, 1.0e3);
        properties->SetValue(POISSON_RATIO, 0.3);
        properties->SetValue(CONSTITUTIVE_LAW, Registry<ConstitutiveLaw>::Instance().Get("LinearElastic3DLaw").Clone());
        properties->SetValue(INTEGRATION_ORDER_CONTACT, 3);
        const std::vector<IndexType> master_faces = Block(1, 6, 0.0, -0.5, false);
        const std::vector<IndexType> slave_faces = Block(1001, 5, 0.03, -0.01, true);
        MakePairs(family, slave_faces, master_faces);
        SetStep();
        ContactUtilities::ComputeExplicitContributionConditions(part->GetSubModelPart("ComputingContact"));
    }

    /// Nodes (ids from @p first), elements and DoFs of an n × n × 2 block over [x0, x0 + 1]² × [z0, z0 + 0.5]; returns
    /// the node ids of its contact faces (4 per face): the bottom face of the slave block, outward normal −z, or the
    /// top face of the master block, outward normal +z.
    std::vector<IndexType> Block(IndexType first, int n, double x0, double z0, bool slave) {
        auto id = [&](int i, int j, int k) { return first + IndexType(i + (n + 1) * (j + (n + 1) * k)); };
        for (int k = 0; k <= 2; ++k)
            for (int j = 0; j <= n; ++j)
                for (int i = 0; i <= n; ++i) {
                    auto node = part->CreateNewNode(id(i, j, k), x0 + double(i) / n, x0 + double(j) / n, z0 + 0.25 * k);
                    node->AddDof(DISPLACEMENT_X, REACTION_X);
                    node->AddDof(DISPLACEMENT_Y, REACTION_Y);
                    node->AddDof(DISPLACEMENT_Z, REACTION_Z);
                    if (slave && k == 0 && !penalty) {
                        node->AddDof(VECTOR_LAGRANGE_MULTIPLIER_X);
                        node->AddDof(VECTOR_LAGRANGE_MULTIPLIER_Y);
                        node->AddDof(VECTOR_LAGRANGE_MULTIPLIER_Z);
                    }
                }
        for (int k = 0; k < 2; ++k)
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i)
                    part->CreateNewElement("SmallDisplacementElement3D8N", id(i, j, k),
                                           {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                                            id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
                                            id(i, j + 1, k + 1)},
                                           part->pGetProperties(1));
        std::vector<IndexType> faces;
        const int k = slave ? 0 : 2;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                if (slave) faces.insert(faces.end(), {id(i, j, k), id(i, j + 1, k), id(i + 1, j + 1, k), id(i + 1, j, k)});
                else faces.insert(faces.end(), {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k)});
            }
        return faces;
    }

    /// A pair of @p family 3D4N for every slave face whose square overlaps a master face's; slave nodes inactive,
    /// slipping or sticking by their id.
    void MakePairs(const std::string& family, const std::vector<IndexType>& slave_faces,
                   const std::vector<IndexType>& master_faces) {
        ModelPart& computing = part->CreateSubModelPart("ComputingContact");
        const auto& prototype = dynamic_cast<const PairedCondition&>(
            Registry<Condition>::Instance().Get(family + "MortarContactCondition3D4N"));
        auto face = [&](const std::vector<IndexType>& ids, std::size_t f) {
            Geometry::PointsArrayType points;
            for (std::size_t a = 0; a < 4; ++a) points.push_back(part->pGetNode(ids[4 * f + a]));
            return CreateGeometry("Quadrilateral3D4", points);
        };
        auto box = [&](const std::vector<IndexType>& ids, std::size_t f, int c) {
            double low = 1e9, high = -1e9;
            for (std::size_t a = 0; a < 4; ++a) {
                low = std::min(low, part->GetNode(ids[4 * f + a]).Coordinates()[c]);
                high = std::max(high, part->GetNode(ids[4 * f + a]).Coordinates()[c]);
            }
            return std::make_pair(low, high);
        };
        const Array3 normal(0.0, 0.0, -1.0);
        IndexType id = 5001;
        for (std::size_t s = 0; s < slave_faces.size() / 4; ++s) {
            auto slave = face(slave_faces, s);
            for (std::size_t m = 0; m < master_faces.size() / 4; ++m) {
                bool overlap = true;
                for (int c = 0; c < 2; ++c) {
                    const auto [ls, hs] = box(slave_faces, s, c);
                    const auto [lm, hm] = box(master_faces, m, c);
                    overlap = overlap && ls < hm - 1e-9 && lm < hs - 1e-9;
                }
                if (!overlap) continue;
                auto pair = prototype.Create(id++, slave, part->pGetProperties(1), face(master_faces, m));
                pair->SetValue(NORMAL, normal);
                part->AddCondition(pair);
                computing.AddCondition(pair);
            }
        }
        for (const IndexType node_id : slave_faces) {
            Node& node = part->GetNode(node_id);
            const int state = static_cast<int>(node_id % 3);  // 0 inactive, 1 slip, 2 stick
            node.FastGetSolutionStepValue(NORMAL) = normal;
            node.Set(SLAVE, true);
            node.Set(ACTIVE, state != 0);
            node.Set(SLIP, state == 1);
            node.SetValue(INITIAL_PENALTY, 1.0e3);
            node.SetValue(FRICTION_COEFFICIENT, 0.3);
            node.SetValue(TANGENT_XI, Array3(1.0, 0.0, 0.0));
            node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = Array3(0.02, -0.01, -0.1 - 0.01 * state);
        }
    }

    /// The step: random start displacement d(1) (0.005) and d(0) = d(1) + a random increment (0.005) + a slide of the
    /// upper block (0.01 in x); nodes at X0 + d(0). Then the pairs' Initialize / InitializeSolutionStep.
    void SetStep() {
        std::mt19937 rng(18);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        for (const auto& node : part->Nodes()) {
            const Array3 d1(0.005 * u(rng), 0.005 * u(rng), 0.005 * u(rng));
            Array3 d0 = d1 + Array3(0.005 * u(rng), 0.005 * u(rng), 0.005 * u(rng));
            if (node->Id() > 1000) d0[0] += 0.01;
            node->FastGetSolutionStepValue(DISPLACEMENT, 1) = d1;
            node->FastGetSolutionStepValue(DISPLACEMENT) = d0;
            node->Coordinates() = node->InitialCoordinates() + d0;
        }
        for (const auto& element : part->Elements()) element->Initialize(*info);
        for (const auto& condition : part->Conditions()) {
            condition->Initialize(*info);
            condition->InitializeSolutionStep(*info);
        }
    }
};

/// The assembled system of one build.
struct System {
    SparseMatrixType A;
    SystemVectorType b;
};

bool BitIdentical(const SystemVectorType& x, const SystemVectorType& y) {
    return x.size() == y.size() && std::memcmp(x.data(), y.data(), sizeof(double) * std::size_t(x.size())) == 0;
}

bool BitIdentical(const SparseMatrixType& x, const SparseMatrixType& y) {
    const auto nnz = std::size_t(x.nonZeros());
    return x.rows() == y.rows() && x.nonZeros() == y.nonZeros() &&
           std::memcmp(x.innerIndexPtr(), y.innerIndexPtr(), sizeof(int) * nnz) == 0 &&
           std::memcmp(x.valuePtr(), y.valuePtr(), sizeof(double) * nnz) == 0;
}

/// A builder set up on the blocks (with the nodal penalty coupling for the penalty family, as the contact strategy
/// installs it).
struct Assembler {
    Scheme scheme;
    std::shared_ptr<BlockBuilderAndSolver> builder = std::make_shared<BlockBuilderAndSolver>(CreateLinearSolver({}));
    System system;
    SystemVectorType dx;

    explicit Assembler(FrictionalBlocks& blocks) {
        if (blocks.penalty) builder->AddAssemblyContributor(std::make_shared<NodalPenaltyCoupling>());
        builder->SetUpDofSet(scheme, *blocks.part);
        builder->SetUpSystem(*blocks.part);
        builder->ResizeAndInitializeVectors(scheme, system.A, dx, system.b, *blocks.part);
    }
    System Build(ModelPart& part, int threads) {
        ParallelUtilities::SetNumThreads(threads);
        EXPECT_EQ(ParallelUtilities::GetNumThreads(), threads);
        builder->Build(scheme, part, system.A, system.b);
        return system;
    }
};

/// Every assembled element's and condition's local system added entry by entry in entity order (the serial loop the
/// builder ran before it was parallel), then the contributors' blocks.
System SerialReference(FrictionalBlocks& blocks, const Assembler& assembler) {
    System reference = assembler.system;
    std::fill(reference.A.valuePtr(), reference.A.valuePtr() + reference.A.nonZeros(), 0.0);
    reference.b.setZero();
    const ProcessInfo& info = *blocks.info;
    auto add = [&](auto& entity) {
        if (!IsAssembled(entity)) return;
        Matrix lhs;
        Vector rhs;
        EquationIdVectorType ids;
        entity.CalculateLocalSystem(lhs, rhs, info);
        entity.EquationIdVector(ids, info);
        for (std::size_t a = 0; a < ids.size() && rhs.size() != 0; ++a) reference.b[Eigen::Index(ids[a])] += rhs[Eigen::Index(a)];
        for (std::size_t c = 0; c < ids.size() && lhs.size() != 0; ++c)
            for (std::size_t a = 0; a < ids.size(); ++a)
                reference.A.coeffRef(Eigen::Index(ids[a]), Eigen::Index(ids[c])) += lhs(Eigen::Index(a), Eigen::Index(c));
    };
    for (const auto& element : blocks.part->Elements()) add(*element);
    for (const auto& condition : blocks.part->Conditions()) add(*condition);
    for (const auto& contributor : assembler.builder->AssemblyContributors())
        contributor->AddLHS(*blocks.part, info,
                            [&](const EquationIdVectorType& rows, const EquationIdVectorType& cols, const Matrix* block) {
                                for (std::size_t c = 0; c < cols.size(); ++c)
                                    for (std::size_t a = 0; a < rows.size(); ++a)
                                        reference.A.coeffRef(Eigen::Index(rows[a]), Eigen::Index(cols[c])) +=
                                            (*block)(Eigen::Index(a), Eigen::Index(c));
                            });
    return reference;
}

class ParallelAssembly : public ::testing::TestWithParam<std::string> {};

TEST_P(ParallelAssembly, SystemIsBitIdenticalForOneAndTwoThreadsOnAFrictional3DContactModel) {
    const ThreadCountGuard guard;
    FrictionalBlocks blocks(GetParam());
    Assembler assembler(blocks);
    const std::size_t pairs = blocks.part->GetSubModelPart("ComputingContact").NumberOfConditions();
    ASSERT_GE(pairs, 50u);
    ASSERT_EQ(blocks.part->NumberOfElements(), 122u);

    const System one = assembler.Build(*blocks.part, 1);
    ASSERT_GT(one.b.norm(), 0.0);
    // The contact rows carry the pairs' tangent: some slave node is active and the pairs are not isolated.
    double contact = 0.0;
    for (const auto& condition : blocks.part->GetSubModelPart("ComputingContact").Conditions()) {
        Matrix lhs;
        Vector rhs;
        condition->CalculateLocalSystem(lhs, rhs, *blocks.info);
        contact = std::max(contact, lhs.cwiseAbs().maxCoeff());
    }
    ASSERT_GT(contact, 0.0);
    const System reference = SerialReference(blocks, assembler);
    EXPECT_TRUE(BitIdentical(one.A, reference.A));
    EXPECT_TRUE(BitIdentical(one.b, reference.b));
    for (int repeat = 0; repeat < 3; ++repeat) {  // a race would show as a difference in some repetition
        const System two = assembler.Build(*blocks.part, 2);
        EXPECT_TRUE(BitIdentical(one.A, two.A)) << "LHS differs with 2 threads, repetition " << repeat;
        EXPECT_TRUE(BitIdentical(one.b, two.b)) << "RHS differs with 2 threads, repetition " << repeat;
    }

    // The RHS-only and LHS-only builds: the same numbers as the full build's.
    SystemVectorType rhs_one, rhs_two;
    ParallelUtilities::SetNumThreads(1);
    assembler.builder->BuildRHS(assembler.scheme, *blocks.part, rhs_one);
    ParallelUtilities::SetNumThreads(2);
    assembler.builder->BuildRHS(assembler.scheme, *blocks.part, rhs_two);
    EXPECT_TRUE(BitIdentical(rhs_one, rhs_two));
    SparseMatrixType lhs_two = one.A;
    assembler.builder->BuildLHS(assembler.scheme, *blocks.part, lhs_two);
    EXPECT_TRUE(BitIdentical(one.A, lhs_two));
}

INSTANTIATE_TEST_SUITE_P(FrictionalFamilies, ParallelAssembly, ::testing::Values("ALMFrictional", "PenaltyFrictional"),
                         [](const auto& info) { return info.param; });

/// A one-DoF element whose local system throws when it was created failing.
class FailingElement : public Element {
public:
    FailingElement(IndexType id, Geometry::Pointer geometry, bool fails) : Element(id, std::move(geometry)), mFails(fails) {}
    void CalculateLocalSystem(Matrix& rLeftHandSideMatrix, Vector& rRightHandSideVector, const ProcessInfo&) override {
        if (mFails) throw InputError("element " + std::to_string(Id()) + " failed");
        rLeftHandSideMatrix = Matrix::Identity(1, 1);
        rRightHandSideVector = Vector::Ones(1);
    }
    void EquationIdVector(EquationIdVectorType& rResult, const ProcessInfo&) const override {
        rResult = {GetGeometry()[0].GetDof(DISPLACEMENT_X).EquationId()};
    }
    void GetDofList(DofsVectorType& rElementalDofList, const ProcessInfo&) const override {
        rElementalDofList = {&GetGeometry()[0].GetDof(DISPLACEMENT_X)};
    }

private:
    bool mFails;
};

TEST(ParallelAssembly, TheFirstFailingEntityInIdOrderIsReportedWhateverTheThreadCount) {
    const ThreadCountGuard guard;
    RegisterContactApplication();
    Model model;
    ModelPart& part = model.CreateModelPart("Structure");
    part.AddNodalSolutionStepVariable(DISPLACEMENT);
    for (IndexType id = 1; id <= 5000; ++id) {
        auto node = part.CreateNewNode(id, double(id), 0.0, 0.0);
        node->AddDof(DISPLACEMENT_X);
        const bool fails = id == 3001 || id == 4500;
        part.AddElement(std::make_shared<FailingElement>(id, CreateGeometry("Point3D", {node}), fails));
    }
    Scheme scheme;
    BlockBuilderAndSolver builder(CreateLinearSolver({}));
    SparseMatrixType A;
    SystemVectorType dx, b;
    builder.SetUpDofSet(scheme, part);
    builder.SetUpSystem(part);
    builder.ResizeAndInitializeVectors(scheme, A, dx, b, part);
    for (const int threads : {1, 2}) {
        ParallelUtilities::SetNumThreads(threads);
        try {
            builder.Build(scheme, part, A, b);
            ADD_FAILURE() << "no error with " << threads << " thread(s)";
        } catch (const InputError& error) {
            EXPECT_STREQ(error.what(), "element 3001 failed") << threads << " thread(s)";
        }
    }
    EXPECT_THROW(ParallelUtilities::SetNumThreads(0), InputError);
}

}  // namespace
}  // namespace contact_app::testing
