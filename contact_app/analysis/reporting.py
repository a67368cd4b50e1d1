"""Console report of an analysis: a per-step table, a progress bar on terminals, a closing summary.

::

     step          time  iter  res ratio    res abs   dx ratio     dx abs  converged
        1  1.000000e-01     2  3.112e-16  1.204e-18          -          -  yes
    ...
    summary: 10 steps, 20 Newton iterations, all converged
      wall time: import 0.004 s, initialize 0.010 s, solve 0.120 s (assembly 0.070 s,
                 linear solve 0.030 s), output 0.020 s, total 0.160 s
      files written (11): VTK_Output/Structure_0_1.vtk, ...
"""

from __future__ import annotations

import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from typing import TextIO

PHASES = ("import", "initialize", "solve", "output")
_HEADER = (
    f"{'step':>6}  {'time':>12}  {'iter':>4}  {'res ratio':>9}  {'res abs':>9}  "
    f"{'dx ratio':>9}  {'dx abs':>9}  converged"
)
_CONTACT_HEADER = f"  {'active':>6}  {'slip':>6}  {'pairs':>6}  {'max pen.':>9}"


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

    """

    step: int
    time: float
    iterations: int
    residual: tuple[float, float] | None
    increment: tuple[float, float] | None
    converged: bool
    contact: tuple[int, int, int, float] | None = None


def _norm(value: float | None) -> str:
    return f"{value:9.3e}" if value is not None else f"{'-':>9}"


class Reporter:
    """Collect timings and step records; print them to ``stream`` (None = silent).

    Args:
        stream: where the table and the summary go (default ``sys.stdout``).
        progress: draw a progress bar; None = only when ``stream`` is a terminal.

    """

    def __init__(
        self, stream: TextIO | None = None, progress: bool | None = None, *, quiet: bool = False
    ):
        self.stream = None if quiet else (stream or sys.stdout)
        isatty = bool(self.stream is not None and getattr(self.stream, "isatty", lambda: False)())
        self._progress_wanted = isatty if progress is None else progress
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
        #: Steps redone in sub-steps, and the sub-steps solved for them.
        self.cut_steps = 0
        self.sub_steps = 0
        #: What happens to a step that does not converge, and why (set by the analysis stage).
        self.non_convergence_policy = ""

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

    def begin_loop(
        self,
        start_time: float,
        end_time: float,
        expected_steps: int | None,
        contact_columns: bool = False,
    ) -> None:
        """Print the table header (with the contact columns of a contact analysis)."""
        self._contact_columns = contact_columns
        self._span = (start_time, end_time)
        self._expected = expected_steps
        several = expected_steps is None or expected_steps > 1
        self._progress_on = self._progress_wanted and several and self.stream is not None
        if expected_steps == 0:
            self._print(
                f"no step to solve: start_time {start_time} is not below end_time {end_time}"
            )
            return
        self._print(_HEADER + (_CONTACT_HEADER if contact_columns else ""))

    def record_step(self, record: StepRecord) -> None:
        """Store a step and print its row."""
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
