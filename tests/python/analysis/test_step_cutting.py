"""A step that does not converge is redone in sub-steps from the last converged state.

The solver decides (``StepCuttingSettings``; the contact solvers return ``split_factor`` and
``max_number_splits`` when ``adaptative_strategy`` is set). Here a solver that fails every step
longer than a limit checks the mechanics on the plate case, whose load grows with time (the
converged state at a time does not depend on the path).
"""

from __future__ import annotations

import importlib.util
import shutil
from pathlib import Path

import numpy as np
import pytest
from analysis_cases import DATA

import contact_app as ca
from contact_app.analysis import StructuralMechanicsAnalysis
from contact_app.analysis.reporting import Reporter
from contact_app.parameters import Parameters


def _limit(
    analysis: StructuralMechanicsAnalysis,
    limit: float | None,
    settings: tuple[float, int] | None,
    fails_after: float | None = None,
) -> StructuralMechanicsAnalysis:
    """Fail every solve longer than ``limit`` or beyond TIME ``fails_after``, as Newton would."""
    solver = analysis._GetSolver()
    solve = solver.SolveSolutionStep
    sub_steps: list[tuple[float, float]] = []

    def limited_solve() -> bool:
        info = solver.GetComputingModelPart().ProcessInfo
        if limit is not None and info[ca.DELTA_TIME] > limit + 1e-12:
            return False  # as if Newton had failed (nothing is solved)
        if fails_after is not None and info[ca.TIME] > fails_after + 1e-12:
            # As if Newton had diverged: an iterate that is not the solution.
            for node in solver.GetComputingModelPart().Nodes:
                node.SetSolutionStepValue(ca.DISPLACEMENT_X, 1.0e3)
            return False
        sub_steps.append((info[ca.TIME], info[ca.DELTA_TIME]))
        return solve()

    solver.SolveSolutionStep = limited_solve
    solver.StepCuttingSettings = lambda: settings
    analysis.sub_steps = sub_steps
    return analysis


def _analysis(
    limit: float | None,
    settings: tuple[float, int] | None,
    fails_after: float | None = None,
    end_time: float = 1.0,
) -> StructuralMechanicsAnalysis:
    parameters = Parameters.from_file(DATA / "plate_static_parameters.json")
    parameters.AddValue("output_processes", {})
    parameters["processes"].AddValue("json_check_process", [])
    parameters["problem_data"]["end_time"].SetDouble(end_time)
    # One step when the run ends early (a reference state at that time).
    parameters["solver_settings"]["time_stepping"]["time_step"].SetDouble(
        0.5 if end_time == 1.0 else end_time
    )
    analysis = StructuralMechanicsAnalysis(
        ca.Model(), parameters, base_dir=DATA, reporter=Reporter(quiet=True)
    )
    return _limit(analysis, limit, settings, fails_after)


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
    """Nothing converges: the run stops at the start, with the start's state and time."""
    analysis = _analysis(limit=0.01, settings=(2.0, 2))
    with pytest.raises(ca.ConvergenceError, match="(?s)step cutting gave up.*TIME = 0 "):
        analysis.Run()
    assert [(s.time, s.converged) for s in analysis.reporter.steps] == [(0.0, False)]
    assert analysis.sub_steps == []
    part = analysis.model.GetModelPart("Structure")
    assert part.ProcessInfo[ca.TIME] == 0.0
    assert _right_edge_ux(analysis) == 0.0


def test_a_cutting_that_gives_up_leaves_the_last_converged_state_at_its_time() -> None:
    """Sub-steps converge up to TIME 0.75, then fail: state, loads and TIME are those of 0.75.

    Before, the step was recorded at TIME 1.0 with the loads of the last failed sub-step.
    """
    analysis = _analysis(limit=None, settings=(2.0, 2), fails_after=0.8)
    with pytest.raises(ca.ConvergenceError, match=r"(?s)TIME = 1 was not reached.*TIME = 0\.75 "):
        analysis.Run()
    steps = analysis.reporter.steps
    assert [(round(s.time, 12), s.converged) for s in steps] == [(0.5, True), (0.75, False)]
    part = analysis.model.GetModelPart("Structure")
    assert part.ProcessInfo[ca.TIME] == pytest.approx(0.75)
    loads = [
        c.GetValue(ca.LINE_LOAD)[0] for c in part.GetSubModelPart("LineLoad2D_right").Conditions
    ]
    assert loads and loads == pytest.approx([2.0 * 0.75] * len(loads))
    reference = _analysis(limit=None, settings=None, end_time=0.75)
    reference.Run()
    assert _right_edge_ux(analysis) == pytest.approx(_right_edge_ux(reference), rel=1e-12)


def test_without_cutting_a_failed_step_stops_the_run_by_default() -> None:
    analysis = _analysis(limit=0.2, settings=None)
    with pytest.raises(ca.ConvergenceError, match='on_non_converged_step is "stop", the default'):
        analysis.Run()
    assert [s.converged for s in analysis.reporter.steps] == [False]


def test_without_cutting_a_failed_step_is_kept_when_the_settings_say_continue() -> None:
    parameters = Parameters.from_file(DATA / "plate_static_parameters.json")
    parameters.AddValue("output_processes", {})
    parameters["processes"].AddValue("json_check_process", [])
    parameters["solver_settings"].AddValue("on_non_converged_step", "continue")
    analysis = StructuralMechanicsAnalysis(
        ca.Model(), parameters, base_dir=DATA, reporter=Reporter(quiet=True)
    )
    _limit(analysis, limit=1e-3, settings=None)
    analysis.Run()
    assert [s.converged for s in analysis.reporter.steps] == [False, False]


HERTZ_2D = Path(__file__).parents[3] / "examples" / "hertz_2d"


def test_hertz_2d_cutting_that_gives_up_stops_at_the_last_converged_sub_step(
    tmp_path: Path,
) -> None:
    """The 2D Hertz example with step cutting, its sub-steps failing beyond TIME 0.8.

    Before: the step was written at TIME 1.0 with LINE_LOAD -4.689 (the last failed sub-step's).
    Now: the run stops with TIME 0.8, LINE_LOAD -6.25 * 0.8 and the displacements of the
    converged sub-step at 0.8; the VTK output ends at step 3 (TIME 0.75).
    """
    spec = importlib.util.spec_from_file_location("hertz_2d_make_mesh", HERTZ_2D / "make_mesh.py")
    make_mesh = importlib.util.module_from_spec(spec)
    assert spec.loader is not None
    spec.loader.exec_module(make_mesh)
    make_mesh.write_mesh(tmp_path / "hertz_2d.msh", 1)
    shutil.copy(HERTZ_2D / "materials.json", tmp_path)
    parameters = Parameters.from_file(HERTZ_2D / "ProjectParameters.json")
    parameters["solver_settings"]["contact_settings"].AddValue("adaptative_strategy", True)
    output = parameters["output_processes"]["vtk_output"][0]["Parameters"]
    output["output_path"].SetString(str(tmp_path / "vtk_output"))
    analysis = StructuralMechanicsAnalysis(
        ca.Model(), parameters, base_dir=tmp_path, reporter=Reporter(quiet=True)
    )
    solver = analysis._GetSolver()
    _limit(analysis, None, solver.StepCuttingSettings(), fails_after=0.8)
    part = analysis.model.GetModelPart("Structure")
    converged: dict[float, np.ndarray] = {}
    finalize = analysis.FinalizeSolutionStep

    def remember() -> None:
        values = [node.GetSolutionStepValue(ca.DISPLACEMENT) for node in part.Nodes]
        converged[round(part.ProcessInfo[ca.TIME], 12)] = np.array(values)
        finalize()

    analysis.FinalizeSolutionStep = remember
    with pytest.raises(ca.ConvergenceError, match=r"(?s)TIME = 1 was not reached.*TIME = 0\.8 "):
        analysis.Run()
    assert [(round(s.time, 12), s.converged) for s in analysis.reporter.steps] == [
        (0.25, True),
        (0.5, True),
        (0.75, True),
        (0.8, False),
    ]
    assert part.ProcessInfo[ca.TIME] == pytest.approx(0.8)
    top = part.GetSubModelPart("LineLoad2D_top").Conditions
    assert [c.GetValue(ca.LINE_LOAD)[1] for c in top] == pytest.approx([-6.25 * 0.8] * len(top))
    restored = np.array([node.GetSolutionStepValue(ca.DISPLACEMENT) for node in part.Nodes])
    assert np.array_equal(restored, converged[0.8])
    assert np.abs(restored[:, 1]).max() > 1e-3  # the state of a loaded contact, not the start
    assert len(list((tmp_path / "vtk_output").glob("*.vtu"))) == 3
