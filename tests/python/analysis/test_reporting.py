"""Console report: table rows, progress bar only on terminals, closing summary."""

from __future__ import annotations

import io
import json
from pathlib import Path

import pytest
from analysis_cases import load

import contact_app as ca
from contact_app.analysis import IterationStatus, Reporter, StepRecord, StructuralMechanicsAnalysis
from contact_app.analysis.reporting import linear_solver_text
from contact_app.parameters import Parameters


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def _records() -> list[StepRecord]:
    return [
        StepRecord(1, 0.5, 2, (1e-12, 3e-15), None, True),
        StepRecord(2, 1.0, 10, (2e-3, 4e-4), (1e-2, 5e-5), False),
    ]


def test_table_rows_and_summary() -> None:
    stream = io.StringIO()
    reporter = Reporter(stream)
    reporter.begin_loop(0.0, 1.0, 2)
    for record in _records():
        reporter.record_step(record)
    reporter.add_builder_timings({"setup": 0.5, "build": 1.0, "solve": 0.25})
    reporter.files = ["out/a.vtu", "out/b.vtu"]
    reporter.finish()
    lines = stream.getvalue().splitlines()
    assert lines[0].split() == [
        "step",
        "time",
        "iter",
        "res",
        "ratio",
        "res",
        "abs",
        "dx",
        "ratio",
        "dx",
        "abs",
        "converged",
    ]
    assert lines[1].split() == ["1", "5.000000e-01", "2", "1.000e-12", "3.000e-15", "-", "-", "yes"]
    assert lines[2].split()[-1] == "NO"
    assert lines[3] == "summary: 2 steps, 12 Newton iterations, 1 NOT converged (steps 2)"
    assert "assembly 1.500 s, linear solve 0.250 s" in lines[4]
    assert lines[5] == "  files written (2): out/a.vtu, out/b.vtu"
    assert "\r" not in stream.getvalue()  # not a terminal: no progress bar
    assert reporter.non_converged_steps() == [2]


def test_krylov_column_and_summary_of_an_iterative_solver() -> None:
    stream = io.StringIO()
    reporter = Reporter(stream)
    reporter.begin_loop(0.0, 1.0, 2, krylov_column=True)
    first, second = _records()
    first.krylov = [31, 25]
    second.krylov = list(range(1, 11))  # more than KRYLOV_SHOWN
    reporter.record_step(first)
    reporter.record_step(second)
    reporter.linear_solver = {
        "solver": "mixed_ulm_linear_solver(petsc)",
        "krylov": True,
        "krylov_method": "gmres + gamg, 2 levels",
        "krylov_iterations": [31, 25, *range(1, 11)],
        "tolerance": 1e-6,
        "preconditioner_seconds": 1.5,
        "preconditioner_setups": 4,
        "krylov_seconds": 2.0,
        "near_null_space": 6,
    }
    reporter.finish()
    lines = stream.getvalue().splitlines()
    assert lines[0].endswith("krylov its")
    assert lines[1].endswith("  31 25")
    assert lines[2].endswith("  1 2 3 4 5 6 7 8 ...")
    assert (
        "linear solver: mixed_ulm_linear_solver(petsc), gmres + gamg, 2 levels: 12 solves, 111 "
        "iterations (max 31, mean 9.2) to a relative residual of 1e-06, set-up 1.5 s (4 "
        "preconditioner set-ups for 12 solves), iterations 2 s, 6 rigid-body modes"
    ) in stream.getvalue()


def test_progress_bar_on_a_terminal_with_several_steps() -> None:
    stream = _Terminal()
    reporter = Reporter(stream)
    reporter.begin_loop(0.0, 1.0, 2)
    reporter.record_step(_records()[0])
    assert stream.getvalue().endswith("[###############...............]  50%  step 1/2")
    reporter.record_step(_records()[1])
    reporter.finish()
    text = stream.getvalue()
    assert text.count("\r\x1b[K") == 2  # the bar is cleared before the next row and the summary
    assert "summary:" in text.splitlines()[-3]


def test_no_progress_bar_for_a_single_step() -> None:
    stream = _Terminal()
    reporter = Reporter(stream)
    reporter.begin_loop(0.0, 1.0, 1)
    reporter.record_step(_records()[0])
    assert "[" not in stream.getvalue()


def test_quiet_prints_nothing_but_keeps_the_records() -> None:
    reporter = Reporter(quiet=True)
    reporter.begin_loop(0.0, 1.0, 2)
    reporter.record_step(_records()[1])
    reporter.finish()
    assert reporter.non_converged_steps() == [2]
    assert reporter.summary().startswith("summary: 1 steps, 10 Newton iterations")


class _Clock:
    """A clock the test moves by hand (no timing in the tests)."""

    def __init__(self) -> None:
        self.now = 100.0

    def __call__(self) -> float:
        return self.now


def test_live_line_appears_only_after_the_delay_and_is_rewritten_in_place() -> None:
    stream, clock = _Terminal(), _Clock()
    reporter = Reporter(stream, progress=False, clock=clock, live_after=2.0)
    reporter.begin_loop(0.0, 1.0, 2, contact_columns=True)
    reporter.begin_step(7)
    clock.now += 1.0
    assert not reporter.wants_iteration()
    reporter.iteration(IterationStatus(1, (0.5, 1.0), None, (3, 1, 4, 0.0), 0.4))
    assert "Newton" not in stream.getvalue()  # a short step stays silent
    clock.now += 1.5
    reporter.iteration(IterationStatus(2, (2e-3, 1.0), (4e-4, 1e-6), (12, 2, 8, 0.0), 1.5))
    clock.now += 3.0
    reporter.iteration(IterationStatus(3, (1e-6, 1.0), None, (12, 0, 8, 0.0), 2.0))
    text = stream.getvalue()
    lines = text.split("\r\x1b[K")
    assert lines[-2].endswith(
        "step 7 | Newton 2 | res ratio 2.000e-03 | dx ratio 4.000e-04 | active 12 slip 2 | "
        "linear solve 1.1 s (step 1.5 s) | 2 s"
    )
    assert lines[-1] == (
        "step 7 | Newton 3 | res ratio 1.000e-06 | active 12 slip 0 | "
        "linear solve 0.5 s (step 2.0 s) | 6 s"
    )
    assert "\n" not in text.partition("\n")[2]  # only the header ends a line so far
    reporter.record_step(StepRecord(7, 0.5, 3, (1e-6, 1.0), None, True, (12, 0, 8, 0.0)))
    cleared, _, row = stream.getvalue().rpartition("\r\x1b[K")
    assert cleared.endswith("| 6 s") and row.split()[:3] == ["7", "5.000000e-01", "3"]
    assert not reporter.wants_iteration()  # the row replaced the line; the next step starts over


def test_no_live_line_when_not_a_terminal_unless_forced() -> None:
    clock = _Clock()
    for stream, live, shown in (
        (io.StringIO(), None, False),
        (_Terminal(), False, False),
        (io.StringIO(), True, True),
    ):
        reporter = Reporter(stream, clock=clock, live=live, live_after=0.0)
        reporter.begin_step(1)
        reporter.iteration(IterationStatus(1, None, None, None, 0.0))
        assert ("Newton 1" in stream.getvalue()) is shown
    quiet = Reporter(quiet=True, live=True, live_after=0.0)
    quiet.begin_step(1)
    assert not quiet.wants_iteration()


def test_a_run_shows_one_live_line_per_newton_iteration(
    case_dir: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(case_dir)
    parameters = load(case_dir / "plate_static_parameters.json")
    del parameters["output_processes"]
    stream = io.StringIO()  # not a terminal: the line is forced on
    reporter = Reporter(stream, live=True, live_after=0.0)
    analysis = StructuralMechanicsAnalysis(
        ca.Model(), Parameters(json.dumps(parameters)), reporter=reporter
    )
    analysis.Run()
    text = stream.getvalue()
    iterations = sum(record.iterations for record in reporter.steps)
    assert text.count("| Newton ") == iterations >= 2
    assert "step 1 | Newton 1 | res ratio " in text and "step 2 | Newton 1 | " in text
    quiet = io.StringIO()
    parameters["problem_data"]["echo_level"] = 0
    StructuralMechanicsAnalysis(
        ca.Model(), Parameters(json.dumps(parameters)), reporter=Reporter(quiet, live_after=0.0)
    ).Run()
    assert "| Newton" not in quiet.getvalue() and "\r" not in quiet.getvalue()


def _mumps(enlargements: int) -> dict:
    return {
        "solver": "mumps",
        "ordering": "metis",
        "ordering_setting": "auto",
        "factorizations": 12,
        "max_factor_nonzeros": 4.0e5,
        "max_factor_memory": 8.0 * 2.0**20,
        "workspace_enlargements": enlargements,
    }


def test_a_factorisation_redone_with_more_working_space_is_reported() -> None:
    text = linear_solver_text(_mumps(3))
    assert text == (
        'linear solver: mumps, ordering metis ("auto"), 12 factorisations '
        "(3 redone with more working space), largest factors 4e+05 nnz in 8.0 MB"
    )


def test_no_enlargement_says_nothing_about_working_space() -> None:
    assert "working space" not in linear_solver_text(_mumps(0))
    statistics = _mumps(0)
    del statistics["workspace_enlargements"]  # a solver that does not count them
    assert linear_solver_text(statistics) == linear_solver_text(_mumps(0))


def test_out_of_core_factorisations_are_reported() -> None:
    statistics = _mumps(0) | {"out_of_core_factorizations": 12}
    assert linear_solver_text(statistics) == (
        'linear solver: mumps, ordering metis ("auto"), 12 factorisations '
        "(12 out of core: the factors on disk in the temporary directory), "
        "largest factors 4e+05 nnz in 8.0 MB"
    )
    assert "out of core" not in linear_solver_text(_mumps(0))
