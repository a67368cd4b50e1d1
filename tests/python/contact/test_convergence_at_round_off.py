"""Convergence criteria in the round-off regime (issue 16).

A step whose load did not change since the last converged one starts at a residual that is itself
round-off: the ratio to it cannot fall, and the absolute tolerance (1e-9) is below the round-off
of nodal forces of order 1e9 (E = 2e11 on the reference patch). The criteria measure their ratio
against the residual before the first correction and accept a correction at round-off of the
state it corrects (RoundOffBound, docs/theory/convergence_criteria.md).
"""

from __future__ import annotations

import json
import time
from pathlib import Path

import numpy as np
import pytest
from test_kratos_contact_cases import CASES, CASES_DIR

import contact_app as ca
from contact_app.analysis import StructuralMechanicsAnalysis
from contact_app.analysis.reporting import Reporter
from contact_app.parameters import Parameters

PATCH = CASES_DIR / f"{CASES['alm_frictionless_2d_hyper_simple']}_parameters.json"
CYLINDERS = CASES_DIR.parent / "kratos_examples" / "cylinders" / "source" / "vertical_movement"
#: The reference converges each step of the vertical cylinders in 3 iterations.
MAX_ITERATIONS = 3


def _patch(
    steps: int, values: dict[str, list[object]] | None = None
) -> StructuralMechanicsAnalysis:
    """The reference patch in ``steps`` steps to TIME 1, with constraint ``values`` replaced."""
    parameters = Parameters.from_file(PATCH)
    parameters.AddValue("output_processes", {})
    parameters["processes"].AddValue("json_check_process", [])
    parameters["solver_settings"]["time_stepping"]["time_step"].SetDouble(1.0 / steps)
    for process in parameters["processes"]["constraints_process_list"]:
        name = process["Parameters"]["model_part_name"].GetString()
        if values and name in values:
            process["Parameters"].AddValue("value", values[name])
    analysis = StructuralMechanicsAnalysis(
        ca.Model(), parameters, base_dir=PATCH.parent, reporter=Reporter(quiet=True)
    )
    analysis.Run()
    return analysis


def _displacements(analysis: StructuralMechanicsAnalysis) -> np.ndarray:
    part = analysis.model.GetModelPart("Structure")
    return np.array([node.GetSolutionStepValue(ca.DISPLACEMENT) for node in part.Nodes])


def _assert_fast(analysis: StructuralMechanicsAnalysis) -> None:
    steps = analysis.reporter.steps
    assert all(step.converged for step in steps), [step.iterations for step in steps]
    assert max(step.iterations for step in steps) <= MAX_ITERATIONS, [s.iterations for s in steps]


pytestmark = pytest.mark.skipif(not PATCH.is_file(), reason="../shared/kratos_cases missing")


@pytest.fixture(scope="module")
def one_step() -> np.ndarray:
    return _displacements(_patch(1))


@pytest.mark.parametrize("steps", [10, 20, 50])
def test_patch_held_at_its_displacement_converges_every_step(steps: int, one_step) -> None:
    """The imposed displacement from the first step on: every later step is at round-off."""
    analysis = _patch(steps)
    _assert_fast(analysis)
    assert np.abs(_displacements(analysis) - one_step).max() < 1e-12


@pytest.mark.parametrize("steps", [10, 20, 50])
def test_patch_ramped_to_its_displacement_converges_every_step(steps: int, one_step) -> None:
    """The same final displacement reached in equal increments."""
    analysis = _patch(steps, {"Structure.IMPOSE_DISP_Auto1": [0.0, "-0.01*t", 0.0]})
    _assert_fast(analysis)
    assert np.abs(_displacements(analysis) - one_step).max() < 1e-12


def test_rigid_translation_of_the_pressed_patch_converges_at_once() -> None:
    """Press in the first half, then translate everything by (3e-3, 2e-3): a rigid motion."""
    x, y = "3e-3*max(2*t-1,0)", "2e-3*max(2*t-1,0)"
    analysis = _patch(
        2,
        {
            "Structure.DISPLACEMENT_Displacement_Auto1": [x, y, 0.0],
            "Structure.DISPLACEMENT_Displacement_Auto2": [x, y, 0.0],
            "Structure.IMPOSE_DISP_Auto1": [x, f"-0.01+{y}", 0.0],
        },
    )
    _assert_fast(analysis)
    pressed = _patch(1)
    moved = _displacements(analysis) - _displacements(pressed)
    assert np.abs(moved - [3e-3, 2e-3, 0.0]).max() < 1e-12


@pytest.mark.skipif(not CYLINDERS.is_dir(), reason="../shared/kratos_examples missing")
def test_vertical_cylinders_converge_in_few_iterations(tmp_path: Path) -> None:
    """Nodal forces of order 1e10: round-off in 3 iterations per step, as in the reference."""
    parameters = json.loads((CYLINDERS / "ProjectParameters.json").read_text())
    parameters["problem_data"]["end_time"] = 0.05
    parameters["output_processes"] = {}
    case = tmp_path / "ProjectParameters.json"
    case.write_text(json.dumps(parameters))
    for name in ("StructuralMaterials.json", "cylinders.mdpa"):
        (tmp_path / name).symlink_to(CYLINDERS / name)
    analysis = StructuralMechanicsAnalysis(
        ca.Model(), Parameters.from_file(case), base_dir=tmp_path, reporter=Reporter(quiet=True)
    )
    start = time.perf_counter()
    analysis.Run()
    steps = analysis.reporter.steps
    print(
        f"\n{len(steps)} steps, iterations {[s.iterations for s in steps]}, "
        f"{time.perf_counter() - start:.2f} s"
    )
    assert len(steps) >= 10
    _assert_fast(analysis)
