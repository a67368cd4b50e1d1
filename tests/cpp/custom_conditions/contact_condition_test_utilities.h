// SPDX-License-Identifier: BSD-3-Clause
/// Shared fixtures of the contact condition tests: a model part with the ALM variables and DoFs, pairs
/// built from coordinate tables, the registered names.
#pragma once

#include <algorithm>
#include <array>
#include <map>
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
#include "custom_conditions/mortar_contact_condition.h"
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

/// @p f applied to the mortar base of whichever registered contact instantiation @p c is (−1 for another condition).
template <class TFunction>
int WithMortarBase(const Condition* c, TFunction&& f) {
#define CONTACT_APP_TRY(D, NS, NM, F)                                                                 \
    if (auto p = dynamic_cast<const MortarContactCondition<D, NS, FrictionalCase::F, false, NM>*>(c)) \
        return f(*p);                                                                                 \
    if (auto p = dynamic_cast<const MortarContactCondition<D, NS, FrictionalCase::F, true, NM>*>(c))  \
        return f(*p);
#define CONTACT_APP_TRY_PAIRS(F) \
    CONTACT_APP_TRY(2, 2, 2, F)  \
    CONTACT_APP_TRY(3, 3, 3, F)  \
    CONTACT_APP_TRY(3, 4, 4, F)  \
    CONTACT_APP_TRY(3, 3, 4, F)  \
    CONTACT_APP_TRY(3, 4, 3, F)
    CONTACT_APP_TRY_PAIRS(FRICTIONLESS)
    CONTACT_APP_TRY_PAIRS(FRICTIONLESS_COMPONENTS)
    CONTACT_APP_TRY_PAIRS(FRICTIONLESS_PENALTY)
    CONTACT_APP_TRY_PAIRS(FRICTIONAL)
    CONTACT_APP_TRY_PAIRS(FRICTIONAL_PENALTY)
#undef CONTACT_APP_TRY_PAIRS
#undef CONTACT_APP_TRY
    return -1;
}

/// GetActiveInactiveValue (Σ 2^i over the ACTIVE slave nodes) of a registered contact pair.
inline int ActiveInactiveValue(const Condition* c) {
    return WithMortarBase(c, [](const auto& p) { return p.GetActiveInactiveValue(); });
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

/// The registered names of the two Coulomb families (ALM frictional, penalty frictional).
inline std::vector<std::string> FrictionalNames() {
    std::vector<std::string> names;
    for (const auto& row : RegisteredContactConditionNames())
        if (row.family == "ALMFrictional" || row.family == "PenaltyFrictional") names.push_back(row.name);
    return names;
}

/// Whether the registered condition @p row is of a penalty family (displacement DoFs only).
inline bool IsPenalty(const ContactConditionName& row) { return row.family.rfind("Penalty", 0) == 0; }

/// Local unknown of a pair: (node, variable) in the order [master u, slave u, λ].
struct LocalDof {
    Node* node;
    int component;  ///< 0..2 displacement, −1 scalar multiplier, kVectorMultiplier + c vector multiplier
};
constexpr int kVectorMultiplier = 10;

/// DISPLACEMENT_c, LAGRANGE_MULTIPLIER_CONTACT_PRESSURE or VECTOR_LAGRANGE_MULTIPLIER_c of @p dof.
inline const Variable<double>& DofVariable(const LocalDof& dof) {
    static const std::array<const Variable<double>*, 3> u = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
    static const std::array<const Variable<double>*, 3> l = {&VECTOR_LAGRANGE_MULTIPLIER_X,
                                                             &VECTOR_LAGRANGE_MULTIPLIER_Y,
                                                             &VECTOR_LAGRANGE_MULTIPLIER_Z};
    if (dof.component < 0) return LAGRANGE_MULTIPLIER_CONTACT_PRESSURE;
    return dof.component >= kVectorMultiplier ? *l[dof.component - kVectorMultiplier] : *u[dof.component];
}

/// The local unknowns of @p pair as the spec orders them: master u, slave u, then no λ (penalty), one scalar λ per
/// slave node (ALM frictionless) or d components of VECTOR_LAGRANGE_MULTIPLIER per slave node (ALM frictionless
/// components, ALM frictional).
inline std::vector<LocalDof> LocalDofs(PairedCondition& pair, const ContactConditionName& row) {
    const int dim = row.dim;
    std::vector<LocalDof> dofs;
    auto& master = const_cast<Geometry&>(pair.GetPairedGeometry());
    auto& slave = const_cast<Geometry&>(pair.GetParentGeometry());
    for (std::size_t l = 0; l < master.size(); ++l)
        for (int c = 0; c < dim; ++c) dofs.push_back({&master[l], c});
    for (std::size_t j = 0; j < slave.size(); ++j)
        for (int c = 0; c < dim; ++c) dofs.push_back({&slave[j], c});
    if (row.family == "ALMFrictionlessComponents" || row.family == "ALMFrictional")
        for (std::size_t j = 0; j < slave.size(); ++j)
            for (int c = 0; c < dim; ++c) dofs.push_back({&slave[j], kVectorMultiplier + c});
    else if (!IsPenalty(row))
        for (std::size_t j = 0; j < slave.size(); ++j) dofs.push_back({&slave[j], -1});
    return dofs;
}

/// Moves a displacement DoF (current coordinates and DISPLACEMENT(0), not the start-of-step d(1)) or a multiplier
/// by @p h.
inline void Perturb(const LocalDof& dof, double h) {
    if (dof.component < 0) {
        dof.node->FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) += h;
    } else if (dof.component >= kVectorMultiplier) {
        dof.node->FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER)[dof.component - kVectorMultiplier] += h;
    } else {
        dof.node->Coordinates()[dof.component] += h;
        dof.node->FastGetSolutionStepValue(DISPLACEMENT)[dof.component] += h;
    }
}

/// Checks what docs/registered_conditions.md §2 says of the registered pair @p name: its MatrixSize, the sizes of
/// the local system of @p pair, and its DoF list and equation ids in the order of LocalDofs.
inline void ExpectSpecLocalSystem(PairedCondition& pair, const std::string& name, const ProcessInfo& info) {
    static const std::map<std::string, std::map<std::string, int>> spec_sizes = {
        {"ALMFrictionless", {{"2D2N", 10}, {"3D3N", 21}, {"3D4N", 28}, {"3D3N4N", 24}, {"3D4N3N", 25}}},
        {"ALMFrictionlessComponents", {{"2D2N", 12}, {"3D3N", 27}, {"3D4N", 36}, {"3D3N4N", 30}, {"3D4N3N", 33}}},
        {"ALMFrictional", {{"2D2N", 12}, {"3D3N", 27}, {"3D4N", 36}, {"3D3N4N", 30}, {"3D4N3N", 33}}},
        {"PenaltyFrictionless", {{"2D2N", 8}, {"3D3N", 18}, {"3D4N", 24}, {"3D3N4N", 21}, {"3D4N3N", 21}}},
        {"PenaltyFrictional", {{"2D2N", 8}, {"3D3N", 18}, {"3D4N", 24}, {"3D3N4N", 21}, {"3D4N3N", 21}}}};
    const auto& row = DecodedName(name);
    const std::string suffix = name.substr(name.find("Condition") + 9);
    EXPECT_EQ(row.matrix_size, spec_sizes.at(row.family).at(suffix));
    Matrix lhs;
    Vector rhs;
    pair.CalculateLocalSystem(lhs, rhs, info);
    EXPECT_EQ(lhs.rows(), row.matrix_size);
    EXPECT_EQ(lhs.cols(), row.matrix_size);
    EXPECT_EQ(rhs.size(), row.matrix_size);
    DofsVectorType dofs;
    EquationIdVectorType ids;
    pair.GetDofList(dofs, info);
    pair.EquationIdVector(ids, info);
    ASSERT_EQ(static_cast<int>(dofs.size()), row.matrix_size);
    ASSERT_EQ(static_cast<int>(ids.size()), row.matrix_size);
    const auto expected = LocalDofs(pair, row);
    for (int q = 0; q < row.matrix_size; ++q) {
        EXPECT_EQ(dofs[q]->Id(), expected[q].node->Id()) << q;
        EXPECT_EQ(&dofs[q]->GetVariable(), static_cast<const VariableData*>(&DofVariable(expected[q]))) << q;
    }
}

/// A flat slave face (normal +y in 2D, length 1; +z in 3D, the unit square or its half) and the master face matching
/// it node for node at the distance @p g along the normal.
inline void FlatMatchingPair(const ContactConditionName& row, double g, Eigen::MatrixXd& s, Eigen::MatrixXd& m) {
    s.resize(row.num_slave, row.dim);
    m.resize(row.num_master, row.dim);
    if (row.dim == 2) {
        s << 3.0, 0.0, 2.0, 0.0;
        m << 2.0, g, 3.0, g;
    } else if (row.num_slave == 3) {
        s << 0, 0, 0, 1, 0, 0, 0, 1, 0;
        m << 0, 0, g, 0, 1, g, 1, 0, g;
    } else {
        s << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
        m << 0, 0, g, 0, 1, g, 1, 1, g, 1, 0, g;
    }
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

/// Sets the slave nodal NORMAL (historical, where the node has it) and the pair NORMAL as the search/criteria would
/// for one face from its current coordinates.
inline void UpdateNormals(PairedCondition& pair, int dim) {
    Eigen::MatrixXd nodal;
    Eigen::VectorXd center;
    FaceNormals(pair.GetParentGeometry(), dim, nodal, center);
    auto& slave = const_cast<Geometry&>(pair.GetParentGeometry());
    for (std::size_t i = 0; i < slave.size(); ++i) {
        if (!slave[i].SolutionStepsDataHas(NORMAL)) continue;  // a tying model may leave NORMAL out
        Array3 n = Array3::Zero();
        n.head(dim) = nodal.row(i).transpose();
        slave[i].FastGetSolutionStepValue(NORMAL) = n;
    }
    Array3 c = Array3::Zero();
    c.head(dim) = center;
    pair.SetValue(NORMAL, c);
}

/// The registered pair condition @p name on new nodes of @p model, added by its AddNode (the DoFs are the
/// model's): slave rows of @p slave (ids 1..n_s), master rows of @p master (ids n_s+1..).
template <class TModel>
std::shared_ptr<PairedCondition> MakeRegisteredPair(TModel& model, const std::string& name,
                                                    const Eigen::MatrixXd& slave, const Eigen::MatrixXd& master,
                                                    IndexType id) {
    const auto& row = DecodedName(name);
    Geometry::PointsArrayType s, m;
    for (int i = 0; i < slave.rows(); ++i) {
        model.AddNode(i + 1, slave.row(i).transpose());
        s.push_back(model.part->pGetNode(i + 1));
    }
    for (int i = 0; i < master.rows(); ++i) {
        model.AddNode(slave.rows() + i + 1, master.row(i).transpose());
        m.push_back(model.part->pGetNode(slave.rows() + i + 1));
    }
    const auto& prototype = dynamic_cast<const PairedCondition&>(Registry<Condition>::Instance().Get(name));
    return std::dynamic_pointer_cast<PairedCondition>(
        prototype.Create(id, CreateGeometry(FaceGeometryName(row.dim, row.num_slave), s), model.properties,
                         CreateGeometry(FaceGeometryName(row.dim, row.num_master), m)));
}

/// Expects what PairedCondition answers for every pair kind: no mass, no damping (empty matrices) and a zero
/// WEIGHTED_GAP at each integration point. Returns the number of integration points.
inline std::size_t ExpectNoMassNoDampingZeroGap(PairedCondition& pair, const ProcessInfo& info) {
    Matrix mass, damping;
    pair.CalculateMassMatrix(mass, info);
    pair.CalculateDampingMatrix(damping, info);
    EXPECT_EQ(mass.size(), 0);
    EXPECT_EQ(damping.size(), 0);
    std::vector<double> gap;
    pair.CalculateOnIntegrationPoints(WEIGHTED_GAP, gap, info);
    EXPECT_FALSE(gap.empty());
    for (double v : gap) EXPECT_EQ(v, 0.0);
    return gap.size();
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

    /// The pair condition @p name on new nodes (MakeRegisteredPair); the normals are left to UpdateNormals.
    std::shared_ptr<PairedCondition> MakePair(const std::string& name, const Eigen::MatrixXd& slave,
                                              const Eigen::MatrixXd& master, IndexType id = 1) {
        return MakeRegisteredPair(*this, name, slave, master, id);
    }

    /// MakePair, with THICKNESS @p thickness on the properties and the normals of the slave face (UpdateNormals).
    std::shared_ptr<PairedCondition> MakeNormalPair(const std::string& name, const Eigen::MatrixXd& slave,
                                                    const Eigen::MatrixXd& master, double thickness) {
        auto pair = MakePair(name, slave, master);
        properties->SetValue(THICKNESS, thickness);
        UpdateNormals(*pair, DecodedName(name).dim);
        return pair;
    }

    Model model;
    ModelPart* part = nullptr;
    Properties::Pointer properties;
};

}  // namespace contact_app::testing
