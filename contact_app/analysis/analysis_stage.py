"""Kratos-style analysis stage: the life cycle of a simulation (Kratos ``analysis_stage``).

Order of the calls (``docs/input_layer.md`` §1):

* ``Initialize``: modelers → ``solver.ImportModelPart`` → ``PrepareModelPart`` → ``AddDofs`` →
  ``ModifyInitialProperties`` → ``ModifyInitialGeometry`` → processes created → every process
  ``ExecuteInitialize`` → ``solver.Initialize`` → ``Check`` → ``ModifyAfterSolverInitialize`` →
  every process ``ExecuteBeforeSolutionLoop`` → TIME = start_time (a restarted model part keeps the
  TIME and STEP of its restart file, and its processes get their saved ``SetRestartState`` after
  ``ExecuteInitialize``).
* ``RunSolutionLoop``: while ``time < end_time`` (up to round-off of the step,
  :func:`contact_app.analysis.time_loop.keep_advancing`): ``AdvanceInTime`` →
  ``InitializeSolutionStep`` (processes ``ExecuteInitializeSolutionStep``,
  ``ChangeMaterialProperties``, ``solver.InitializeSolutionStep``) → ``Predict`` →
  ``SolveSolutionStep`` → ``FinalizeSolutionStep`` (solver, then processes) →
  ``OutputSolutionStep``.
* ``OutputSolutionStep``: only when an output process ``IsOutputStep()``: every process
  ``ExecuteBeforeOutputStep``, ``PrintOutput`` of those output processes, every process
  ``ExecuteAfterOutputStep``.
* ``Finalize``: every process ``ExecuteFinalize``, ``solver.Finalize``.

A Newton iteration that meets an inverted element (``InvertedElementError``: det J or det F ≤ 0)
fails the step, not the run. A step that does not converge is redone in sub-steps when the solver
cuts steps (``adaptative_strategy``, or ``cut_step_on_inverted_element`` for an inverted element).
A step that still does not converge stops the run by default: ``ConvergenceError`` is raised before
that step's finalize and output hooks, so the outputs end at the last converged step. The loop goes
on from that state, as Kratos does, only when ``solver_settings.on_non_converged_step`` is
"continue" (or the stage was created with ``stop_on_non_convergence=False``). Step cutting that
gives up always stops, with the model back at its last converged state and TIME.
"""

from __future__ import annotations

import logging
from typing import Any

import contact_app as ca

from ..io.restart_utility import RestoreProcessStates
from ..launch_rank import is_output_rank
from ..parameters import Parameters
from .reporting import IterationStatus, Reporter, StepRecord
from .solvers.mechanical_solver import STOP_DEFAULT_REASON
from .time_loop import keep_advancing

logger = logging.getLogger("contact_app.analysis")


class AnalysisStage:
    """Base analysis stage: derived stages create the solver and the processes.

    Args:
        model: the model to work on.
        project_parameters: the whole ``ProjectParameters.json`` tree.
        stop_on_non_convergence: True: stop at the first step that does not converge; False: go
            on from it; None (default): as ``solver_settings.on_non_converged_step`` says ("stop"
            unless set to "continue").
        reporter: console report (default: a table on stdout).

    """

    def __init__(
        self,
        model: ca.Model,
        project_parameters: Parameters,
        *,
        stop_on_non_convergence: bool | None = None,
        reporter: Reporter | None = None,
    ):
        if not isinstance(model, ca.Model):
            raise TypeError(f"model must be a contact_app.Model, got {type(model).__name__}")
        self.model = model
        self.project_parameters = project_parameters
        self.stop_on_non_convergence = stop_on_non_convergence
        self.reporter = reporter or Reporter()
        problem_data = project_parameters["problem_data"]
        self.echo_level = problem_data["echo_level"].GetInt()
        self.parallel_type = problem_data["parallel_type"].GetString()
        self.start_time = problem_data["start_time"].GetDouble()
        self.end_time = problem_data["end_time"].GetDouble()
        self.time = self.start_time
        self._last_delta = 0.0  # the last step, for the end-of-loop tolerance
        self._solver: Any = None
        #: Why step cutting gave up (the run then stops), or "".
        self._gave_up = ""
        #: The InvertedElementError that failed the last solve, or None.
        self._failure: Any = None
        self._list_of_processes: list[Any] = []
        self._list_of_output_processes: list[Any] = []

    # -- the three phases --

    def Run(self) -> None:
        """Initialize, RunSolutionLoop, Finalize (Finalize also runs when the loop stops early)."""
        self.Initialize()
        try:
            self.RunSolutionLoop()
        except ca.ConvergenceError:
            self.Finalize()
            raise
        self.Finalize()

    def Initialize(self) -> None:
        """Read the model, create the processes, initialize solver and processes."""
        solver = self._GetSolver()
        with self.reporter.phase("import"):
            self._ModelersSetup()
            solver.ImportModelPart()
            solver.PrepareModelPart()
            solver.AddDofs()
        with self.reporter.phase("initialize"):
            self.ModifyInitialProperties()
            self.ModifyInitialGeometry()
            self._CreateListsOfProcesses()
            for process in self._GetListOfProcesses():
                process.ExecuteInitialize()
            info = solver.GetComputingModelPart().ProcessInfo
            if info[ca.IS_RESTARTED]:
                RestoreProcessStates(self._GetListOfProcesses(), info[ca.RESTART_PROCESS_STATES])
            solver.Initialize()
            self.Check()
            self.ModifyAfterSolverInitialize()
            for process in self._GetListOfProcesses():
                process.ExecuteBeforeSolutionLoop()
            info = solver.GetComputingModelPart().ProcessInfo
            if info[ca.IS_RESTARTED]:
                self.time = float(
                    info[ca.TIME]
                )  # the loop resumes at the restart file's TIME and STEP
            else:
                self.time = self.start_time
                info[ca.TIME] = self.time

    def RunSolutionLoop(self) -> None:
        """Solve the steps while ``time < end_time``."""
        solver = self._GetSolver()
        self.reporter.begin_loop(
            self.start_time,
            self.end_time,
            self._ExpectedSteps(),
            contact_columns=hasattr(self._GetSolver(), "ContactStatus"),
            krylov_column=bool(self._LinearSolverStatistics().get("krylov", False)),
        )
        self.reporter.non_convergence_policy = self._NonConvergencePolicyNote()
        self.reporter.echo_linear_solver = self.echo_level >= 1
        while self.KeepAdvancingSolutionLoop():
            with self.reporter.phase("solve"):
                previous = self.time
                self.time = solver.AdvanceInTime(self.time)
                self._last_delta = self.time - previous
                builder = solver.GetBuilderAndSolver()
                builder.ResetTimings()
                self.reporter.begin_step(int(solver.GetComputingModelPart().ProcessInfo[ca.STEP]))
                solves_before = len(self._LinearSolverStatistics().get("krylov_iterations", []))
                converged = self._TrySolveStep()
                cutting = self._StepCutting() if not converged else None
                if cutting is not None:
                    converged = self._SolveWithSubsteps(*cutting)
                self.reporter.add_builder_timings(builder.GetTimings())
                record = self._StepRecord(converged)
                krylov = self._LinearSolverStatistics().get("krylov_iterations", [])
                record.krylov = [int(n) for n in krylov[solves_before:]] if krylov else None
                self.reporter.record_step(record)
                if hasattr(solver, "GetLinearSolver"):
                    self.reporter.add_linear_solver(solver.GetLinearSolver().GetStatistics())
                if not converged and (self._gave_up or not self._GoesOnAfterNonConvergence()):
                    self._StopOnNonConvergence()
                if not converged:
                    logger.warning(
                        "TIME = %.6g: the step did not converge and the analysis goes on with this "
                        "state, as %s asks",
                        self.time,
                        "stop_on_non_convergence=False"
                        if self.stop_on_non_convergence is False
                        else 'solver_settings.on_non_converged_step = "continue"',
                    )
                self.FinalizeSolutionStep()
            with self.reporter.phase("output"):
                self.OutputSolutionStep()

    def _TrySolveStep(self) -> bool:
        """InitializeSolutionStep, Predict, SolveSolutionStep; an inverted element fails the step.

        The solver turns an ``InvertedElementError`` inside Newton into "not converged" (and keeps
        it as ``last_failure``); one raised by the step's initialization or prediction is caught
        here. Either is kept in ``self._failure`` for the step-cutting decision and the messages.
        """
        solver = self._GetSolver()
        self._failure = None
        strategy = solver.GetSolutionStrategy()
        observed = self.reporter.live and hasattr(strategy, "SetIterationObserver")
        if observed:  # the live Newton line of a long step (the echo_level >= 2 lines replace it)
            observed = self.echo_level < 2 and _solver_echo_level(solver) < 2
        try:
            self.InitializeSolutionStep()
            solver.Predict()
            if observed:
                strategy.SetIterationObserver(self._ReportIteration)
            try:
                converged = bool(solver.SolveSolutionStep())
            finally:
                if observed:  # the strategy must not keep the stage alive through a cycle
                    strategy.SetIterationObserver(None)
        except ca.InvertedElementError as failure:
            logger.warning(
                "TIME = %.6g: the step did not converge: %s", self.time, _first_line(failure)
            )
            converged = False
            self._failure = failure
        else:
            self._failure = getattr(solver, "last_failure", None) if not converged else None
        return converged

    def _StepCutting(self) -> tuple[float, int] | None:
        """(split_factor, max_number_splits) to redo the failed step with, or None.

        ``adaptative_strategy`` cuts any step that does not converge; an inverted element also
        cuts the step when the user did not enable it (``cut_step_on_inverted_element``, default
        true): it is a property of the Newton iterate, which a smaller increment avoids, and the
        step still ends at the time the user asked for.
        """
        solver = self._GetSolver()
        cutting = getattr(solver, "StepCuttingSettings", lambda: None)()
        if cutting is not None or self._failure is None:
            return cutting
        cutting = getattr(solver, "InvertedElementCuttingSettings", lambda: None)()
        if cutting is not None:
            logger.warning(
                "TIME = %.6g: the step is cut (split_factor %g, max_number_splits %d) because of "
                "an inverted element, although adaptative_strategy is off: "
                "solver_settings.cut_step_on_inverted_element is true by default (set it to false "
                "to stop instead)",
                self.time,
                *cutting,
            )
        return cutting

    def _GoesOnAfterNonConvergence(self) -> bool:
        """Whether the loop goes on from a step that did not converge (default: no)."""
        if self.stop_on_non_convergence is not None:
            return not self.stop_on_non_convergence
        policy = getattr(self._GetSolver(), "NonConvergedStepPolicy", lambda: "stop")()
        return bool(policy == "continue")

    def _NonConvergencePolicyNote(self) -> str:
        """One line for the summary: what a step that does not converge does, and why."""
        if self.stop_on_non_convergence is not None:
            return (
                "the run stops (stop_on_non_convergence=True)"
                if self.stop_on_non_convergence
                else "the run goes on from it (stop_on_non_convergence=False)"
            )
        if self._GoesOnAfterNonConvergence():
            return (
                'the run goes on from it (solver_settings.on_non_converged_step = "continue"; '
                'the default "stop" would end the run there)'
            )
        return (
            'the run stops (solver_settings.on_non_converged_step = "stop", the default: '
            f"{STOP_DEFAULT_REASON})"
        )

    def _SolveWithSubsteps(self, split_factor: float, max_number_splits: int) -> bool:
        """Redo a step that did not converge in sub-steps from its last converged state.

        The sub-step is the step divided by ``split_factor``, divided again after each sub-step that
        fails (at most ``max_number_splits`` times); every sub-step restarts from the last converged
        state (buffer 1 copied into the current step, the mesh moved back) and runs the processes'
        and the solver's step hooks at its own time. Converged sub-steps but the last are finalised
        and the time is cloned, so the step ends at its original time (STEP counts the sub-steps).
        When a sub-step still fails after ``max_number_splits`` splits, the model is put back to its
        last converged state (``_RestoreLastConverged``) and the run stops: going on would start the
        next step from a state of a time that was never converged.

        Returns:
            Whether the whole step was solved.
        """
        solver = self._GetSolver()
        part = solver.GetComputingModelPart().GetRootModelPart()
        info = part.ProcessInfo
        self.reporter.cut_steps += 1
        target = self.time
        start = target - info[ca.DELTA_TIME]
        delta = (target - start) / split_factor
        splits = 1
        tolerance = 1.0e-12 * max(abs(target), 1.0)
        time = start
        converged_delta = info[ca.DELTA_TIME]
        utils = ca.VariableUtils()
        while time < target - tolerance:
            following = min(time + delta, target)
            utils.CopySolutionStepData(part, 1, 0)
            utils.UpdateCurrentPosition(part.Nodes)
            info[ca.TIME] = following
            info[ca.DELTA_TIME] = following - time
            logger.info("step cut: solving %.6g -> %.6g (split level %d)", time, following, splits)
            self.reporter.sub_steps += 1
            if self._TrySolveStep():
                converged_delta = following - time
                time = following
                if time < target - tolerance:
                    self.FinalizeSolutionStep()
                    part.CloneTimeStep(time)
                continue
            splits += 1
            if splits > max_number_splits:
                reason = f" ({_first_line(self._failure)})" if self._failure is not None else ""
                self._gave_up = (
                    f"step cutting gave up: a sub-step to TIME = {following:.6g} did not converge"
                    f"{reason} after max_number_splits = {max_number_splits} splits (sub-step "
                    f"{following - time:.3g}); TIME = {target:.6g} was not reached"
                )
                self._RestoreLastConverged(time, converged_delta)
                return False
            delta /= split_factor
        self.time = target
        return True

    def _RestoreLastConverged(self, time: float, delta: float) -> None:
        """Put the model back to its last converged state, at ``time``.

        The historical values of the last converged (sub-)step (buffer 1) are copied into the
        current step, the mesh is moved back, TIME and DELTA_TIME are those of that state, and the
        processes' step values (loads, prescribed values) are applied again at that time, so that
        nothing of the failed sub-step is left under any time.
        """
        part = self._GetSolver().GetComputingModelPart().GetRootModelPart()
        utils = ca.VariableUtils()
        utils.CopySolutionStepData(part, 1, 0)
        utils.UpdateCurrentPosition(part.Nodes)
        part.ProcessInfo[ca.TIME] = time
        part.ProcessInfo[ca.DELTA_TIME] = delta
        self.time = time
        self.ApplyBoundaryConditions()

    def Finalize(self) -> None:
        """Every process ``ExecuteFinalize``, then ``solver.Finalize``."""
        with self.reporter.phase("output"):
            for process in self._GetListOfProcesses():
                process.ExecuteFinalize()
        self._GetSolver().Finalize()

    # -- per step --

    def KeepAdvancingSolutionLoop(self) -> bool:
        """True while ``time < end_time`` beyond round-off of the last step (no extra step)."""
        return keep_advancing(self.time, self.end_time, self._last_delta)

    def InitializeSolutionStep(self) -> None:
        """Apply the processes' step values, then initialize the solver step."""
        self.ApplyBoundaryConditions()
        self.ChangeMaterialProperties()
        self._GetSolver().InitializeSolutionStep()

    def ApplyBoundaryConditions(self) -> None:
        """Every process ``ExecuteInitializeSolutionStep``."""
        for process in self._GetListOfProcesses():
            process.ExecuteInitializeSolutionStep()

    def ChangeMaterialProperties(self) -> None:
        """Hook (empty)."""

    def FinalizeSolutionStep(self) -> None:
        """``solver.FinalizeSolutionStep``, then every process ``ExecuteFinalizeSolutionStep``."""
        self._GetSolver().FinalizeSolutionStep()
        for process in self._GetListOfProcesses():
            process.ExecuteFinalizeSolutionStep()

    def OutputSolutionStep(self) -> None:
        """Before/After output hooks around the output processes that print this step."""
        printing = [p for p in self._GetListOfOutputProcesses() if p.IsOutputStep()]
        if not printing:
            return
        for process in self._GetListOfProcesses():
            process.ExecuteBeforeOutputStep()
        for process in printing:
            if is_output_rank():  # the other MPI ranks hold the same results (launch_rank.py)
                process.PrintOutput()
        for process in self._GetListOfProcesses():
            process.ExecuteAfterOutputStep()

    def Check(self) -> None:
        """Check the solver and every process."""
        self._GetSolver().Check()
        for process in self._GetListOfProcesses():
            process.Check()

    # -- hooks --

    def ModifyInitialProperties(self) -> None:
        """Hook (empty)."""

    def ModifyInitialGeometry(self) -> None:
        """Hook (empty)."""

    def ModifyAfterSolverInitialize(self) -> None:
        """Hook (empty)."""

    def _ModelersSetup(self) -> None:
        """Modelers (none supported; the derived stage rejects a non-empty list)."""

    # -- solver and processes --

    def _GetSolver(self) -> Any:
        if self._solver is None:
            self._solver = self._CreateSolver()
        return self._solver

    def _CreateSolver(self) -> Any:
        raise NotImplementedError("derived analysis stages create the solver")

    def _CreateListsOfProcesses(self) -> None:
        self._list_of_processes = self._CreateProcesses("processes")
        outputs = self._CreateProcesses("output_processes")
        misplaced = [p for p in self._list_of_processes if _is_output(p)]
        for process in misplaced:
            logger.warning(
                'the output process %s is listed in "processes"; it is used as an output process, '
                'but belongs in "output_processes"',
                type(process).__name__,
            )
        not_outputs = [p for p in outputs if not _is_output(p)]
        for process in not_outputs:
            logger.warning(
                'the process %s is listed in "output_processes" but has no '
                'IsOutputStep/PrintOutput; it runs as a regular process (its place is "processes")',
                type(process).__name__,
            )
        self._list_of_output_processes = misplaced + [p for p in outputs if _is_output(p)]
        self._list_of_processes += outputs

    def _CreateProcesses(self, parameter_name: str) -> list[Any]:
        raise NotImplementedError("derived analysis stages create the processes")

    def _GetListOfProcesses(self) -> list[Any]:
        return self._list_of_processes

    def _GetListOfOutputProcesses(self) -> list[Any]:
        return self._list_of_output_processes

    # -- reporting --

    def _ExpectedSteps(self) -> int | None:
        return None

    def _LinearSolverStatistics(self) -> dict:
        """The linear solver's figures (``LinearSolver.GetStatistics()``), {} without one."""
        solver = self._GetSolver()
        if not hasattr(solver, "GetLinearSolver"):
            return {}
        return dict(solver.GetLinearSolver().GetStatistics())

    def _StepRecord(self, converged: bool) -> StepRecord:
        solver = self._GetSolver()
        info = solver.GetComputingModelPart().ProcessInfo
        strategy = solver.GetSolutionStrategy()
        criterion = solver.GetConvergenceCriterion()
        residual = increment = None
        if criterion is not None:
            if criterion.residual is not None:
                residual = (criterion.residual.LastRatio(), criterion.residual.LastAbsolute())
            if criterion.displacement is not None:
                increment = (
                    criterion.displacement.LastRatio(),
                    criterion.displacement.LastAbsolute(),
                )
        status = getattr(solver, "ContactStatus", None)
        return StepRecord(
            info[ca.STEP],
            info[ca.TIME],
            int(strategy.GetIterationNumber()),
            residual,
            increment,
            converged,
            status() if status is not None else None,
        )

    def _ReportIteration(self) -> None:
        """The strategy's iteration observer: the live line of a step that takes long."""
        solver = self._GetSolver()
        solve = float(solver.GetBuilderAndSolver().GetTimings().get("solve", 0.0))
        if not self.reporter.wants_iteration():  # a short step: only the solver's clock
            iteration = int(solver.GetSolutionStrategy().GetIterationNumber())
            self.reporter.iteration(IterationStatus(iteration, linear_solve=solve))
            return
        record = self._StepRecord(False)
        self.reporter.iteration(
            IterationStatus(
                record.iterations, record.residual, record.increment, record.contact, solve
            )
        )

    def _StopOnNonConvergence(self) -> None:
        solver = self._GetSolver()
        info = solver.GetComputingModelPart().ProcessInfo
        if self._gave_up:
            raise ca.ConvergenceError(
                f"{self._gave_up}; last norms: {solver.LastNorms() or 'n/a'}\n"
                f"  stopped:  the model is left at its last converged state, TIME = "
                f"{info[ca.TIME]:.6g} (its loads and displacements); the outputs end at the last "
                "converged step\n"
                "  fix:      reduce the time step, raise max_iteration or max_number_splits, or "
                "check loads and supports"
            )
        if self._failure is not None:
            what = f"did not converge: {_first_line(self._failure)}"
        else:
            what = (
                f"did not converge in {solver.GetSolutionStrategy().GetIterationNumber()} "
                f"iterations; last norms: {solver.LastNorms() or 'n/a'}"
            )
        why = (
            "as asked by --stop-on-non-convergence (stop_on_non_convergence=True)"
            if self.stop_on_non_convergence
            else 'solver_settings.on_non_converged_step is "stop", the default: '
            + STOP_DEFAULT_REASON
        )
        cutting = (
            "solver_settings.cut_step_on_inverted_element: true"
            if self._failure is not None
            else "contact_settings.adaptative_strategy"
        )
        raise ca.ConvergenceError(
            f"step {info[ca.STEP]} (TIME = {info[ca.TIME]:.6g}) {what}\n"
            f"  stopped:  {why}; the outputs end at the last converged step\n"
            f"  fix:      reduce the time step, enable step cutting ({cutting}), raise "
            "max_iteration, or check loads and supports; to go on from such a step set "
            'solver_settings.on_non_converged_step: "continue"'
        )


def _solver_echo_level(solver: Any) -> int:
    """``solver_settings.echo_level`` (0 when the solver has no such setting)."""
    settings = getattr(solver, "settings", None)
    if settings is None or not settings.Has("echo_level"):
        return 0
    return int(settings["echo_level"].GetInt())


def _first_line(error: BaseException) -> str:
    return str(error).partition("\n")[0]


def _is_output(process: Any) -> bool:
    return callable(getattr(process, "IsOutputStep", None)) and callable(
        getattr(process, "PrintOutput", None)
    )
