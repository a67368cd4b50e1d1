// SPDX-License-Identifier: BSD-3-Clause
/// Shared fixtures of the mesh-tying and MPC condition tests: a model part whose historical variables and DoFs
/// can be left out one by one (Check() messages), flat non-matching pairs of every registered kind, normals.
#pragma once

#include <random>
#include <set>
#include <string>
#include <vector>

#include "../custom_utilities/mortar_test_utilities.h"
#include "contact_condition_test_utilities.h"
#include "custom_strategies/contact_master_slave_constraint.h"

namespace contact_app::testing {

/// A model part for tied / MPC pairs. Historical: DISPLACEMENT, NORMAL, WEIGHTED_GAP, WEIGHTED_SLIP, REACTION,
/// TEMPERATURE, SCALAR_LAGRANGE_MULTIPLIER, VECTOR_LAGRANGE_MULTIPLIER minus @p skip_variables; DoFs of the
/// scalar components of all of them minus @p skip_dofs (names). Buffer size 2.
class TyingPairModel {
public:
    explicit TyingPairModel(std::set<std::string> skip_variables = {}, std::set<std::string> skip_dofs = {})
        : mSkipDofs(std::move(skip_dofs)) {
        RegisterContactApplication();
        RegisterContactConditions();
        RegisterContactMasterSlaveConstraints();
        part = &model.CreateModelPart("Tying");
        part->SetBufferSize(2);
        for (const VariableData* v :
             {static_cast<const VariableData*>(&DISPLACEMENT), static_cast<const VariableData*>(&NORMAL),
              static_cast<const VariableData*>(&WEIGHTED_GAP), static_cast<const VariableData*>(&WEIGHTED_SLIP),
              static_cast<const VariableData*>(&REACTION), static_cast<const VariableData*>(&TEMPERATURE),
              static_cast<const VariableData*>(&SCALAR_LAGRANGE_MULTIPLIER),
              static_cast<const VariableData*>(&VECTOR_LAGRANGE_MULTIPLIER)})
            if (!skip_variables.count(v->Name())) part->AddNodalSolutionStepVariable(*v);
        properties = part->CreateNewProperties(1);
    }

    Node& AddNode(IndexType id, const Eigen::VectorXd& x) {
        auto node = part->CreateNewNode(id, x[0], x.size() > 1 ? x[1] : 0.0, x.size() > 2 ? x[2] : 0.0);
        for (const Variable<double>* v :
             {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z, &TEMPERATURE, &SCALAR_LAGRANGE_MULTIPLIER,
              &VECTOR_LAGRANGE_MULTIPLIER_X, &VECTOR_LAGRANGE_MULTIPLIER_Y, &VECTOR_LAGRANGE_MULTIPLIER_Z})
            if (!mSkipDofs.count(v->Name()) && node->SolutionStepsDataHas(*v)) node->AddDof(*v);
        return *node;
    }

    /// The registered pair @p name on new nodes (slave ids 1..n_s, master ids n_s+1..); the slave nodal NORMAL
    /// (historical) and the condition NORMAL are set from the slave face.
    std::shared_ptr<PairedCondition> MakePair(const std::string& name, const Eigen::MatrixXd& slave,
                                              const Eigen::MatrixXd& master, IndexType id = 1) {
        auto condition = MakeRegisteredPair(*this, name, slave, master, id);
        UpdateNormals(*condition, DecodedName(name).dim);
        return condition;
    }

    Model model;
    ModelPart* part = nullptr;
    Properties::Pointer properties;

private:
    std::set<std::string> mSkipDofs;
};

/// The five registered suffixes and their (dim, n_s, n_m).
struct PairKind {
    const char* suffix;
    int dim, num_slave, num_master;
};
inline const std::vector<PairKind>& AllPairKinds() {
    static const std::vector<PairKind> kinds = {
        {"2D2N", 2, 2, 2}, {"3D3N", 3, 3, 3}, {"3D4N", 3, 4, 4}, {"3D3N4N", 3, 3, 4}, {"3D4N3N", 3, 4, 3}};
    return kinds;
}

/// Two coplanar, non-matching faces (slave normal +y in 2D, +z in 3D; master reversed), then one random rigid
/// motion: the master is a rotated, scaled, shifted copy overlapping most of the slave.
inline void FlatNonMatchingPair(const PairKind& kind, std::mt19937& rng, Eigen::MatrixXd& slave,
                                Eigen::MatrixXd& master) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    if (kind.dim == 2) {
        slave.resize(2, 2);
        master.resize(2, 2);
        slave << 1.0 + 0.1 * u(rng), 0.0, 0.1 * u(rng), 0.0;
        const double x0 = 0.3 * u(rng), length = 1.0 + 0.3 * u(rng);
        master << x0, 0.0, x0 + length, 0.0;
        const double angle = M_PI * u(rng);
        Eigen::Matrix2d r;
        r << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
        const Eigen::RowVector2d t(u(rng), u(rng));
        slave = (slave * r.transpose()).rowwise() + t;
        master = (master * r.transpose()).rowwise() + t;
        return;
    }
    slave.resize(kind.num_slave, 3);
    master.resize(kind.num_master, 3);
    const auto s = kind.num_slave == 3 ? PerturbedUnitFace<3>(rng, 0.15) : PerturbedUnitFace<4>(rng, 0.15);
    for (int i = 0; i < kind.num_slave; ++i) slave.row(i) << s[i][0], s[i][1], 0.0;
    const auto m = kind.num_master == 3 ? PerturbedUnitFace<3>(rng, 0.15) : PerturbedUnitFace<4>(rng, 0.15);
    const double angle = 0.5 * u(rng), scale = 1.0 + 0.2 * u(rng);
    const Eigen::Vector2d offset(0.2 * u(rng), 0.2 * u(rng));
    for (int j = 0; j < kind.num_master; ++j) {
        const Eigen::Vector2d p = scale * (Eigen::Rotation2Dd(angle).toRotationMatrix() *
                                           (m[kind.num_master - 1 - j] - Eigen::Vector2d(0.4, 0.4)));
        master.row(j) << p[0] + 0.4 + offset[0], p[1] + 0.4 + offset[1], 0.0;
    }
    const Eigen::Matrix3d r = RandomRotation(rng);
    const Eigen::RowVector3d t(u(rng), u(rng), u(rng));
    slave = (slave * r.transpose()).rowwise() + t;
    master = (master * r.transpose()).rowwise() + t;
}

}  // namespace contact_app::testing
