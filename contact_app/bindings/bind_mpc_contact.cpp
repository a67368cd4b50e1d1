// SPDX-License-Identifier: BSD-3-Clause
// The MPC contact route: its active-set criterion and its Newton strategy (custom_strategies/).
#include "contact_app/bindings/bindings.h"
#include "custom_strategies/mpc_contact_criteria.h"
#include "custom_strategies/residual_based_newton_raphson_mpc_contact_strategy.h"

namespace contact_app::bindings {

void BindMPCContact(py::module_& m) {
    py::class_<MPCContactCriteria, ConvergenceCriteria, std::shared_ptr<MPCContactCriteria>>(
        m, "MPCContactCriteria", "Active-set (and stick/slip) convergence of the MPC contact route from the reactions.")
        .def(py::init<>())
        .def("ActiveNodes", &MPCContactCriteria::ActiveNodes, "Active slave nodes after the last update.")
        .def("SlipNodes", &MPCContactCriteria::SlipNodes, "Active slipping slave nodes after the last update.")
        .def("LastActiveFlips", &MPCContactCriteria::LastActiveFlips)
        .def("LastSlipFlips", &MPCContactCriteria::LastSlipFlips)
        .def_static("ComputeLumpedSlaveArea", &MPCContactCriteria::ComputeLumpedSlaveArea, py::arg("model_part"),
                    "NODAL_MAUX := lumped slave area on the nodes of \"Contact\".");

    using Strategy = ResidualBasedNewtonRaphsonMPCContactStrategy;
    py::class_<Strategy, NewtonRaphsonStrategy, std::shared_ptr<Strategy>>(
        m, "ResidualBasedNewtonRaphsonMPCContactStrategy",
        "Newton–Raphson for MPC contact: constraints refreshed and re-imposed per iteration, reactions for the set.")
        .def(py::init([](ModelPart& part, Scheme::Pointer scheme, ConvergenceCriteria::Pointer criteria,
                         BuilderAndSolver::Pointer builder, int max_iteration, bool compute_reactions,
                         bool reform_step_dofs, bool move_mesh_flag, int inner_loop_iterations,
                         bool update_each_nl_iteration, bool enforce_ntn) {
                 StrategySettings settings;
                 settings.compute_reactions = compute_reactions;
                 settings.reform_dofs_at_each_step = reform_step_dofs;
                 settings.move_mesh_flag = move_mesh_flag;
                 MPCContactStrategySettings mpc;
                 mpc.inner_loop_iterations = inner_loop_iterations;
                 mpc.update_each_nl_iteration = update_each_nl_iteration;
                 mpc.enforce_ntn = enforce_ntn;
                 return std::make_shared<Strategy>(part, scheme, builder, criteria, max_iteration, settings, mpc);
             }),
             py::arg("model_part"), py::arg("scheme"), py::arg("convergence_criterion"), py::arg("builder_and_solver"),
             py::arg("max_iteration") = 30, py::arg("compute_reactions") = true, py::arg("reform_step_dofs") = true,
             py::arg("move_mesh_flag") = true, py::arg("inner_loop_iterations") = 5,
             py::arg("update_each_nl_iteration") = false, py::arg("enforce_ntn") = false, py::keep_alive<1, 2>())
        .def("GetInnerLoopIterations", &Strategy::GetInnerLoopIterations)
        .def_static("ComputeNodalWeights", &Strategy::ComputeNodalWeights, py::arg("model_part"),
                    "NODAL_PAUX := number of SLAVE conditions of \"Contact\" holding the node.");
}

}  // namespace contact_app::bindings
