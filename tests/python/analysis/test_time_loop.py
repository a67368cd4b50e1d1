"""The time loop: no extra step from round-off, and meaningless step sequences refused up front."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

import contact_app as ca
from contact_app.analysis.time_loop import MAX_STEPS, count_steps, keep_advancing
from contact_app.parameters import Parameters


def _constant(delta: float):  # type: ignore[no-untyped-def]
    return lambda time: delta


@pytest.mark.parametrize(
    ("end", "delta", "steps"),
    [(0.05, 0.005, 10), (1.0, 0.1, 10), (0.3, 0.1, 3), (0.7, 0.01, 70), (0.0501, 0.005, 11)],
)
def test_steps_that_add_up_to_end_time_stop_there(end: float, delta: float, steps: int) -> None:
    assert count_steps(0.0, end, _constant(delta), "here", constant=True) == steps


def test_keep_advancing_tolerates_round_off_only() -> None:
    assert not keep_advancing(0.049999999999999996, 0.05, 0.005)
    assert keep_advancing(0.0499, 0.05, 0.005)
    assert keep_advancing(0.0, 1.0e-12, 0.0)  # before the first step: strict


@pytest.mark.parametrize(
    ("start", "end", "delta", "fragment"),
    [
        (1.0e10, 1.0e10 + 1.0, 1.0e-10, "floating-point resolution of TIME"),
        (0.0, 1.0, 1.0e-9, "1e+09 steps from start_time 0 to end_time 1"),
        (0.0, 1.7e308, 1.5e308, "TIME would become inf"),
    ],
)
def test_meaningless_step_sequences_are_refused(
    start: float, end: float, delta: float, fragment: str
) -> None:
    with pytest.raises(ca.InputError, match="where:    here") as failure:
        count_steps(start, end, _constant(delta), "here", constant=True)
    assert fragment in str(failure.value)


def test_a_table_that_never_reaches_the_end_is_bounded() -> None:
    with pytest.raises(ca.InputError, match=f"more than {MAX_STEPS} steps"):
        count_steps(0.0, 1.0, lambda time: 1.0e-8 if time < 0.5 else 0.1, "here")


@pytest.mark.parametrize(("end", "delta", "steps"), [(0.05, 0.005, 10), (0.7, 0.1, 7)])
def test_a_run_stops_at_end_time_without_an_extra_step(
    case_dir: Path, in_tmp: Path, end: float, delta: float, steps: int
) -> None:
    path = case_dir / "plate_static_parameters.json"
    parameters = json.loads(path.read_text())
    parameters["problem_data"]["end_time"] = end
    parameters["solver_settings"]["time_stepping"] = {"time_step": delta}
    parameters["processes"].pop("json_check_process")
    path.write_text(json.dumps(parameters))
    analysis = ca.analysis.run(path, quiet=True)
    info = analysis.model.GetModelPart("Structure").ProcessInfo
    assert info[ca.STEP] == steps
    assert info[ca.TIME] == pytest.approx(end, rel=1e-12)


def test_a_nan_split_factor_built_in_python_is_refused() -> None:
    settings = Parameters({"split_factor": math.nan}, "<parameters>", ("contact_settings",))
    with pytest.raises(ca.InputError, match="contact_settings › split_factor"):
        settings.ValidateAndAssignDefaults({"split_factor": 10.0})
