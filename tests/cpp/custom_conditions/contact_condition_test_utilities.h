// SPDX-License-Identifier: BSD-3-Clause
/// Shared fixtures of the contact condition tests: a model part with the ALM variables and DoFs, pairs
/// built from coordinate tables, the registered names.
#pragma once

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../custom_utilities/mortar_test_utilities.h"
#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/geometries/geometry_factory.h"
#include "contact_app/kernel/model.h"
#include "contact_app/kernel/registry.h"
#include "custom_conditions/contact_condition_registration.h"
#include "custom_conditions/paired_condition.h"
#include "custom_utilities/mortar_normals.h"

namespace contact_app::testing {

inline std::vector<std::string> RegisteredContactNames() {
    std::vector<std::string> names;
    for (const auto& row : RegisteredContactConditionNames()) names.push_back(row.name);
    return names;
}

inline const ContactConditionName& DecodedName(const std::string& name) {
    for (const auto& row : RegisteredContactConditionNames())
        if (row.name == name) return row;
    throw std::runtime_error("not registered: " + name);
}

inline std::string FaceGeometryName(int dim, int num_nodes) {
    return dim == 2 ? "Line2D2" : (num_nodes == 3 ? "Triangle3D3" : "Quadrilateral3D4");
}

/// Random slave and master face coordinates of the pair kind TPair (a positive radius in axisymmetry).
template <class TPair>
void RandomCoordinates(std::mt19937& rng, bool axisym, Eigen::MatrixXd& slave, Eigen::MatrixXd& master) {
    const auto pair = MakeRandomPair<TPair>(rng, 0.3, !axisym);
    slave = pair.slave;
    master = pair.master;
    if (axisym) {  // positive radius
        slave.col(0).array() += 2.0;
        master.col(0).array() += 2.0;
    }
}

/// Random coordinates for the pair kind of the registered name @p row.
inline void RandomPairCoordinates(const ContactConditionName& row, std::mt19937& rng, Eigen::MatrixXd& s, Eigen::MatrixXd& m) {
    if (row.dim == 2)
        RandomCoordinates<MortarPairTraits<2, 2, 2>>(rng, row.axisymmetric, s, m);
    else if (row.num_slave == 3 && row.num_master == 3)
        RandomCoordinates<MortarPairTraits<3, 3, 3>>(rng, false, s, m);
    else if (row.num_slave == 4 && row.num_master == 4)
        RandomCoordinates<MortarPairTraits<3, 4, 4>>(rng, false, s, m);
    else if (row.num_slave == 3)
        RandomCoordinates<MortarPairTraits<3, 3, 4>>(rng, false, s, m);
    else
        RandomCoordinates<MortarPairTraits<3, 4, 3>>(rng, false, s, m);
}

/// max over rows of ‖LHS_i − FD_i‖ / max(‖LHS_i‖, 1e−3·max_k ‖LHS_k‖): every row is measured against its own
/// size (no entry dominates); rows that vanish analytically (D is diagonal with dual multipliers) are compared
/// at 1e−3 of the largest row, above the FD round-off.
inline double RowwiseRelativeError(const Matrix& lhs, const Matrix& fd) {
    double worst = 0.0;
    const double floor = 1e-3 * lhs.rowwise().norm().maxCoeff();
    for (Eigen::Index i = 0; i < lhs.rows(); ++i)
        worst = std::max(worst, (lhs.row(i) - fd.row(i)).norm() / std::max(lhs.row(i).norm(), floor));
    return worst;
}

/// Nodal (rows) and centre unit normals of the slave face from its current coordinates.
inline void FaceNormals(const Geometry& face, int dim, Eigen::MatrixXd& nodal, Eigen::VectorXd& center) {
    const int n = static_cast<int>(face.size());
    Eigen::MatrixXd x(n, dim);
    for (int i = 0; i < n; ++i) x.row(i) = face[i].Coordinates().head(dim).transpose();
    if (dim == 2) {
        const NodeCoordinates<double, 2, 2> c = x;
        nodal = FaceNodalUnitNormals<2, 2, double>(c);
        center = FaceCenterUnitNormal<2, 2, double>(c);
    } else if (n == 3) {
        const NodeCoordinates<double, 3, 3> c = x;
        nodal = FaceNodalUnitNormals<3, 3, double>(c);
        center = FaceCenterUnitNormal<3, 3, double>(c);
    } else {
        const NodeCoordinates<double, 3, 4> c = x;
        nodal = FaceNodalUnitNormals<3, 4, double>(c);
        center = FaceCenterUnitNormal<3, 4, double>(c);
    }
}

/// Sets the slave nodal NORMAL (historical) and the pair NORMAL as the search/criteria would for one face.
inline void UpdateNormals(PairedCondition& pair, int dim) {
    Eigen::MatrixXd nodal;
    Eigen::VectorXd center;
    FaceNormals(pair.GetParentGeometry(), dim, nodal, center);
    auto& slave = const_cast<Geometry&>(pair.GetParentGeometry());
    for (std::size_t i = 0; i < slave.size(); ++i) {
        Array3 n = Array3::Zero();
        n.head(dim) = nodal.row(i).transpose();
        slave[i].FastGetSolutionStepValue(NORMAL) = n;
    }
    Array3 c = Array3::Zero();
    c.head(dim) = center;
    pair.SetValue(NORMAL, c);
}

/// A model part with the historical variables and DoFs of the ALM frictionless (scalar and vector multiplier) solvers.
class ContactPairModel {
public:
    ContactPairModel() {
        RegisterContactApplication();
        RegisterContactConditions();
        part = &model.CreateModelPart("Contact");
        for (const VariableData* v : {static_cast<const VariableData*>(&DISPLACEMENT),
                                      static_cast<const VariableData*>(&NORMAL),
                                      static_cast<const VariableData*>(&WEIGHTED_GAP),
                                      static_cast<const VariableData*>(&LAGRANGE_MULTIPLIER_CONTACT_PRESSURE),
                                      static_cast<const VariableData*>(&VECTOR_LAGRANGE_MULTIPLIER)})
            part->AddNodalSolutionStepVariable(*v);
        properties = part->CreateNewProperties(1);
    }

    Node& AddNode(IndexType id, const Eigen::VectorXd& x) {
        auto node = part->CreateNewNode(id, x[0], x[1], x.size() > 2 ? x[2] : 0.0);
        node->AddDof(DISPLACEMENT_X);
        node->AddDof(DISPLACEMENT_Y);
        node->AddDof(DISPLACEMENT_Z);
        node->AddDof(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE);
        node->AddDof(VECTOR_LAGRANGE_MULTIPLIER_X);
        node->AddDof(VECTOR_LAGRANGE_MULTIPLIER_Y);
        node->AddDof(VECTOR_LAGRANGE_MULTIPLIER_Z);
        return *node;
    }

    /// The pair condition @p name on new nodes: slave rows of @p slave (ids 1..n_s), master rows of @p master
    /// (ids n_s+1..); historical NORMAL of the slave nodes and condition NORMAL from the slave face.
    std::shared_ptr<PairedCondition> MakePair(const std::string& name, const Eigen::MatrixXd& slave,
                                              const Eigen::MatrixXd& master, IndexType id = 1) {
        const auto& row = DecodedName(name);
        Geometry::PointsArrayType s, m;
        for (int i = 0; i < slave.rows(); ++i) {
            AddNode(i + 1, slave.row(i).transpose());
            s.push_back(part->pGetNode(i + 1));
        }
        for (int i = 0; i < master.rows(); ++i) {
            AddNode(slave.rows() + i + 1, master.row(i).transpose());
            m.push_back(part->pGetNode(slave.rows() + i + 1));
        }
        const auto& prototype = dynamic_cast<const PairedCondition&>(Registry<Condition>::Instance().Get(name));
        auto condition = std::dynamic_pointer_cast<PairedCondition>(
            prototype.Create(id, CreateGeometry(FaceGeometryName(row.dim, row.num_slave), s), properties,
                             CreateGeometry(FaceGeometryName(row.dim, row.num_master), m)));
        return condition;
    }

    Model model;
    ModelPart* part = nullptr;
    Properties::Pointer properties;
};

}  // namespace contact_app::testing
