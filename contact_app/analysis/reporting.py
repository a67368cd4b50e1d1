"""Console report of an analysis: a per-step table, a progress bar on terminals, a closing summary.

On a terminal, a step that has run for ``LIVE_AFTER`` seconds also gets a live line, rewritten in
place after every Newton iteration until the step's row replaces it::

  step 3 | Newton 4 | res ratio 1.234e-03 | active 96 slip 0 | linear solve 3.1 s (step 9.8 s) | 9 s

(the criteria's ratios, the active and slipping slave nodes of a contact analysis, the linear
solver's seconds in the last iteration and in the whole step, the step's wall time). It is not
written when ``stream`` is not a terminal, so logs stay clean.

::

     step          time  iter  res ratio    res abs   dx ratio     dx abs  converged
        1  1.000000e-01     2  3.112e-16  1.204e-18          -          -  yes
    ...
    summary: 10 steps, 20 Newton iterations, all converged
      wall time: import 0.004 s, initialize 0.010 s, solve 0.120 s (assembly 0.070 s,
                 linear solve 0.030 s), output 0.020 s, total 0.160 s
      linear solver: umfpack, ordering amd ("auto"), 20 factorisations, largest factors
                     1.234e+04 nnz in 0.9 MB
      files written (11): VTK_Output/Structure_0_1.vtk, ...
"""

from __future__ import annotations

import shutil
import sys
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from typing import TextIO

PHASES = ("import", "initialize", "solve", "output")
_HEADER = (
    f"{'step':>6}  {'time':>12}  {'iter':>4}  {'res ratio':>9}  {'res abs':>9}  "
    f"{'dx ratio':>9}  {'dx abs':>9}  converged"
)
_CONTACT_HEADER = f"  {'active':>6}  {'slip':>6}  {'pairs':>6}  {'max pen.':>9}"
_KRYLOV_HEADER = "  krylov its"
#: Krylov iteration counts shown per step row (the rest is "...").
KRYLOV_SHOWN = 8
#: Seconds a step runs before its live Newton line appears.
LIVE_AFTER = 2.0


@dataclass
class StepRecord:
    """What one solved step reports.

    Attributes:
        step: STEP of the ProcessInfo.
        time: TIME of the step.
        iterations: Newton iterations (1 for a linear strategy).
        residual: (ratio, absolute) of the residual criterion, None if not used.
        increment: (ratio, absolute) of the displacement criterion, None if not used.
        converged: whether the step converged.
        contact: (active slave nodes, slipping ones, pairs, max penetration) of a contact
            analysis, None otherwise.
        krylov: the iterations of every linear solve of the step (one per Newton iteration) with an
            iterative solver, None otherwise.

    """

    step: int
    time: float
    iterations: int
    residual: tuple[float, float] | None
    increment: tuple[float, float] | None
    converged: bool
    contact: tuple[int, int, int, float] | None = None
    krylov: list[int] | None = None


@dataclass
class IterationStatus:
    """What the live line shows after one Newton iteration.

    Attributes:
        iteration: the Newton iteration just done (1-based, within the step).
        residual: (ratio, absolute) of the residual criterion, None if not used.
        increment: (ratio, absolute) of the displacement criterion, None if not used.
        contact: (active, slipping, pairs, max penetration) of a contact analysis, None otherwise.
        linear_solve: seconds spent in the linear solver since the step began.

    """

    iteration: int
    residual: tuple[float, float] | None = None
    increment: tuple[float, float] | None = None
    contact: tuple[int, int, int, float] | None = None
    linear_solve: float = 0.0


def _norm(value: float | None) -> str:
    return f"{value:9.3e}" if value is not None else f"{'-':>9}"


def linear_solver_text(statistics: dict, *, largest: bool = True) -> str:
    """One line on the linear solver (``LinearSolver.GetStatistics()``).

    Args:
        statistics: the solver's figures (solver, ordering, ordering_setting, factorizations,
            factor_nonzeros and factor_memory of the last factorisation and their maxima).
        largest: report the largest factors of the run (the summary) rather than the last ones
            (the step log).

    """
    text = f"linear solver: {statistics['solver']}"
    if statistics.get("ordering"):
        text += f", ordering {statistics['ordering']}"
        if statistics.get("ordering_setting"):
            text += f' ("{statistics["ordering_setting"]}")'
    count = int(statistics.get("factorizations", 0))
    if count:
        text += f", {count} factorisation{'s' if count != 1 else ''}"
    enlargements = int(statistics.get("workspace_enlargements", 0))
    if enlargements:  # MUMPS redid a factorisation with more working space (ICNTL(14))
        text += f" ({enlargements} redone with more working space)"
    out_of_core = int(statistics.get("out_of_core_factorizations", 0))
    if out_of_core:  # MUMPS kept the factors on disk: in core they would not fit (ICNTL(22))
        text += f" ({out_of_core} out of core: the factors on disk in the temporary directory)"
    iterations = [int(n) for n in statistics.get("krylov_iterations", [])]
    if statistics.get("krylov") and iterations:
        text += (
            f", {statistics.get('krylov_method', '')}: {len(iterations)} solves, "
            f"{sum(iterations)} iterations (max {max(iterations)}, mean "
            f"{sum(iterations) / len(iterations):.1f}) to a relative residual of "
            f"{float(statistics.get('tolerance', 0.0)):.0e}, set-up "
            f"{float(statistics.get('preconditioner_seconds', 0.0)):.3g} s "
            f"({int(statistics.get('preconditioner_setups', len(iterations)))} preconditioner "
            f"set-ups for {len(iterations)} solves), iterations "
            f"{float(statistics.get('krylov_seconds', 0.0)):.3g} s"
        )
        if int(statistics.get("near_null_space", 0)):
            text += f", {int(statistics['near_null_space'])} rigid-body modes"
    key = "max_factor" if largest else "factor"
    nonzeros = float(statistics.get(f"{key}_nonzeros", 0.0))
    if nonzeros > 0.0:
        memory = float(statistics.get(f"{key}_memory", 0.0)) / 2.0**20
        which = "largest" if largest else "last"
        text += f", {which} factors {nonzeros:.4g} nnz in {memory:.1f} MB"
    return text


def condensation_text(statistics: dict) -> str:
    """One line on the static condensation (``LinearSolver.GetStatistics()``), "" without one.

    Says whether the last solve was condensed and why not, the interface and system sizes, the
    bulk factorisations with their wall time and the condensed solves with theirs.
    """
    status = str(statistics.get("condensation", ""))
    if not status:
        return ""
    text = f"static condensation: {status}"
    solves = int(statistics.get("condensed_solves", 0))
    if not solves:
        return text
    interface = int(statistics.get("interface_size", 0))
    size = interface + int(statistics.get("bulk_size", 0))
    bulk = int(statistics.get("bulk_factorizations", 0))
    seconds = float(statistics.get("interface_seconds", 0.0))
    return (
        f"{text}; interface {interface} of {size} equations, bulk condensed {bulk}x in "
        f"{float(statistics.get('bulk_seconds', 0.0)):.3g} s, {solves} condensed "
        f"solve{'s' if solves != 1 else ''} in {seconds:.3g} s ({seconds / solves:.3g} s each)"
    )


class Reporter:
    """Collect timings and step records; print them to ``stream`` (None = silent).

    Args:
        stream: where the table and the summary go (default ``sys.stdout``).
        progress: draw a progress bar; None = only when ``stream`` is a terminal.
        quiet: print nothing.
        live: show the live Newton line of long steps; None = only when ``stream`` is a terminal.
        clock: the seconds clock the live line's delay is measured with (tests pass a fake one).
        live_after: seconds a step runs before its live line appears.

    """

    def __init__(
        self,
        stream: TextIO | None = None,
        progress: bool | None = None,
        *,
        quiet: bool = False,
        live: bool | None = None,
        clock: Callable[[], float] = time.perf_counter,
        live_after: float = LIVE_AFTER,
    ):
        self.stream = None if quiet else (stream or sys.stdout)
        isatty = bool(self.stream is not None and getattr(self.stream, "isatty", lambda: False)())
        self._progress_wanted = isatty if progress is None else progress
        #: Whether long steps get a live Newton line (never when nothing is printed).
        self.live = self.stream is not None and (isatty if live is None else live)
        self._clock = clock
        self._live_after = live_after
        self._step_label = ""
        self._step_started: float | None = None
        self._last_solve = 0.0
        self._progress_on = False
        self._bar_shown = False
        self.phases = dict.fromkeys(PHASES, 0.0)
        self.assembly = 0.0
        self.linear_solve = 0.0
        self.steps: list[StepRecord] = []
        self.files: list[str] = []
        self._started = time.perf_counter()
        self.started_wall = time.time()
        self._span = (0.0, 0.0)
        self._expected: int | None = None
        self._contact_columns = False
        self._krylov_column = False
        #: Steps redone in sub-steps, and the sub-steps solved for them.
        self.cut_steps = 0
        self.sub_steps = 0
        #: What happens to a step that does not converge, and why (set by the analysis stage).
        self.non_convergence_policy = ""
        #: The linear solver's latest figures (``LinearSolver.GetStatistics()``), None = unknown.
        self.linear_solver: dict | None = None
        #: Print the linear solver's line under every step row (echo_level >= 1).
        self.echo_linear_solver = False

    def _print(self, text: str = "") -> None:
        if self.stream is not None:
            self._ClearBar()
            print(text, file=self.stream)
            self._DrawBar()

    @contextmanager
    def phase(self, name: str) -> Iterator[None]:
        """Add the wall time of the block to phase ``name``."""
        start = time.perf_counter()
        try:
            yield
        finally:
            self.phases[name] += time.perf_counter() - start

    def add_builder_timings(self, timings: dict[str, float]) -> None:
        """Add a builder's assembly (setup + build) and linear-solve seconds."""
        self.assembly += float(timings.get("build", 0.0)) + float(timings.get("setup", 0.0))
        self.linear_solve += float(timings.get("solve", 0.0))

    def add_linear_solver(self, statistics: dict) -> None:
        """Keep the linear solver's figures after a step; print them when echo_linear_solver."""
        previous = self.linear_solver
        self.linear_solver = dict(statistics)
        if not self.echo_linear_solver:
            return
        count = int(statistics.get("factorizations", 0))
        step_count = count - (int(previous.get("factorizations", 0)) if previous else 0)
        line = linear_solver_text(statistics, largest=False)
        if count:
            line += f" ({step_count} in this step)"
        self._print(f"{'':8}{line}")

    def begin_loop(
        self,
        start_time: float,
        end_time: float,
        expected_steps: int | None,
        contact_columns: bool = False,
        krylov_column: bool = False,
    ) -> None:
        """Print the table header.

        With the contact columns of a contact analysis, and the iterations of each linear solve
        with an iterative solver.
        """
        self._contact_columns = contact_columns
        self._krylov_column = krylov_column
        self._span = (start_time, end_time)
        self._expected = expected_steps
        several = expected_steps is None or expected_steps > 1
        self._progress_on = self._progress_wanted and several and self.stream is not None
        if expected_steps == 0:
            self._print(
                f"no step to solve: start_time {start_time} is not below end_time {end_time}"
            )
            return
        self._print(
            _HEADER
            + (_CONTACT_HEADER if contact_columns else "")
            + (_KRYLOV_HEADER if krylov_column else "")
        )

    def begin_step(self, step: int) -> None:
        """Start the clock of step ``step`` (its live line appears ``live_after`` s later)."""
        self._step_label = str(step)
        self._step_started = self._clock()
        self._last_solve = 0.0

    def wants_iteration(self) -> bool:
        """Whether :meth:`iteration` would print now (callers skip gathering the status if not)."""
        return (
            self.live
            and self._step_started is not None
            and self._clock() - self._step_started >= self._live_after
        )

    def iteration(self, status: IterationStatus) -> None:
        """Rewrite the live line of the running step (nothing before ``live_after`` seconds).

        Call it after every iteration (with only ``iteration`` and ``linear_solve`` while
        :meth:`wants_iteration` is false): the line shows the linear solve of the last iteration.
        """
        last = max(status.linear_solve - self._last_solve, 0.0)
        self._last_solve = status.linear_solve
        if not self.wants_iteration() or self.stream is None or self._step_started is None:
            return
        elapsed = self._clock() - self._step_started
        parts = [f"step {self._step_label}", f"Newton {status.iteration}"]
        if status.residual is not None:
            parts.append(f"res ratio {status.residual[0]:.3e}")
        if status.increment is not None:
            parts.append(f"dx ratio {status.increment[0]:.3e}")
        if status.contact is not None:
            parts.append(f"active {status.contact[0]} slip {status.contact[1]}")
        parts.append(f"linear solve {last:.1f} s (step {status.linear_solve:.1f} s)")
        parts.append(f"{elapsed:.0f} s")
        line = " | ".join(parts)
        width = shutil.get_terminal_size((200, 24)).columns - 1
        self._ClearBar()
        self.stream.write(line[: max(width, 20)])  # one screen line, so \r can rewrite it
        self.stream.flush()
        self._bar_shown = True

    def record_step(self, record: StepRecord) -> None:
        """Store a step and print its row (which replaces the step's live line)."""
        self._step_started = None
        self.steps.append(record)
        residual = record.residual or (None, None)
        increment = record.increment or (None, None)
        row = (
            f"{record.step:>6}  {record.time:12.6e}  {record.iterations:>4}  {_norm(residual[0])}  "
            f"{_norm(residual[1])}  {_norm(increment[0])}  {_norm(increment[1])}  "
            + ("yes" if record.converged else "NO")
        )
        if self._contact_columns and record.contact is not None:
            active, slip, pairs, penetration = record.contact
            row = row[: row.rfind("  ") + 2] + f"{row[row.rfind('  ') + 2 :]:>9}"
            row += f"  {active:>6}  {slip:>6}  {pairs:>6}  {_norm(penetration)}"
        if self._krylov_column:
            counts = record.krylov or []
            shown = " ".join(str(n) for n in counts[:KRYLOV_SHOWN])
            row += "  " + (shown + (" ..." if len(counts) > KRYLOV_SHOWN else "") or "-")
        self._print(row)

    def _DrawBar(self) -> None:
        if not self._progress_on or self.stream is None or not self.steps:
            return
        start, end = self._span
        current = self.steps[-1].time
        fraction = 1.0 if end <= start else min(max((current - start) / (end - start), 0.0), 1.0)
        width = 30
        filled = int(round(fraction * width))
        count = f"{len(self.steps)}/{self._expected}" if self._expected else f"{len(self.steps)}"
        self.stream.write(f"[{'#' * filled}{'.' * (width - filled)}] {fraction:4.0%}  step {count}")
        self.stream.flush()
        self._bar_shown = True

    def _ClearBar(self) -> None:
        if self._bar_shown and self.stream is not None:
            self.stream.write("\r\x1b[K")
            self._bar_shown = False

    def non_converged_steps(self) -> list[int]:
        """STEP numbers of the steps that did not converge."""
        return [record.step for record in self.steps if not record.converged]

    def summary(self) -> str:
        """The closing summary (several lines)."""
        total = time.perf_counter() - self._started
        iterations = sum(record.iterations for record in self.steps)
        failed = self.non_converged_steps()
        if failed:
            listing = ", ".join(str(s) for s in failed[:10]) + (", ..." if len(failed) > 10 else "")
            convergence = f"{len(failed)} NOT converged (steps {listing})"
        else:
            convergence = "all converged" if self.steps else "nothing solved"
        phases = self.phases
        lines = [
            f"summary: {len(self.steps)} steps, {iterations} Newton iterations, {convergence}",
            f"  wall time: import {phases['import']:.3f} s, "
            f"initialize {phases['initialize']:.3f} s, solve {phases['solve']:.3f} s "
            f"(assembly {self.assembly:.3f} s, linear solve {self.linear_solve:.3f} s), "
            f"output {phases['output']:.3f} s, total {total:.3f} s",
        ]
        if self.linear_solver is not None:
            lines.append("  " + linear_solver_text(self.linear_solver))
            condensation = condensation_text(self.linear_solver)
            if condensation:
                lines.append("  " + condensation)
        if self.cut_steps:
            lines.append(
                f"  step cutting: {self.cut_steps} step(s) redone in {self.sub_steps} sub-steps"
            )
        if (failed or self.cut_steps) and self.non_convergence_policy:
            lines.append(f"  a step that does not converge: {self.non_convergence_policy}")
        if self.files:
            shown = ", ".join(self.files[:5]) + (", ..." if len(self.files) > 5 else "")
            lines.append(f"  files written ({len(self.files)}): {shown}")
        else:
            lines.append("  files written: none")
        return "\n".join(lines)

    def finish(self) -> None:
        """Remove the progress bar and print the summary."""
        if self.stream is None:
            return
        self._ClearBar()
        self._progress_on = False
        print(self.summary(), file=self.stream)
        self.stream.flush()
