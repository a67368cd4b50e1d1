// SPDX-License-Identifier: BSD-3-Clause
// The contact condition table: method × NV × family × axisym × pair → Kratos name → prototype.
#include "custom_conditions/contact_condition_registration.h"

#include <memory>
#include <utility>

#include "contact_app/kernel/geometries/geometry_factory.h"
#include "contact_app/kernel/registry.h"
#include "custom_conditions/alm_frictionless_components_mortar_contact_condition.h"
#include "custom_conditions/alm_frictional_mortar_contact_condition.h"
#include "custom_conditions/alm_frictionless_mortar_contact_condition.h"
#include "custom_conditions/mesh_tying_mortar_condition.h"
#include "custom_conditions/mpc_mortar_contact_condition.h"
#include "custom_conditions/penalty_frictional_mortar_contact_condition.h"
#include "custom_conditions/penalty_frictionless_mortar_contact_condition.h"

namespace contact_app {
namespace {

struct PairRow {
    const char* suffix;
    int dim, num_slave, num_master;
};

constexpr PairRow kPairs[] = {{"2D2N", 2, 2, 2}, {"3D3N", 3, 3, 3}, {"3D4N", 3, 4, 4}, {"3D3N4N", 3, 3, 4},
                              {"3D4N3N", 3, 4, 3}};

using Factory = std::shared_ptr<const Condition> (*)(const PairRow&, bool nv, bool axisym, Geometry::Pointer slave,
                                                      Geometry::Pointer master);

struct FamilyRow {
    const char* method;  ///< "ALM" or "Penalty" ("" for the non-contact families MeshTying and MPC)
    const char* family;  ///< "Frictionless", "FrictionlessComponents", "Frictional", "MeshTying", "MPC"
    FrictionalCase frictional_case;  ///< non-contact families: the case with the same local size (matrix_size)
    bool has_axisym;
    bool implemented;  ///< flip (and give the factory) when the family lands
    Factory factory;
    bool has_nv = true;                           ///< mesh tying and MPC have no NV variant
    const char* stem = "MortarContactCondition";  ///< "MortarCondition" for mesh tying
};

/// The plane prototypes of a family (5 pairs × NV). @throws InternalError for an axisymmetric or unknown row
template <template <int, int, bool, int> class TFamily>
std::shared_ptr<const Condition> MakePlaneFamily(const PairRow& pair, bool nv, bool axisym, Geometry::Pointer s,
                                                 Geometry::Pointer m) {
    CONTACT_CHECK(!axisym, InternalError, "contact condition table: the family has no axisymmetric variant");
    auto make = [&](auto prototype) -> std::shared_ptr<const Condition> { return prototype; };
#define CONTACT_APP_PAIR(D, NS, NM)                                                                          \
    if (pair.dim == D && pair.num_slave == NS && pair.num_master == NM)                                      \
        return nv ? make(std::make_shared<const TFamily<D, NS, true, NM>>(0, s, nullptr, m))                 \
                  : make(std::make_shared<const TFamily<D, NS, false, NM>>(0, s, nullptr, m));
    CONTACT_APP_PAIR(2, 2, 2)
    CONTACT_APP_PAIR(3, 3, 3)
    CONTACT_APP_PAIR(3, 4, 4)
    CONTACT_APP_PAIR(3, 3, 4)
    CONTACT_APP_PAIR(3, 4, 3)
#undef CONTACT_APP_PAIR
    CONTACT_THROW(InternalError, "contact condition table: unknown pair ", pair.suffix);
}

/// The prototypes of a family without NV / axisymmetric variants (mesh tying, MPC): true mixed pairs.
template <template <int, int, int> class TFamily>
std::shared_ptr<const Condition> MakePairFamily(const PairRow& pair, bool nv, bool axisym, Geometry::Pointer s,
                                                Geometry::Pointer m) {
    CONTACT_CHECK(!nv && !axisym, InternalError, "condition table: the family has no NV / axisymmetric variant");
#define CONTACT_APP_PAIR(D, NS, NM)                                     \
    if (pair.dim == D && pair.num_slave == NS && pair.num_master == NM) \
        return std::make_shared<const TFamily<D, NS, NM>>(0, s, nullptr, m);
    CONTACT_APP_PAIR(2, 2, 2)
    CONTACT_APP_PAIR(3, 3, 3)
    CONTACT_APP_PAIR(3, 4, 4)
    CONTACT_APP_PAIR(3, 3, 4)
    CONTACT_APP_PAIR(3, 4, 3)
#undef CONTACT_APP_PAIR
    CONTACT_THROW(InternalError, "condition table: unknown pair ", pair.suffix);
}

/// The plane prototypes plus the 2D axisymmetric variant TAxisym.
template <template <int, int, bool, int> class TFamily, template <int, bool> class TAxisym>
std::shared_ptr<const Condition> MakeFamily(const PairRow& pair, bool nv, bool axisym, Geometry::Pointer s,
                                            Geometry::Pointer m) {
    if (axisym)
        return nv ? std::shared_ptr<const Condition>(std::make_shared<const TAxisym<2, true>>(0, s, nullptr, m))
                  : std::shared_ptr<const Condition>(std::make_shared<const TAxisym<2, false>>(0, s, nullptr, m));
    return MakePlaneFamily<TFamily>(pair, nv, false, std::move(s), std::move(m));
}

const FamilyRow kFamilies[] = {
    {"ALM", "Frictionless", FrictionalCase::FRICTIONLESS, true, true,
     MakeFamily<AugmentedLagrangianMethodFrictionlessMortarContactCondition,
                AugmentedLagrangianMethodFrictionlessMortarContactAxisymCondition>},
    {"ALM", "FrictionlessComponents", FrictionalCase::FRICTIONLESS_COMPONENTS, false, true,
     MakePlaneFamily<AugmentedLagrangianMethodFrictionlessComponentsMortarContactCondition>},
    {"ALM", "Frictional", FrictionalCase::FRICTIONAL, true, true,
     MakeFamily<AugmentedLagrangianMethodFrictionalMortarContactCondition,
                AugmentedLagrangianMethodFrictionalMortarContactAxisymCondition>},
    {"Penalty", "Frictionless", FrictionalCase::FRICTIONLESS_PENALTY, true, true,
     MakeFamily<PenaltyMethodFrictionlessMortarContactCondition, PenaltyMethodFrictionlessMortarContactAxisymCondition>},
    {"Penalty", "Frictional", FrictionalCase::FRICTIONAL_PENALTY, true, true,
     MakeFamily<PenaltyMethodFrictionalMortarContactCondition, PenaltyMethodFrictionalMortarContactAxisymCondition>},
    // Non-contact families: MeshTyingMortarCondition<pair> (size of the DISPLACEMENT tying, d(2n_s + n_m)) and
    // MPCMortarContactCondition<pair> (d(n_s + n_m)).
    {"", "MeshTying", FrictionalCase::FRICTIONLESS_COMPONENTS, false, true, MakePairFamily<MeshTyingMortarCondition>,
     false, "MortarCondition"},
    {"", "MPC", FrictionalCase::FRICTIONLESS_PENALTY, false, true, MakePairFamily<MPCMortarContactCondition>, false},
};

Geometry::Pointer PrototypeFace(int dim, int num_nodes) {
    Geometry::PointsArrayType points;
    for (int i = 0; i < num_nodes; ++i) points.push_back(std::make_shared<Node>(i + 1, 0.0, 0.0, 0.0));
    const char* name = dim == 2 ? "Line2D2" : (num_nodes == 3 ? "Triangle3D3" : "Quadrilateral3D4");
    return CreateGeometry(name, points);
}

/// Calls @p visit(row, family, pair) for every name of the decoder whose family is implemented.
template <class TVisit>
void ForEachImplementedName(TVisit&& visit) {
    for (const FamilyRow& family : kFamilies) {
        if (!family.implemented) continue;
        for (const bool nv : {false, true})
            for (const bool axisym : {false, true})
                for (const PairRow& pair : kPairs) {
                    if ((axisym && (!family.has_axisym || pair.dim != 2)) || (nv && !family.has_nv)) continue;
                    ContactConditionName row;
                    row.name = std::string(family.method) + (nv ? "NV" : "") + family.family +
                               (axisym ? "Axisym" : "") + family.stem + pair.suffix;
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

}  // namespace

const std::vector<ContactConditionName>& RegisteredContactConditionNames() {
    static const std::vector<ContactConditionName> names = [] {
        std::vector<ContactConditionName> result;
        ForEachImplementedName([&](const ContactConditionName& row, const FamilyRow&, const PairRow&) {
            result.push_back(row);
        });
        return result;
    }();
    return names;
}

void RegisterContactConditions() {
    static bool registered = false;
    if (registered) return;
    registered = true;
    ForEachImplementedName([](const ContactConditionName& row, const FamilyRow& family, const PairRow& pair) {
        Registry<Condition>::Instance().Add(
            row.name, family.factory(pair, row.normal_variation, row.axisymmetric, PrototypeFace(pair.dim, pair.num_slave),
                                     PrototypeFace(pair.dim, pair.num_master)));
    });
}

}  // namespace contact_app
