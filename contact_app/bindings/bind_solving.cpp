// SPDX-License-Identifier: BSD-3-Clause
#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "contact_app/bindings/bindings.h"
#include "contact_app/solving/builder_and_solvers/block_builder_and_solver.h"
#include "contact_app/solving/builder_and_solvers/elimination_builder_and_solver.h"
#include "contact_app/solving/convergence_criteria/composite_criteria.h"
#include "contact_app/solving/convergence_criteria/displacement_criteria.h"
#include "contact_app/solving/convergence_criteria/mixed_generic_criteria.h"
#include "contact_app/solving/convergence_criteria/residual_criteria.h"
#include "contact_app/solving/linear_solvers/linear_solver_factory.h"
#include "contact_app/solving/linear_solvers/static_condensation_solver.h"
#include "contact_app/solving/schemes/bossak_scheme.h"
#include "contact_app/solving/strategies/line_search_strategy.h"

namespace contact_app::bindings {

namespace {

void BindLinearSolvers(py::module_& m) {
    py::class_<LinearSolver, LinearSolver::Pointer>(m, "LinearSolver", "Solver of the global linear system.")
        .def("Info", &LinearSolver::Info,
             "The solver's own name (umfpack, mumps, cholmod, klu, sparse_lu, cg, bicgstab; under a Kratos LU "
             "name, the one that ran last).")
        .def("Clear", &LinearSolver::Clear, "Forgets the cached factorisation.")
        .def("NumberOfSymbolicAnalyses", &LinearSolver::NumberOfSymbolicAnalyses,
             "How often the sparsity pattern was analysed (pattern reuse diagnostic).")
        .def(
            "GetStatistics",
            [](const LinearSolver& self) {
                const LinearSolverStatistics s = self.Statistics();
                py::dict statistics;
                statistics["solver"] = s.solver;
                statistics["ordering"] = s.ordering;
                statistics["ordering_setting"] = s.ordering_setting;
                statistics["factorizations"] = s.factorizations;
                statistics["system_size"] = s.system_size;
                statistics["factor_nonzeros"] = s.factor_nonzeros;
                statistics["max_factor_nonzeros"] = s.max_factor_nonzeros;
                statistics["factor_memory"] = s.factor_memory;
                statistics["max_factor_memory"] = s.max_factor_memory;
                statistics["factor_flops"] = s.factor_flops;
                statistics["symbolic_seconds"] = s.symbolic_seconds;
                statistics["numeric_seconds"] = s.numeric_seconds;
                statistics["workspace_enlargements"] = s.workspace_enlargements;
                statistics["out_of_core_factorizations"] = s.out_of_core_factorizations;
                statistics["symbolic_analyses"] = self.NumberOfSymbolicAnalyses();
                statistics["condensation"] = s.condensation;
                statistics["interface_size"] = s.interface_size;
                statistics["bulk_size"] = s.bulk_size;
                statistics["bulk_factorizations"] = s.bulk_factorizations;
                statistics["condensed_solves"] = s.condensed_solves;
                statistics["bulk_seconds"] = s.bulk_seconds;
                statistics["interface_seconds"] = s.interface_seconds;
                statistics["krylov"] = s.krylov;
                statistics["krylov_method"] = s.krylov_method;
                statistics["krylov_iterations"] = s.krylov_iterations;
                statistics["last_relative_residual"] = s.last_relative_residual;
                statistics["tolerance"] = s.tolerance;
                statistics["preconditioner_seconds"] = s.preconditioner_seconds;
                statistics["preconditioner_setups"] = s.preconditioner_setups;
                statistics["krylov_seconds"] = s.krylov_seconds;
                statistics["ranks"] = s.ranks;
                statistics["near_null_space"] = s.near_null_space;
                return statistics;
            },
            "solver, ordering (used) and ordering_setting (asked for), factorizations, system_size, "
            "factor_nonzeros (nnz L + U) and factor_memory (bytes) of the last factorisation, and their maxima; factor_flops, symbolic_seconds and "
            "numeric_seconds (CPU) summed over the run, symbolic_analyses, workspace_enlargements (MUMPS factorisations "
            "redone with more working space), out_of_core_factorizations (MUMPS factorisations kept on disk); static condensation: condensation ('' = "
            "not a condensing solver, 'yes' or 'no (why)'), interface_size and bulk_size of the last condensed solve, "
            "bulk_factorizations, condensed_solves, bulk_seconds and interface_seconds (wall); Krylov solvers: krylov "
            "(True), krylov_method, krylov_iterations (per solve of the run), last_relative_residual, tolerance, "
            "preconditioner_seconds, preconditioner_setups (solves that set the preconditioner up), krylov_seconds "
            "(wall), ranks (MPI) and near_null_space (rigid-body modes given).");
    py::class_<StaticCondensationSolver, LinearSolver, std::shared_ptr<StaticCondensationSolver>>(
        m, "StaticCondensationSolver",
        "Condenses a constant bulk onto the contact interface (linear_solver_settings.static_condensation).")
        .def(py::init([](LinearSolver::Pointer inner, const std::string& mode, const std::string& bulk_not_linear) {
                 return std::make_shared<StaticCondensationSolver>(std::move(inner), ParseStaticCondensationMode(mode),
                                                                   bulk_not_linear);
             }),
             py::arg("inner"), py::arg("mode") = "auto", py::arg("bulk_not_linear") = "",
             "inner: solver of the full system; mode: 'auto', 'on' or 'off'; bulk_not_linear: why the bodies' "
             "stiffness may change ('' = it does not; 'auto' then refuses).")
        .def("LastSolveWasCondensed", &StaticCondensationSolver::LastSolveWasCondensed)
        .def("SetBulkInCoreLimit", &StaticCondensationSolver::SetBulkInCoreLimit, py::arg("bytes"),
             "Bulk factors CHOLMOD expects above this many bytes are kept out of core by MUMPS instead (0: always; "
             "negative, the default: half the memory available when the bulk is factorised).")
        .def("InnerSolver", &StaticCondensationSolver::InnerSolver, "The solver of the full system.");
    m.def(
        "CreateLinearSolver",
        [](const std::string& solver_type, double tolerance, int max_iteration, const std::string& ordering,
           const std::string& krylov_type, const std::string& preconditioner_type, const std::string& smoother_type,
           const std::string& coarsening_type, int gmres_krylov_space_dimension, int verbosity, int max_levels,
           int coarse_enough, int pre_sweeps, int post_sweeps, bool reform_preconditioner_at_each_step) {
            KrylovSettings krylov;
            krylov.krylov_type = krylov_type;
            krylov.preconditioner_type = preconditioner_type;
            krylov.smoother_type = smoother_type;
            krylov.coarsening_type = coarsening_type;
            krylov.gmres_krylov_space_dimension = gmres_krylov_space_dimension;
            krylov.verbosity = verbosity;
            krylov.max_levels = max_levels;
            krylov.coarse_enough = coarse_enough;
            krylov.pre_sweeps = pre_sweeps;
            krylov.post_sweeps = post_sweeps;
            krylov.reform_preconditioner_at_each_step = reform_preconditioner_at_each_step;
            return CreateLinearSolver({solver_type, tolerance, max_iteration, ordering, krylov});
        },
        py::arg("solver_type") = "", py::arg("tolerance") = 1.0e-6, py::arg("max_iteration") = 1000,
        py::arg("ordering") = "auto", py::arg("krylov_type") = "", py::arg("preconditioner_type") = "",
        py::arg("smoother_type") = "", py::arg("coarsening_type") = "", py::arg("gmres_krylov_space_dimension") = 100,
        py::arg("verbosity") = 0, py::arg("max_levels") = -1, py::arg("coarse_enough") = 1000,
        py::arg("pre_sweeps") = 1, py::arg("post_sweeps") = 1, py::arg("reform_preconditioner_at_each_step") = true,
        "Linear solver for a Kratos or contact_app solver_type name ('' = skyline_lu_factorization: UMFPACK "
        "or MUMPS by size); ordering (UMFPACK, MUMPS): 'auto', 'amd' or 'metis'; the other keywords are the "
        "amgcl keys of the PETSc Krylov solver (solver_type 'amgcl', 'gmres', 'petsc').");
    m.def(
        "CheckKrylovSettings",
        [](const std::string& krylov_type, const std::string& preconditioner_type, const std::string& smoother_type,
           const std::string& coarsening_type) {
            KrylovSettings krylov;
            krylov.krylov_type = krylov_type;
            krylov.preconditioner_type = preconditioner_type;
            krylov.smoother_type = smoother_type;
            krylov.coarsening_type = coarsening_type;
            PetscOptionsFromSettings(krylov);
        },
        py::arg("krylov_type") = "", py::arg("preconditioner_type") = "", py::arg("smoother_type") = "",
        py::arg("coarsening_type") = "",
        "Raises InputError for a krylov_type, preconditioner_type, smoother_type or coarsening_type the PETSc solver "
        "does not take (without loading PETSc).");
    m.def("PetscUnavailableReason", &PetscUnavailableReason,
          "'' when the PETSc solver is available, else why not and which package provides it.");
    m.def(
        "MpiRankAndSize",
        []() {
            const auto solver = std::make_shared<PetscKrylovSolver>(KrylovSettings{});
            return std::make_pair(solver->Rank(), solver->Ranks());
        },
        "(rank, ranks) of PETSC_COMM_WORLD (initialises PETSc and MPI; ConfigurationError without PETSc).");
    m.def("registered_linear_solvers", &RegisteredLinearSolverNames, "Every accepted linear solver_type, sorted.");
    m.def("ResolveLinearSolverName", &ResolveLinearSolverName, py::arg("solver_type"),
          "The solver a solver_type name maps to.");
}

void BindSchemes(py::module_& m) {
    // The base class is the static scheme; "Scheme" names the same class.
    py::class_<Scheme, Scheme::Pointer>(m, "ResidualBasedIncrementalUpdateStaticScheme",
                                        "Static scheme (base of all schemes): u += Δx on free DoFs.")
        .def(py::init<>())
        .def("Info", &Scheme::Info, "Scheme name.")
        .def("Check", &Scheme::Check, py::arg("model_part"));
    m.attr("Scheme") = m.attr("ResidualBasedIncrementalUpdateStaticScheme");
    py::class_<BossakScheme, Scheme, std::shared_ptr<BossakScheme>>(m, "ResidualBasedBossakDisplacementScheme",
                                                            "Implicit Bossak–Newmark displacement scheme.")
        .def(py::init<double, double>(), py::arg("damp_factor_m") = -0.3, py::arg("newmark_beta") = 0.25);
    m.def(
        "ResidualBasedNewmarkDisplacementScheme", []() { return std::make_shared<BossakScheme>(0.0, 0.25); },
        "Newmark average-acceleration scheme (Bossak with damp_factor_m = 0).");
}

void BindBuilders(py::module_& m) {
    py::class_<BuilderAndSolver, BuilderAndSolver::Pointer>(m, "BuilderAndSolver", "Global assembly and solve.")
        .def("GetEquationSystemSize", &BuilderAndSolver::GetEquationSystemSize, "Number of equations.")
        .def("Info", &BuilderAndSolver::Info, "block or elimination.")
        .def(
            "GetTimings",
            [](const BuilderAndSolver& self) {
                const auto& t = self.Timings();
                py::dict timings;
                timings["setup"] = t.setup;
                timings["build"] = t.build;
                timings["solve"] = t.solve;
                timings["builds"] = t.builds;
                timings["solves"] = t.solves;
                timings["scatter"] = t.scatter;
                timings["residual"] = t.residual;
                timings["residual_builds"] = t.residual_builds;
                return timings;
            },
            "Seconds spent in setup (DoFs, graph), build (assembly) and solve, and the call counts.")
        .def("ResetTimings", &BuilderAndSolver::ResetTimings)
        .def(
            "GetDofSet", [](BuilderAndSolver& self) { return self.GetDofSet(); }, py::return_value_policy::reference,
            "The DoFs of the system, sorted by (node id, variable).");
    py::class_<BlockBuilderAndSolver, BuilderAndSolver, std::shared_ptr<BlockBuilderAndSolver>>(
        m, "ResidualBasedBlockBuilderAndSolver", "Builder keeping fixed DoFs in the system.")
        .def(py::init<LinearSolver::Pointer>(), py::arg("linear_solver"));
    py::class_<EliminationBuilderAndSolver, BuilderAndSolver, std::shared_ptr<EliminationBuilderAndSolver>>(
        m, "ResidualBasedEliminationBuilderAndSolver", "Builder removing fixed DoFs from the system.")
        .def(py::init<LinearSolver::Pointer>(), py::arg("linear_solver"));
}

void BindCriteria(py::module_& m) {
    py::class_<ConvergenceCriteria, ConvergenceCriteria::Pointer>(m, "ConvergenceCriteria", "Newton convergence test.")
        .def("SetEchoLevel", &ConvergenceCriteria::SetEchoLevel, py::arg("level"))
        .def("LastNorms", &ConvergenceCriteria::LastNorms, "The norms of the last check, one line.")
        .def("Info", &ConvergenceCriteria::Info, "Criterion name.");
    py::class_<DisplacementCriteria, ConvergenceCriteria, std::shared_ptr<DisplacementCriteria>>(
        m, "DisplacementCriteria", "Relative/absolute norm of the free DoF increment.")
        .def(py::init<double, double>(), py::arg("relative_tolerance"), py::arg("absolute_tolerance"))
        .def("LastRatio", &DisplacementCriteria::LastRatio)
        .def("LastAbsolute", &DisplacementCriteria::LastAbsolute);
    py::class_<ResidualCriteria, ConvergenceCriteria, std::shared_ptr<ResidualCriteria>>(
        m, "ResidualCriteria", "Relative/absolute norm of the free, unconstrained residual.")
        .def(py::init<double, double>(), py::arg("relative_tolerance"), py::arg("absolute_tolerance"))
        .def("LastRatio", &ResidualCriteria::LastRatio)
        .def("LastAbsolute", &ResidualCriteria::LastAbsolute);
    py::class_<MixedGenericCriteria, ConvergenceCriteria, std::shared_ptr<MixedGenericCriteria>>(
        m, "MixedGenericCriteria", "Increment criterion with (relative, absolute) tolerances per variable.")
        .def(py::init([](const std::vector<std::tuple<const VariableData*, double, double>>& list) {
                 std::vector<MixedGenericCriteria::Entry> entries;
                 for (const auto& [variable, relative, absolute] : list) entries.push_back({variable, relative, absolute});
                 return std::make_shared<MixedGenericCriteria>(entries);
             }),
             py::arg("tolerances"), "tolerances: list of (variable, relative_tolerance, absolute_tolerance).")
        .def("LastRatio", &MixedGenericCriteria::LastRatio, py::arg("group"))
        .def("LastAbsolute", &MixedGenericCriteria::LastAbsolute, py::arg("group"));
    py::class_<CompositeCriteria, ConvergenceCriteria, std::shared_ptr<CompositeCriteria>> composite(
        m, "CompositeCriteria", "Two criteria combined with AND or OR.");
    m.def(
        "AndCriteria",
        [](ConvergenceCriteria::Pointer a, ConvergenceCriteria::Pointer b) {
            return std::make_shared<CompositeCriteria>(CompositeCriteria::Mode::And, a, b);
        },
        py::arg("first"), py::arg("second"), "Converged when both criteria are.");
    m.def(
        "OrCriteria",
        [](ConvergenceCriteria::Pointer a, ConvergenceCriteria::Pointer b) {
            return std::make_shared<CompositeCriteria>(CompositeCriteria::Mode::Or, a, b);
        },
        py::arg("first"), py::arg("second"), "Converged when either criterion is.");
}

StrategySettings Settings(bool compute_reactions, bool reform_step_dofs, bool move_mesh_flag) {
    StrategySettings settings;
    settings.compute_reactions = compute_reactions;
    settings.reform_dofs_at_each_step = reform_step_dofs;
    settings.move_mesh_flag = move_mesh_flag;
    return settings;
}

void BindStrategies(py::module_& m) {
    py::class_<SolvingStrategy, SolvingStrategy::Pointer>(m, "SolvingStrategy", "Implicit solving strategy.")
        .def("Initialize", &SolvingStrategy::Initialize)
        .def("InitializeSolutionStep", &SolvingStrategy::InitializeSolutionStep)
        .def("Predict", &SolvingStrategy::Predict)
        .def("SolveSolutionStep", &SolvingStrategy::SolveSolutionStep, "Returns whether the step converged.")
        .def("FinalizeSolutionStep", &SolvingStrategy::FinalizeSolutionStep)
        .def("Solve", &SolvingStrategy::Solve, "The four step calls in order; returns convergence.")
        .def("Check", &SolvingStrategy::Check)
        .def("Clear", &SolvingStrategy::Clear)
        .def("MoveMesh", &SolvingStrategy::MoveMesh)
        .def("SetEchoLevel", &SolvingStrategy::SetEchoLevel, py::arg("level"))
        .def(
            "SetIterationObserver",
            [](SolvingStrategy& self, std::optional<std::function<void()>> observer) {
                self.SetIterationObserver(observer ? std::move(*observer) : std::function<void()>());
            },
            py::arg("observer"),
            "Callable without arguments run after every Newton iteration (None removes it); an exception it raises "
            "ends the step.")
        .def("GetIterationNumber", &SolvingStrategy::GetIterationNumber)
        .def("IsConverged", &SolvingStrategy::LastStepConverged)
        .def(
            "GetBuilderAndSolver",
            [](SolvingStrategy& self) { return &self.GetBuilderAndSolver(); }, py::return_value_policy::reference_internal)
        .def(
            "GetSystemVector", [](SolvingStrategy& self) { return Eigen::VectorXd(self.GetSystemVector()); },
            "Copy of the last right-hand side.")
        .def(
            "GetSolutionVector", [](SolvingStrategy& self) { return Eigen::VectorXd(self.GetSolutionVector()); },
            "Copy of the last increment Δx.");
    m.def(
        "ResidualBasedLinearStrategy",
        [](ModelPart& part, Scheme::Pointer scheme, BuilderAndSolver::Pointer builder, bool compute_reactions,
           bool reform_step_dofs, bool move_mesh_flag) {
            return std::make_shared<SolvingStrategy>(part, scheme, builder,
                                                     Settings(compute_reactions, reform_step_dofs, move_mesh_flag));
        },
        py::arg("model_part"), py::arg("scheme"), py::arg("builder_and_solver"), py::arg("compute_reactions") = true,
        py::arg("reform_step_dofs") = false, py::arg("move_mesh_flag") = true, py::keep_alive<0, 1>(),
        "One build, solve and update per step.");
    py::class_<NewtonRaphsonStrategy, SolvingStrategy, std::shared_ptr<NewtonRaphsonStrategy>>(
        m, "ResidualBasedNewtonRaphsonStrategy", "Full Newton–Raphson (LHS rebuilt every iteration).")
        .def(py::init([](ModelPart& part, Scheme::Pointer scheme, ConvergenceCriteria::Pointer criteria,
                         BuilderAndSolver::Pointer builder, int max_iteration, bool compute_reactions,
                         bool reform_step_dofs, bool move_mesh_flag) {
                 return std::make_shared<NewtonRaphsonStrategy>(
                     part, scheme, builder, criteria, max_iteration,
                     Settings(compute_reactions, reform_step_dofs, move_mesh_flag));
             }),
             py::arg("model_part"), py::arg("scheme"), py::arg("convergence_criterion"), py::arg("builder_and_solver"),
             py::arg("max_iteration") = 10, py::arg("compute_reactions") = true, py::arg("reform_step_dofs") = false,
             py::arg("move_mesh_flag") = true, py::keep_alive<1, 2>())
        .def("GetMaxIterationNumber", &NewtonRaphsonStrategy::GetMaxIterationNumber)
        .def("SetMaxIterationNumber", &NewtonRaphsonStrategy::SetMaxIterationNumber, py::arg("max_iteration"))
        .def("IterationHistory", &NewtonRaphsonStrategy::IterationHistory, "Criterion norms per iteration of the last step.")
        .def(
            "CheckTangentAlong",
            [](NewtonRaphsonStrategy& self, std::optional<SystemVectorType> direction, double step) {
                auto check = self.CheckTangentAlong(direction ? std::move(*direction) : SystemVectorType(), step);
                return py::make_tuple(check.tangent_times_direction, check.central_difference, check.direction);
            },
            py::arg("direction") = py::none(), py::arg("step") = 1e-7,
            "(A v, −(b(x+hv) − b(x−hv))/2h, v) at the current iterate, fixed DoFs zero; direction None: the Newton "
            "correction. A developer's check of the assembled tangent (docs/theory/structural.md §6).");
    py::class_<LineSearchStrategy, NewtonRaphsonStrategy, std::shared_ptr<LineSearchStrategy>>(
        m, "LineSearchStrategy", "Newton–Raphson with a secant line search.")
        .def(py::init([](ModelPart& part, Scheme::Pointer scheme, ConvergenceCriteria::Pointer criteria,
                         BuilderAndSolver::Pointer builder, int max_iteration, bool compute_reactions,
                         bool reform_step_dofs, bool move_mesh_flag, int max_line_search_iterations,
                         double first_alpha_value, double second_alpha_value, double min_alpha, double max_alpha,
                         double line_search_tolerance) {
                 LineSearchSettings line_search{max_line_search_iterations, first_alpha_value, second_alpha_value,
                                                min_alpha, max_alpha, line_search_tolerance};
                 return std::make_shared<LineSearchStrategy>(
                     part, scheme, builder, criteria, max_iteration,
                     Settings(compute_reactions, reform_step_dofs, move_mesh_flag), line_search);
             }),
             py::arg("model_part"), py::arg("scheme"), py::arg("convergence_criterion"), py::arg("builder_and_solver"),
             py::arg("max_iteration") = 10, py::arg("compute_reactions") = true, py::arg("reform_step_dofs") = false,
             py::arg("move_mesh_flag") = true, py::arg("max_line_search_iterations") = 5,
             py::arg("first_alpha_value") = 0.5, py::arg("second_alpha_value") = 1.0, py::arg("min_alpha") = 0.1,
             py::arg("max_alpha") = 2.0, py::arg("line_search_tolerance") = 0.5, py::keep_alive<1, 2>())
        .def("LastAlpha", &LineSearchStrategy::LastAlpha);
}

}  // namespace

void BindSolving(py::module_& m) {
    BindLinearSolvers(m);
    BindSchemes(m);
    BindBuilders(m);
    BindCriteria(m);
    BindStrategies(m);
}

}  // namespace contact_app::bindings
