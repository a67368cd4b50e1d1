// SPDX-License-Identifier: BSD-3-Clause
// The contact condition table: method × NV × family × axisym × pair → Kratos name → prototype.
#include "custom_conditions/contact_condition_registration.h"

#include <memory>
#include <string>
#include <tuple>
#include <utility>

#include "contact_app/kernel/geometries/geometry_factory.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/registry.h"
#include "contact_app/kernel/variables.h"
#include "custom_conditions/mesh_tying_mortar_condition.h"
#include "custom_conditions/mortar_contact_axisym_condition.h"
#include "custom_conditions/mortar_contact_family_condition.h"
#include "custom_conditions/mpc_mortar_contact_condition.h"

namespace contact_app {
namespace {

struct PairRow {
    int dim, num_slave, num_master;
};

#define CONTACT_APP_PAIR_ROW_(A, D, NS, NM) PairRow{D, NS, NM},
constexpr PairRow kPairs[] = {CONTACT_APP_FOR_EACH_MORTAR_PAIR(CONTACT_APP_PAIR_ROW_, ~)};
#undef CONTACT_APP_PAIR_ROW_

/// The Kratos pair suffix: "<d>D<n_s>N", plus "<n_m>N" when the master face differs (3D3N4N).
std::string PairSuffix(const PairRow& pair) {
    std::string suffix = std::to_string(pair.dim) + "D" + std::to_string(pair.num_slave) + "N";
    if (pair.num_master != pair.num_slave) suffix += std::to_string(pair.num_master) + "N";
    return suffix;
}

using Factory = std::shared_ptr<const Condition> (*)(const PairRow&, bool nv, bool axisym, Geometry::Pointer slave,
                                                      Geometry::Pointer master);

struct FamilyRow {
    const char* method;  ///< "ALM" or "Penalty" ("" for the non-contact families MeshTying and MPC)
    const char* family;  ///< "Frictionless", "FrictionlessComponents", "Frictional", "MeshTying", "MPC"
    FrictionalCase frictional_case;  ///< non-contact families: the case with the same local size (matrix_size)
    bool has_axisym;
    Factory factory;
    bool has_nv = true;                           ///< mesh tying and MPC have no NV variant
    const char* stem = "MortarContactCondition";  ///< "MortarCondition" for mesh tying
};

/// make(TPair{}) for the registered pair TPair (RegisteredMortarPairs) that matches @p pair.
/// @throws InternalError for a pair outside the list
template <class TMake, class... TPairs>
std::shared_ptr<const Condition> ForPair(const PairRow& pair, const TMake& make, std::tuple<TPairs...>* = nullptr) {
    if constexpr (sizeof...(TPairs) == 0) {
        return ForPair(pair, make, static_cast<RegisteredMortarPairs*>(nullptr));
    } else {
        std::shared_ptr<const Condition> prototype;
        ((pair.dim == TPairs::Dim && pair.num_slave == TPairs::NumSlave && pair.num_master == TPairs::NumMaster &&
          (prototype = make(TPairs{}), true)) ||
         ...);
        CONTACT_CHECK(prototype != nullptr, InternalError, "contact condition table: unknown pair ", PairSuffix(pair));
        return prototype;
    }
}

/// The plane prototypes of the contact family of friction policy TCase (every pair × NV).
/// @throws InternalError for an axisymmetric row
template <FrictionalCase TCase>
std::shared_ptr<const Condition> MakePlaneFamily(const PairRow& pair, bool nv, bool axisym, Geometry::Pointer s,
                                                 Geometry::Pointer m) {
    CONTACT_CHECK(!axisym, InternalError, "contact condition table: the family has no axisymmetric variant");
    return ForPair(pair, [&](auto pair_traits) -> std::shared_ptr<const Condition> {
        using P = decltype(pair_traits);
        if (nv)
            return std::make_shared<const MortarContactFamilyCondition<P::Dim, P::NumSlave, TCase, true, P::NumMaster>>(
                0, s, nullptr, m);
        return std::make_shared<const MortarContactFamilyCondition<P::Dim, P::NumSlave, TCase, false, P::NumMaster>>(
            0, s, nullptr, m);
    });
}

/// The prototypes of a family without NV / axisymmetric variants (mesh tying, MPC).
template <template <int, int, int> class TFamily>
std::shared_ptr<const Condition> MakePairFamily(const PairRow& pair, bool nv, bool axisym, Geometry::Pointer s,
                                                Geometry::Pointer m) {
    CONTACT_CHECK(!nv && !axisym, InternalError, "condition table: the family has no NV / axisymmetric variant");
    return ForPair(pair, [&](auto pair_traits) -> std::shared_ptr<const Condition> {
        using P = decltype(pair_traits);
        return std::make_shared<const TFamily<P::Dim, P::NumSlave, P::NumMaster>>(0, s, nullptr, m);
    });
}

/// The plane prototypes plus the 2D axisymmetric variant (MortarContactAxisymCondition of the 2D2N pair).
template <FrictionalCase TCase>
std::shared_ptr<const Condition> MakeFamily(const PairRow& pair, bool nv, bool axisym, Geometry::Pointer s,
                                            Geometry::Pointer m) {
    using Axisym = MortarContactAxisymCondition<MortarContactFamilyCondition<2, 2, TCase, false, 2>>;
    using AxisymNV = MortarContactAxisymCondition<MortarContactFamilyCondition<2, 2, TCase, true, 2>>;
    if (axisym) {
        if (nv) return std::make_shared<const AxisymNV>(0, s, nullptr, m);
        return std::make_shared<const Axisym>(0, s, nullptr, m);
    }
    return MakePlaneFamily<TCase>(pair, nv, false, std::move(s), std::move(m));
}

/// The families, the one place to add one: the Kratos class of a row is MortarContactFamilyCondition with its policy
/// (AugmentedLagrangianMethodFrictionlessMortarContactCondition is FRICTIONLESS, ...), whose .cpp
/// (alm_frictionless_mortar_contact_condition.cpp, ...) defines its AddFamilyResidual and ends with
/// CONTACT_APP_INSTANTIATE_CONTACT_FAMILY.
const FamilyRow kFamilies[] = {
    {"ALM", "Frictionless", FrictionalCase::FRICTIONLESS, true, MakeFamily<FrictionalCase::FRICTIONLESS>},
    {"ALM", "FrictionlessComponents", FrictionalCase::FRICTIONLESS_COMPONENTS, false,
     MakePlaneFamily<FrictionalCase::FRICTIONLESS_COMPONENTS>},
    {"ALM", "Frictional", FrictionalCase::FRICTIONAL, true, MakeFamily<FrictionalCase::FRICTIONAL>},
    {"Penalty", "Frictionless", FrictionalCase::FRICTIONLESS_PENALTY, true,
     MakeFamily<FrictionalCase::FRICTIONLESS_PENALTY>},
    {"Penalty", "Frictional", FrictionalCase::FRICTIONAL_PENALTY, true, MakeFamily<FrictionalCase::FRICTIONAL_PENALTY>},
    // Non-contact families: MeshTyingMortarCondition<pair> (size of the DISPLACEMENT tying, d(2n_s + n_m)) and
    // MPCMortarContactCondition<pair> (d(n_s + n_m)).
    {"", "MeshTying", FrictionalCase::FRICTIONLESS_COMPONENTS, false, MakePairFamily<MeshTyingMortarCondition>, false,
     "MortarCondition"},
    {"", "MPC", FrictionalCase::FRICTIONLESS_PENALTY, false, MakePairFamily<MPCMortarContactCondition>, false},
};

Geometry::Pointer PrototypeFace(int dim, int num_nodes) {
    Geometry::PointsArrayType points;
    for (int i = 0; i < num_nodes; ++i) points.push_back(std::make_shared<Node>(i + 1, 0.0, 0.0, 0.0));
    const char* name = dim == 2 ? "Line2D2" : (num_nodes == 3 ? "Triangle3D3" : "Quadrilateral3D4");
    return CreateGeometry(name, points);
}

/// Calls @p visit(row, family, pair) for every name of the table (family × NV × axisym × pair).
template <class TVisit>
void ForEachName(TVisit&& visit) {
    for (const FamilyRow& family : kFamilies) {
        for (const bool nv : {false, true})
            for (const bool axisym : {false, true})
                for (const PairRow& pair : kPairs) {
                    if ((axisym && (!family.has_axisym || pair.dim != 2)) || (nv && !family.has_nv)) continue;
                    ContactConditionName row;
                    row.name = std::string(family.method) + (nv ? "NV" : "") + family.family +
                               (axisym ? "Axisym" : "") + family.stem + PairSuffix(pair);
                    row.family = std::string(family.method) + family.family;
                    row.normal_variation = nv;
                    row.axisymmetric = axisym;
                    row.dim = pair.dim;
                    row.num_slave = pair.num_slave;
                    row.num_master = pair.num_master;
                    row.matrix_size = MortarMatrixSize(pair.dim, pair.num_slave, family.frictional_case, pair.num_master);
                    visit(row, family, pair);
                }
    }
}

/// A solver mortar_type: the condition family it runs (a kFamilies row) and what it adds.
struct MortarTypeRow {
    const char* name;
    const char* method;
    const char* family;
    const char* contact_type;
    bool pure_slip;
    MortarCriterionFamily criterion;
};

const MortarTypeRow kMortarTypes[] = {
    {"ALMContactFrictionless", "ALM", "Frictionless", "Frictionless", false, MortarCriterionFamily::ALM_FRICTIONLESS},
    {"ALMContactFrictionlessComponents", "ALM", "FrictionlessComponents", "FrictionlessComponents", false,
     MortarCriterionFamily::ALM_FRICTIONLESS_COMPONENTS},
    {"ALMContactFrictional", "ALM", "Frictional", "Frictional", false, MortarCriterionFamily::ALM_FRICTIONAL},
    {"ALMContactFrictionalPureSlip", "ALM", "Frictional", "FrictionalPureSlip", true,
     MortarCriterionFamily::ALM_FRICTIONAL},
    {"PenaltyContactFrictionless", "Penalty", "Frictionless", "Frictionless", false,
     MortarCriterionFamily::PENALTY_FRICTIONLESS},
    {"PenaltyContactFrictional", "Penalty", "Frictional", "Frictional", false, MortarCriterionFamily::PENALTY_FRICTIONAL},
    {"PenaltyContactFrictionalPureSlip", "Penalty", "Frictional", "FrictionalPureSlip", true,
     MortarCriterionFamily::PENALTY_FRICTIONAL},
    {"ScalarMeshTying", "", "MeshTying", "", false, MortarCriterionFamily::MESH_TYING},
    {"ComponentsMeshTying", "", "MeshTying", "", false, MortarCriterionFamily::MESH_TYING},
};

const FamilyRow& FindFamily(const std::string& method, const std::string& family) {
    for (const FamilyRow& row : kFamilies)
        if (method == row.method && family == row.family) return row;
    CONTACT_THROW(InternalError, "contact condition table: no family ", method, family);
}

/// The variables and DoFs of a mortar type: NORMAL and NODAL_H always, then the multiplier (scalar for ALM
/// frictionless and scalar tying, by components for the other ALM families and vector tying; none for penalty),
/// WEIGHTED_GAP for contact, WEIGHTED_SLIP for friction, the multiplier's residual (its reaction).
void AddVariables(MortarType& type, bool scalar_tying) {
    const bool alm = type.method == "ALM", tying = type.method.empty();
    const VariableData* residual = nullptr;
    if ((alm && type.family == "Frictionless") || scalar_tying) {
        type.multiplier = alm ? &LAGRANGE_MULTIPLIER_CONTACT_PRESSURE : &SCALAR_LAGRANGE_MULTIPLIER;
        residual = &WEIGHTED_SCALAR_RESIDUAL;
        type.dofs = {{type.multiplier, residual}};
    } else if (alm || tying) {
        type.multiplier = &VECTOR_LAGRANGE_MULTIPLIER;
        residual = &WEIGHTED_VECTOR_RESIDUAL;
        type.dofs = {{&VECTOR_LAGRANGE_MULTIPLIER_X, &WEIGHTED_VECTOR_RESIDUAL_X},
                     {&VECTOR_LAGRANGE_MULTIPLIER_Y, &WEIGHTED_VECTOR_RESIDUAL_Y},
                     {&VECTOR_LAGRANGE_MULTIPLIER_Z, &WEIGHTED_VECTOR_RESIDUAL_Z}};
    }
    type.nodal_variables = {&NORMAL, &NODAL_H};
    if (type.multiplier != nullptr) type.nodal_variables.push_back(type.multiplier);
    if (!tying) type.nodal_variables.push_back(&WEIGHTED_GAP);
    if (type.frictional) type.nodal_variables.push_back(&WEIGHTED_SLIP);
    if (residual != nullptr) type.nodal_variables.push_back(residual);
}

}  // namespace

const std::vector<ContactConditionName>& RegisteredContactConditionNames() {
    static const std::vector<ContactConditionName> names = [] {
        std::vector<ContactConditionName> result;
        ForEachName([&](const ContactConditionName& row, const FamilyRow&, const PairRow&) {
            result.push_back(row);
        });
        return result;
    }();
    return names;
}

std::string MortarType::ConditionName(bool normal_variation, bool axisymmetric) const {
    return method + (normal_variation ? "NV" : "") + family + (axisymmetric ? "Axisym" : "") + condition_stem;
}

const std::vector<MortarType>& MortarTypes() {
    static const std::vector<MortarType> types = [] {
        std::vector<MortarType> result;
        for (const MortarTypeRow& row : kMortarTypes) {
            const FamilyRow& family = FindFamily(row.method, row.family);
            MortarType type;
            type.name = row.name;
            type.method = row.method;
            type.family = row.family;
            type.contact_type = row.contact_type;
            const std::string stem = family.stem;
            type.condition_stem = stem.substr(0, stem.size() - std::string("Condition").size());
            type.frictional = type.family == "Frictional";
            type.pure_slip = row.pure_slip;
            type.has_axisym = family.has_axisym;
            type.criterion = row.criterion;
            AddVariables(type, type.name == "ScalarMeshTying");
            result.push_back(std::move(type));
        }
        return result;
    }();
    return types;
}

void RegisterContactConditions() {
    static bool registered = false;
    if (registered) return;
    registered = true;
    ForEachName([](const ContactConditionName& row, const FamilyRow& family, const PairRow& pair) {
        Registry<Condition>::Instance().Add(
            row.name, family.factory(pair, row.normal_variation, row.axisymmetric, PrototypeFace(pair.dim, pair.num_slave),
                                     PrototypeFace(pair.dim, pair.num_master)));
    });
}

}  // namespace contact_app
