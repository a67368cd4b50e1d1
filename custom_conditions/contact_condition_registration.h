// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace contact_app {

class VariableData;

/// One registered contact condition name, decoded (docs/registered_conditions.md §1).
struct ContactConditionName {
    std::string name;    ///< e.g. "ALMNVFrictionlessAxisymMortarContactCondition2D2N"
    std::string family;  ///< "ALMFrictionless", "ALMFrictionlessComponents", "ALMFrictional", "PenaltyFrictionless", ...
    bool normal_variation = false;
    bool axisymmetric = false;
    int dim = 0, num_slave = 0, num_master = 0;
    int matrix_size = 0;  ///< local system size of the family for this pair
};

/// Every name of the table (the names RegisterContactConditions adds), in table order.
const std::vector<ContactConditionName>& RegisteredContactConditionNames();

/// The active-set and convergence families of the mortar criteria (BaseMortarConvergenceCriteria::Family).
enum class MortarCriterionFamily {
    ALM_FRICTIONLESS,
    ALM_FRICTIONLESS_COMPONENTS,
    ALM_FRICTIONAL,
    PENALTY_FRICTIONLESS,
    PENALTY_FRICTIONAL,
    MESH_TYING
};

/// One solver mortar_type (solver_settings.contact_settings.mortar_type, docs/input_layer.md §2) decoded: the
/// condition family it runs and what the contact solver and processes add for it. The variables are the
/// registered globals (not owned).
struct MortarType {
    std::string name;          ///< "ALMContactFrictionless", ..., "ComponentsMeshTying"
    std::string method;        ///< condition name prefix: "ALM", "Penalty"; "" for mesh tying
    std::string family;        ///< condition family: "Frictionless", "FrictionlessComponents", "Frictional", "MeshTying"
    std::string contact_type;  ///< the contact process' contact_type ("FrictionalPureSlip", ...); "" for mesh tying
    std::string condition_stem;  ///< after family and Axisym in the condition name: "MortarContact"; "Mortar" (tying)
    bool frictional = false;
    bool pure_slip = false;    ///< frictional: every active node slips
    bool has_axisym = false;   ///< the family has the 2D axisymmetric variant
    MortarCriterionFamily criterion = MortarCriterionFamily::ALM_FRICTIONLESS;
    /// Historical variables the solver adds to the structural ones, in the order they are added.
    std::vector<const VariableData*> nodal_variables;
    /// (DoF, reaction) pairs the solver adds to every node.
    std::vector<std::pair<const VariableData*, const VariableData*>> dofs;
    /// The slave multiplier (LAGRANGE_MULTIPLIER_CONTACT_PRESSURE, VECTOR_ or SCALAR_LAGRANGE_MULTIPLIER); null
    /// for the penalty families.
    const VariableData* multiplier = nullptr;

    /// The condition name up to the pair ("ALMNVFrictionalAxisymMortarContact"); the search appends
    /// "Condition<d>D<n>N".
    std::string ConditionName(bool normal_variation, bool axisymmetric) const;
};

/// Every mortar_type, in the order the errors list them.
const std::vector<MortarType>& MortarTypes();

/// Registers the prototypes of the contact condition families in Registry<Condition>, from one
/// table (method × NV × family × axisym × pair). Idempotent.
void RegisterContactConditions();

}  // namespace contact_app
