// SPDX-License-Identifier: BSD-3-Clause
/// Restart of the frictional conditions: Save after a sliding step, Load into a fresh condition created by the
/// prototype on the same faces, identical local system and WEIGHTED_SLIP; mismatched buffers are InputErrors.
#include <random>

#include "contact_app/kernel/serializer.h"
#include "contact_condition_test_utilities.h"

namespace contact_app::testing {
namespace {

/// A pair after InitializeSolutionStep in a step where the master slid along the slave, every slave node stick
/// (the slip measure, hence the start-of-step operators, enter the residual).
struct SlidingStep {
    ContactPairModel model;
    std::shared_ptr<PairedCondition> pair;
    ProcessInfo info;

    explicit SlidingStep(const std::string& name) {
        const auto& row = DecodedName(name);
        model.part->AddNodalSolutionStepVariable(WEIGHTED_SLIP);
        model.part->SetBufferSize(2);
        Eigen::MatrixXd s(row.num_slave, row.dim), m(row.num_master, row.dim);
        if (row.dim == 2) {
            s << 3.0, 0.0, 2.0, 0.0;
            m << 2.2, -0.01, 3.1, -0.012;
        } else if (row.num_slave == 3) {
            s << 0, 0, 0, 1, 0, 0, 0, 1, 0;
        } else {
            s << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
        }
        if (row.dim == 3 && row.num_master == 3) m << 0.1, 0.05, -0.01, 0.1, 1.0, -0.012, 1.1, 0.0, -0.01;
        if (row.dim == 3 && row.num_master == 4)
            m << 0.1, 0.05, -0.01, 0.05, 1.0, -0.012, 1.0, 1.1, -0.01, 1.1, 0.0, -0.01;
        pair = model.MakePair(name, s, m);
        model.properties->SetValue(THICKNESS, 1.0);
        const Array3 slide =
            0.07 *
            (pair->GetParentGeometry()[1].Coordinates() - pair->GetParentGeometry()[0].Coordinates()).normalized();
        auto& slave = const_cast<Geometry&>(pair->GetParentGeometry());
        auto& master = const_cast<Geometry&>(pair->GetPairedGeometry());
        for (std::size_t l = 0; l < master.size(); ++l) {
            master[l].FastGetSolutionStepValue(DISPLACEMENT) = slide;
            master[l].Coordinates() += slide;
        }
        const Array3 n = row.dim == 2 ? Array3(0.0, 1.0, 0.0) : Array3(0.0, 0.0, 1.0);
        for (std::size_t j = 0; j < slave.size(); ++j) {
            slave[j].FastGetSolutionStepValue(NORMAL) = n;
            slave[j].Set(ACTIVE, true);
            slave[j].Set(SLIP, false);
            slave[j].SetValue(INITIAL_PENALTY, 20.0);
            slave[j].SetValue(FRICTION_COEFFICIENT, 0.3);
            slave[j].FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = -0.2 * n;
        }
        pair->SetValue(NORMAL, n);
        info.SetValue(SCALE_FACTOR, 1.0);
        info.SetValue(TANGENT_FACTOR, 0.5);
        info.SetValue(OPERATOR_THRESHOLD, 0.0);  // objective: the slip uses D_old, M_old
        pair->Initialize(info);
        pair->InitializeSolutionStep(info);
    }

    Matrix WeightedSlip(PairedCondition& condition) {
        auto& slave = const_cast<Geometry&>(pair->GetParentGeometry());
        for (std::size_t j = 0; j < slave.size(); ++j) {
            slave[j].FastGetSolutionStepValue(WEIGHTED_SLIP) = Array3::Zero();
            slave[j].FastGetSolutionStepValue(WEIGHTED_GAP) = 0.0;
        }
        condition.AddExplicitContribution(info);
        Matrix slip(slave.size(), 3);
        for (std::size_t j = 0; j < slave.size(); ++j)
            slip.row(j) = slave[j].FastGetSolutionStepValue(WEIGHTED_SLIP).transpose();
        return slip;
    }
};

class ConditionSerializationNames : public ::testing::TestWithParam<std::string> {};

TEST_P(ConditionSerializationNames, LoadedConditionReproducesTheLocalSystemAndTheSlip) {
    SlidingStep step(GetParam());
    Matrix lhs;
    Vector rhs;
    step.pair->CalculateLocalSystem(lhs, rhs, step.info);
    ASSERT_FALSE(step.pair->Is(MODIFIED));  // objective branch taken
    const Matrix slip = step.WeightedSlip(*step.pair);
    ASSERT_GT(slip.norm(), 0.0);
    Serializer out;
    step.pair->Save(out);

    const auto& prototype = dynamic_cast<const PairedCondition&>(Registry<Condition>::Instance().Get(GetParam()));
    auto fresh = std::dynamic_pointer_cast<PairedCondition>(
        prototype.Create(7, step.pair->pGetParentGeometry(), step.model.properties, step.pair->pGetPairedGeometry()));
    fresh->SetValue(NORMAL, step.pair->GetValue(NORMAL));  // the slave normal is set by the search, not restarted
    Matrix fresh_lhs;
    Vector fresh_rhs;
    fresh->CalculateLocalSystem(fresh_lhs, fresh_rhs, step.info);  // no start-of-step operators: another slip
    EXPECT_GT((fresh_rhs - rhs).norm(), 1e-8 * rhs.norm());

    Serializer in(out.Data());
    fresh->Load(in);
    EXPECT_TRUE(in.AtEnd());
    EXPECT_EQ(fresh->Id(), step.pair->Id());
    EXPECT_EQ(fresh->GetPairedNormal(), step.pair->GetPairedNormal());
    fresh->CalculateLocalSystem(fresh_lhs, fresh_rhs, step.info);
    EXPECT_EQ((fresh_rhs - rhs).norm(), 0.0);
    EXPECT_EQ((fresh_lhs - lhs).norm(), 0.0);
    EXPECT_EQ((step.WeightedSlip(*fresh) - slip).norm(), 0.0);
}

TEST_P(ConditionSerializationNames, MismatchedOrCorruptedBuffersAreInputErrors) {
    SlidingStep step(GetParam());
    Serializer out;
    step.pair->Save(out);
    auto message_of_load = [&](PairedCondition& target, const std::string& data) -> std::string {
        Serializer in(data);
        try {
            target.Load(in);
        } catch (const InputError& e) {
            return e.what();
        }
        return "no InputError";
    };
    // Truncated buffer.
    std::string message = message_of_load(*step.pair, out.Data().substr(0, out.Data().size() / 2));
    EXPECT_NE(message.find("Serializer:"), std::string::npos) << message;
    // A corrupted tag names both tags.
    std::string corrupted = out.Data();
    corrupted[corrupted.find("PairedNormal") + 11] = 'X';
    message = message_of_load(*step.pair, corrupted);
    EXPECT_NE(message.find("expected entry 'PairedNormal' but found 'PairedNormaX'"), std::string::npos) << message;
    // The buffer of a frictionless condition lacks the frictional state.
    const auto& row = DecodedName(GetParam());
    std::string frictionless = GetParam();
    frictionless.replace(frictionless.find("Frictional"), 10, "Frictionless");
    ContactPairModel other;
    Eigen::MatrixXd s = Eigen::MatrixXd::Zero(row.num_slave, row.dim),
                    m = Eigen::MatrixXd::Zero(row.num_master, row.dim);
    for (int i = 0; i < row.num_slave; ++i) s(i, i % row.dim) = 1.0;
    for (int i = 0; i < row.num_master; ++i) m(i, i % row.dim) = 1.0;
    auto plain = other.MakePair(frictionless, s, m);
    Serializer plain_out;
    plain->Save(plain_out);
    message = message_of_load(*step.pair, plain_out.Data());
    EXPECT_NE(message.find("truncated"), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(Registered, ConditionSerializationNames, ::testing::ValuesIn(FrictionalNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace contact_app::testing
