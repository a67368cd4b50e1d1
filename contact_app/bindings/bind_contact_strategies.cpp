// SPDX-License-Identifier: BSD-3-Clause
// Contact convergence criteria and the contact Newton strategy (custom_strategies/).
#include <utility>
#include <vector>

#include <pybind11/stl.h>

#include "contact_app/bindings/binding_helpers.h"
#include "contact_app/bindings/bindings.h"
#include "custom_conditions/contact_condition_registration.h"
#include "custom_strategies/displacement_lagrange_multiplier_contact_criteria.h"
#include "custom_strategies/line_search_contact_strategy.h"
#include "custom_strategies/mixed_ulm_linear_solver.h"
#include "custom_strategies/mortar_convergence_criteria.h"
#include "custom_strategies/residual_based_newton_raphson_contact_strategy.h"

namespace contact_app::bindings {

void BindContactStrategies(py::module_& m) {
    py::enum_<ContactBlockMeasure>(m, "ContactBlockMeasure", "How a block of unknowns is judged converged.")
        .value("INCREMENT", ContactBlockMeasure::INCREMENT)
        .value("RESIDUAL", ContactBlockMeasure::RESIDUAL);

    py::class_<ContactCriteriaTolerances>(m, "ContactCriteriaTolerances",
                                          "Tolerances of the displacement and multiplier blocks of a contact system.")
        .def(py::init<>())
        .def_readwrite("displacement_relative", &ContactCriteriaTolerances::displacement_relative)
        .def_readwrite("displacement_absolute", &ContactCriteriaTolerances::displacement_absolute)
        .def_readwrite("lm_relative", &ContactCriteriaTolerances::lm_relative)
        .def_readwrite("lm_absolute", &ContactCriteriaTolerances::lm_absolute)
        .def_readwrite("stick_relative", &ContactCriteriaTolerances::stick_relative)
        .def_readwrite("stick_absolute", &ContactCriteriaTolerances::stick_absolute)
        .def_readwrite("slip_relative", &ContactCriteriaTolerances::slip_relative)
        .def_readwrite("slip_absolute", &ContactCriteriaTolerances::slip_absolute)
        .def_readwrite("ratio_normal_tangent_threshold", &ContactCriteriaTolerances::ratio_normal_tangent_threshold)
        .def_readwrite("ensure_contact", &ContactCriteriaTolerances::ensure_contact)
        .def_readwrite("split_frictional", &ContactCriteriaTolerances::split_frictional)
        .def_readwrite("pure_slip", &ContactCriteriaTolerances::pure_slip);

    using LMCriteria = DisplacementLagrangeMultiplierContactCriteria;
    py::class_<LMCriteria, ConvergenceCriteria, std::shared_ptr<LMCriteria>> lm(
        m, "DisplacementLagrangeMultiplierContactCriteria",
        "Block convergence (displacement / multiplier, optionally normal / stick / slip) of a mortar contact system.");
    lm.def(py::init<ContactBlockMeasure, ContactBlockMeasure, ContactCriteriaTolerances>(),
           py::arg("displacement_measure"), py::arg("lm_measure"), py::arg("tolerances"))
        .def(
            "LastRatio",
            [](const LMCriteria& self, int block) { return self.LastRatio(static_cast<LMCriteria::Block>(block)); },
            py::arg("block"), "Ratio of block 0 disp, 1 lm (normal), 2 stick, 3 slip.")
        .def(
            "LastAbsolute",
            [](const LMCriteria& self, int block) { return self.LastAbsolute(static_cast<LMCriteria::Block>(block)); },
            py::arg("block"), "Absolute norm of block 0 disp, 1 lm (normal), 2 stick, 3 slip.");

    using Mortar = BaseMortarConvergenceCriteria;
    py::class_<Mortar, ConvergenceCriteria, std::shared_ptr<Mortar>> mortar(
        m, "BaseMortarConvergenceCriteria", "Active-set (and stick/slip) convergence of a mortar contact formulation.");
    py::enum_<Mortar::Family>(mortar, "Family")
        .value("ALM_FRICTIONLESS", Mortar::Family::ALM_FRICTIONLESS)
        .value("ALM_FRICTIONLESS_COMPONENTS", Mortar::Family::ALM_FRICTIONLESS_COMPONENTS)
        .value("ALM_FRICTIONAL", Mortar::Family::ALM_FRICTIONAL)
        .value("PENALTY_FRICTIONLESS", Mortar::Family::PENALTY_FRICTIONLESS)
        .value("PENALTY_FRICTIONAL", Mortar::Family::PENALTY_FRICTIONAL)
        .value("MESH_TYING", Mortar::Family::MESH_TYING);
    mortar.def(py::init<Mortar::Family, bool>(), py::arg("family"), py::arg("pure_slip") = false)
        .def("ActiveNodes", &Mortar::ActiveNodes, "Active slave nodes after the last update.")
        .def("SlipNodes", &Mortar::SlipNodes, "Active slipping slave nodes after the last update.")
        .def("NonDissipativeNodes", &Mortar::NonDissipativeNodes,
             "ALM friction: slipping nodes of the last update whose traction points against the slip.")
        .def("LastActiveFlips", &Mortar::LastActiveFlips)
        .def("LastSlipFlips", &Mortar::LastSlipFlips)
        .def("UpdateNormalsAndTangents", &Mortar::UpdateNormalsAndTangents, py::arg("model_part"));

    py::class_<MortarType>(m, "MortarType",
                           "A solver mortar_type decoded from the condition table: the condition family it runs, the "
                           "variables and DoFs the solver adds, the mortar criterion.")
        .def_readonly("name", &MortarType::name)
        .def_readonly("method", &MortarType::method, "Condition name prefix: \"ALM\", \"Penalty\"; \"\" for mesh tying.")
        .def_readonly("family", &MortarType::family, "Condition family: \"Frictionless\", \"Frictional\", ...")
        .def_readonly("contact_type", &MortarType::contact_type, "The contact process' contact_type; \"\" for tying.")
        .def_readonly("frictional", &MortarType::frictional)
        .def_readonly("pure_slip", &MortarType::pure_slip)
        .def_readonly("has_axisym", &MortarType::has_axisym, "The family has the 2D axisymmetric variant.")
        .def_readonly("criterion", &MortarType::criterion, "The family of its BaseMortarConvergenceCriteria.")
        .def_property_readonly(
            "nodal_variables",
            [](const MortarType& self) {
                std::vector<py::object> variables;
                for (const VariableData* variable : self.nodal_variables) variables.push_back(VariableObject(*variable));
                return variables;
            },
            "Historical variables the solver adds to the structural ones, in order.")
        .def_property_readonly(
            "dofs",
            [](const MortarType& self) {
                std::vector<std::pair<py::object, py::object>> dofs;
                for (const auto& [dof, reaction] : self.dofs) dofs.emplace_back(VariableObject(*dof), VariableObject(*reaction));
                return dofs;
            },
            "(DoF, reaction) pairs the solver adds to every node.")
        .def_property_readonly(
            "multiplier",
            [](const MortarType& self) { return self.multiplier ? VariableObject(*self.multiplier) : py::none(); },
            "The slave multiplier variable; None for the penalty families.")
        .def("ConditionName", &MortarType::ConditionName, py::arg("normal_variation"), py::arg("axisymmetric"),
             "The condition name up to the pair, e.g. ALMNVFrictionalAxisymMortarContact.");
    m.def("MortarTypes", &MortarTypes, py::return_value_policy::reference,
          "Every solver mortar_type, decoded from the condition table.");

    py::class_<MixedULMLinearSolver, LinearSolver, std::shared_ptr<MixedULMLinearSolver>>(
        m, "MixedULMLinearSolver",
        "Condenses the dual multipliers of the active slave nodes and solves the displacement-sized system.")
        .def(py::init<LinearSolver::Pointer>(), py::arg("inner_solver"))
        .def("LastSolveWasCondensed", &MixedULMLinearSolver::LastSolveWasCondensed)
        .def("LastCondensedMultipliers", &MixedULMLinearSolver::LastCondensedMultipliers);

    py::class_<ResidualBasedNewtonRaphsonContactStrategy, NewtonRaphsonStrategy,
               std::shared_ptr<ResidualBasedNewtonRaphsonContactStrategy>>(
        m, "ResidualBasedNewtonRaphsonContactStrategy",
        "Newton–Raphson for mortar contact: explicit gaps after the prediction, active set updated by the criteria.")
        .def(py::init([](ModelPart& part, Scheme::Pointer scheme, ConvergenceCriteria::Pointer criteria,
                         BuilderAndSolver::Pointer builder, int max_iteration, bool compute_reactions,
                         bool reform_step_dofs, bool move_mesh_flag, int inner_loop_iterations) {
                 StrategySettings settings;
                 settings.compute_reactions = compute_reactions;
                 settings.reform_dofs_at_each_step = reform_step_dofs;
                 settings.move_mesh_flag = move_mesh_flag;
                 ContactStrategySettings contact;
                 contact.inner_loop_iterations = inner_loop_iterations;
                 return std::make_shared<ResidualBasedNewtonRaphsonContactStrategy>(part, scheme, builder, criteria,
                                                                                    max_iteration, settings, contact);
             }),
             py::arg("model_part"), py::arg("scheme"), py::arg("convergence_criterion"), py::arg("builder_and_solver"),
             py::arg("max_iteration") = 30, py::arg("compute_reactions") = true, py::arg("reform_step_dofs") = true,
             py::arg("move_mesh_flag") = true, py::arg("inner_loop_iterations") = 5, py::keep_alive<1, 2>())
        .def("GetInnerLoopIterations", &ResidualBasedNewtonRaphsonContactStrategy::GetInnerLoopIterations);

    py::class_<LineSearchContactStrategy, ResidualBasedNewtonRaphsonContactStrategy,
               std::shared_ptr<LineSearchContactStrategy>>(
        m, "LineSearchContactStrategy",
        "The contact Newton strategy with a line search per block (displacements, multipliers).")
        .def(py::init([](ModelPart& part, Scheme::Pointer scheme, ConvergenceCriteria::Pointer criteria,
                         BuilderAndSolver::Pointer builder, int max_iteration, bool compute_reactions,
                         bool reform_step_dofs, bool move_mesh_flag, int inner_loop_iterations, double min_alpha) {
                 StrategySettings settings;
                 settings.compute_reactions = compute_reactions;
                 settings.reform_dofs_at_each_step = reform_step_dofs;
                 settings.move_mesh_flag = move_mesh_flag;
                 ContactStrategySettings contact;
                 contact.inner_loop_iterations = inner_loop_iterations;
                 return std::make_shared<LineSearchContactStrategy>(part, scheme, builder, criteria, max_iteration,
                                                                    settings, contact, min_alpha);
             }),
             py::arg("model_part"), py::arg("scheme"), py::arg("convergence_criterion"), py::arg("builder_and_solver"),
             py::arg("max_iteration") = 30, py::arg("compute_reactions") = true, py::arg("reform_step_dofs") = true,
             py::arg("move_mesh_flag") = true, py::arg("inner_loop_iterations") = 5, py::arg("min_alpha") = 1.0e-3,
             py::keep_alive<1, 2>())
        .def("LastDisplacementAlpha", &LineSearchContactStrategy::LastDisplacementAlpha)
        .def("LastMultiplierAlpha", &LineSearchContactStrategy::LastMultiplierAlpha);
}

}  // namespace contact_app::bindings
