"""Analysis stage life cycle: hook order, strict time loop, time-step tables, output steps."""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any

import pytest
from analysis_cases import load

import contact_app as ca
from contact_app.analysis import StructuralMechanicsAnalysis
from contact_app.parameters import Parameters

RECORDER = '''"""A user process module (no kratos_module) that records the hooks it receives."""

CALLS = []


class Recorder:
    def __init__(self, model, settings):
        self.name = settings["name"].GetString()
        self.every = settings["output_every"].GetInt() if settings.Has("output_every") else 0
        self.info = model.GetModelPart("Structure").ProcessInfo

    def _log(self, hook):
        from contact_app import DELTA_TIME, STEP, TIME

        CALLS.append((self.name, hook, self.info[STEP], self.info[TIME], self.info[DELTA_TIME]))

    def __getattr__(self, hook):
        if hook.startswith("Execute") or hook == "Check":
            return lambda: self._log(hook)
        raise AttributeError(hook)


class OutputRecorder(Recorder):
    def IsOutputStep(self):
        from contact_app import STEP

        return self.info[STEP] % self.every == 0

    def PrintOutput(self):
        self._log("PrintOutput")


def Factory(settings, model):
    parameters = settings["Parameters"]
    cls = OutputRecorder if parameters.Has("output_every") else Recorder
    return cls(model, parameters)
'''


def _recorder(name: str, output_every: int = 0) -> dict[str, Any]:
    parameters: dict[str, Any] = {"name": name}
    if output_every:
        parameters["output_every"] = output_every
    return {"python_module": "recording_process", "Parameters": parameters}


@pytest.fixture
def recording_case(case_dir: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """The static plate without result checks and VTK, plus recorders; cwd = the case folder."""
    (case_dir / "recording_process.py").write_text(RECORDER)
    sys.modules.pop("recording_process", None)
    monkeypatch.chdir(case_dir)
    return case_dir


def _plate(case_dir: Path, **time: Any) -> dict[str, Any]:
    parameters = load(case_dir / "plate_static_parameters.json")
    del parameters["processes"]["json_check_process"]
    del parameters["output_processes"]
    parameters["problem_data"].update({k: v for k, v in time.items() if k != "time_stepping"})
    if "time_stepping" in time:
        parameters["solver_settings"]["time_stepping"] = time["time_stepping"]
    return parameters


def _calls() -> list[tuple[Any, ...]]:
    return sys.modules["recording_process"].CALLS


def test_hooks_follow_the_kratos_order(recording_case: Path) -> None:
    parameters = _plate(recording_case)
    parameters["processes"]["other"] = [_recorder("p")]
    parameters["output_processes"] = {"out": [_recorder("o", output_every=2)]}
    analysis = StructuralMechanicsAnalysis(ca.Model(), parameters)
    solver = analysis._GetSolver()
    for method in (
        "ImportModelPart",
        "PrepareModelPart",
        "AddDofs",
        "Initialize",
        "Check",
        "AdvanceInTime",
        "InitializeSolutionStep",
        "Predict",
        "SolveSolutionStep",
        "FinalizeSolutionStep",
        "Finalize",
    ):
        original = getattr(solver, method)

        def wrapped(*args: Any, _original: Any = original, _method: str = method) -> Any:
            _calls().append(("solver", _method))
            return _original(*args)

        setattr(solver, method, wrapped)
    _calls().clear()
    analysis.Run()
    sequence = [f"{c[0]}.{c[1]}" for c in _calls()]
    step = [
        "solver.AdvanceInTime",
        "p.ExecuteInitializeSolutionStep",
        "o.ExecuteInitializeSolutionStep",
        "solver.InitializeSolutionStep",
        "solver.Predict",
        "solver.SolveSolutionStep",
        "solver.FinalizeSolutionStep",
        "p.ExecuteFinalizeSolutionStep",
        "o.ExecuteFinalizeSolutionStep",
    ]
    output = ["p.ExecuteBeforeOutputStep", "o.ExecuteBeforeOutputStep", "o.PrintOutput"]
    output += ["p.ExecuteAfterOutputStep", "o.ExecuteAfterOutputStep"]
    assert sequence == [
        "solver.ImportModelPart",
        "solver.PrepareModelPart",
        "solver.AddDofs",
        "p.ExecuteInitialize",
        "o.ExecuteInitialize",
        "solver.Initialize",
        "solver.Check",
        "p.Check",
        "o.Check",
        "p.ExecuteBeforeSolutionLoop",
        "o.ExecuteBeforeSolutionLoop",
        *step,  # step 1: no output step, so no Before/After output hooks
        *step,
        *output,
        "p.ExecuteFinalize",
        "o.ExecuteFinalize",
        "solver.Finalize",
    ]


@pytest.mark.parametrize(
    ("end_time", "time_step", "times"),
    [
        (1.0, 1.01, [1.01]),
        (0.99, 1.0, [1.0]),
        (1.0, 0.5005, [0.5005, 1.001]),
        (1.0, 0.5, [0.5, 1.0]),
    ],
)
def test_loop_runs_while_time_is_strictly_below_end_time(
    recording_case: Path, end_time: float, time_step: float, times: list[float]
) -> None:
    parameters = _plate(recording_case, end_time=end_time, time_stepping={"time_step": time_step})
    analysis = ca.analysis.run(parameters, quiet=True)
    assert [r.time for r in analysis.reporter.steps] == pytest.approx(times)
    assert [r.step for r in analysis.reporter.steps] == list(range(1, len(times) + 1))


def test_step_time_and_delta_time_with_a_start_time(recording_case: Path) -> None:
    parameters = _plate(recording_case, start_time=1.0, end_time=2.0)
    parameters["processes"]["other"] = [_recorder("p")]
    ca.analysis.run(parameters, quiet=True)
    steps = [c[2:] for c in _calls() if c[1] == "ExecuteInitializeSolutionStep"]
    assert steps == [(1, 1.5, 0.5), (2, 2.0, 0.5)]
    before = [c[2:] for c in _calls() if c[1] == "ExecuteBeforeSolutionLoop"]
    assert before == [(0, 0.0, 0.0)]  # TIME is set to start_time after the processes' hook


def test_end_time_equal_to_start_time_solves_nothing(
    recording_case: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    analysis = ca.analysis.run(_plate(recording_case, end_time=0.0))
    assert analysis.reporter.steps == []
    assert "no step to solve" in capsys.readouterr().out


def test_time_step_table_is_interpolated_at_the_current_time(recording_case: Path) -> None:
    table = [[0.0, 0.25], [1.0, 0.5]]
    parameters = _plate(recording_case, time_stepping={"time_step_table": table})
    analysis = ca.analysis.run(parameters, quiet=True)
    expected, time = [], 0.0
    while time < 1.0:
        time += 0.25 + 0.25 * time
        expected.append(time)
    assert [r.time for r in analysis.reporter.steps] == pytest.approx(expected)


def test_legacy_time_step_intervals_first_match_wins(
    recording_case: Path, caplog: pytest.LogCaptureFixture
) -> None:
    intervals = {
        "first": {"interval": [0.0, 0.5], "time_step": 0.25},
        "second": {"interval": [0.5, "End"], "time_step": 0.5},
    }
    parameters = _plate(recording_case, time_stepping={"time_step_intervals": intervals})
    analysis = ca.analysis.run(parameters, quiet=True)
    assert [r.time for r in analysis.reporter.steps] == pytest.approx([0.25, 0.5, 1.0])
    assert "time_step_intervals is deprecated" in caplog.text


def test_stage_requires_a_model() -> None:
    with pytest.raises(TypeError, match="contact_app.Model"):
        StructuralMechanicsAnalysis("model", {})  # type: ignore[arg-type]


def test_parameters_object_is_completed_in_place(recording_case: Path) -> None:
    parameters = Parameters(json.dumps(_plate(recording_case)))
    StructuralMechanicsAnalysis(ca.Model(), parameters)
    settings = parameters["solver_settings"]
    assert settings["builder_and_solver_settings"]["type"].GetString() == "block"
    assert settings["buffer_size"].GetInt() == 2
    assert not settings.Has("line_search")
