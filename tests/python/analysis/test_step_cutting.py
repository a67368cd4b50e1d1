"""A step that does not converge is redone in sub-steps from the last converged state.

The solver decides (``StepCuttingSettings``; the contact solvers return ``split_factor`` and
``max_number_splits`` when ``adaptative_strategy`` is set). Here a solver that fails every step
longer than a limit checks the mechanics on the plate case, whose load grows with time (the
converged state at a time does not depend on the path).
"""

from __future__ import annotations

import pytest
from analysis_cases import DATA

import contact_app as ca
from contact_app.analysis import StructuralMechanicsAnalysis
from contact_app.analysis.reporting import Reporter
from contact_app.parameters import Parameters


def _analysis(
    limit: float | None, settings: tuple[float, int] | None
) -> StructuralMechanicsAnalysis:
    parameters = Parameters.from_file(DATA / "plate_static_parameters.json")
    parameters.AddValue("output_processes", {})
    parameters["processes"].AddValue("json_check_process", [])
    analysis = StructuralMechanicsAnalysis(
        ca.Model(), parameters, base_dir=DATA, reporter=Reporter(quiet=True)
    )
    solver = analysis._GetSolver()
    solve = solver.SolveSolutionStep
    sub_steps: list[tuple[float, float]] = []

    def limited_solve() -> bool:
        info = solver.GetComputingModelPart().ProcessInfo
        if limit is not None and info[ca.DELTA_TIME] > limit + 1e-12:
            return False  # as if Newton had failed (nothing is solved)
        sub_steps.append((info[ca.TIME], info[ca.DELTA_TIME]))
        return solve()

    solver.SolveSolutionStep = limited_solve
    solver.StepCuttingSettings = lambda: settings
    analysis.sub_steps = sub_steps
    return analysis


def _right_edge_ux(analysis: StructuralMechanicsAnalysis) -> float:
    part = analysis.model.GetModelPart("Structure")
    return max(node.GetSolutionStepValue(ca.DISPLACEMENT_X) for node in part.Nodes)


def test_a_failed_step_is_solved_in_sub_steps_and_ends_at_its_time() -> None:
    analysis = _analysis(limit=0.2, settings=(2.0, 3))
    analysis.Run()
    steps = analysis.reporter.steps
    assert [round(s.time, 12) for s in steps] == [0.5, 1.0]
    assert all(s.converged for s in steps)
    # Each 0.5 step: 0.25 fails, 0.125 converges → sub-steps of 0.125 up to the step's time.
    times = [round(t, 12) for t, _ in analysis.sub_steps]
    assert times == [0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1.0]
    info = analysis.model.GetModelPart("Structure").ProcessInfo
    assert info[ca.TIME] == pytest.approx(1.0)
    assert info[ca.STEP] == 8  # every sub-step is a step of the history
    # The same state as an uncut run at TIME = 1 (load 2.0), i.e. the analytic plate strain.
    reference = _analysis(limit=None, settings=None)
    reference.Run()
    assert _right_edge_ux(analysis) == pytest.approx(_right_edge_ux(reference), rel=1e-12)


def test_cutting_gives_up_after_max_number_splits() -> None:
    analysis = _analysis(limit=0.01, settings=(2.0, 2))
    analysis.Run()
    assert not any(s.converged for s in analysis.reporter.steps)
    assert analysis.sub_steps == []


def test_without_cutting_a_failed_step_is_reported_and_kept() -> None:
    analysis = _analysis(limit=0.2, settings=None)
    analysis.Run()
    assert [s.converged for s in analysis.reporter.steps] == [False, False]
