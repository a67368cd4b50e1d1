"""Restart files: restarted runs equal continuous ones bit for bit; damaged files are refused."""

from __future__ import annotations

import filecmp
import importlib.util
import json
import os
import shutil
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import contact_app as ca
from contact_app.analysis import StructuralMechanicsAnalysis
from contact_app.analysis.reporting import Reporter
from contact_app.io.restart_utility import Inspect, Load, RestartFile

ROOT = Path(__file__).parents[3]
HERTZ = ROOT / "examples" / "hertz_2d"


def _stick_slip_module() -> Any:
    folder = ROOT / "tests" / "python" / "contact"
    sys.path.insert(0, str(folder))
    spec = importlib.util.spec_from_file_location(
        "_stick_slip_case", folder / "test_frictional_stick_slip.py"
    )
    module = importlib.util.module_from_spec(spec)
    assert spec.loader is not None
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


def _run(parameters: dict, end: float, **options: Any) -> StructuralMechanicsAnalysis:
    run = json.loads(json.dumps(parameters))
    run["problem_data"]["end_time"] = end
    run["restart_options"] = options
    analysis = StructuralMechanicsAnalysis(ca.Model(), run, reporter=Reporter(quiet=True))
    analysis.Run()
    return analysis


def _state(analysis: StructuralMechanicsAnalysis) -> dict[str, np.ndarray]:
    part = analysis.model.GetModelPart("Structure")
    names = [
        "DISPLACEMENT",
        "REACTION",
        "VECTOR_LAGRANGE_MULTIPLIER",
        "LAGRANGE_MULTIPLIER_CONTACT_PRESSURE",
    ]
    state: dict[str, np.ndarray] = {}
    for name in names:
        variable = ca.get_variable(name)
        if part.HasNodalSolutionStepVariable(variable):
            state[name] = np.array(
                [np.atleast_1d(n.GetSolutionStepValue(variable)) for n in part.Nodes]
            )
    state["ACTIVE"] = np.array([n.Is(ca.ACTIVE) for n in part.Nodes])
    state["SLIP"] = np.array([n.Is(ca.SLIP) for n in part.Nodes])
    info = part.ProcessInfo
    state["TIME_STEP"] = np.array([info[ca.TIME], info[ca.STEP]])
    return state


def _assert_identical(first: dict[str, np.ndarray], second: dict[str, np.ndarray]) -> None:
    assert first.keys() == second.keys()
    for name, values in first.items():
        np.testing.assert_array_equal(values, second[name], err_msg=name)


def _restarted_equals_continuous(
    parameters: dict, directory: Path, monkeypatch: pytest.MonkeyPatch, end: float, half: float
) -> tuple[Path, Path]:
    continuous, restarted = directory / "continuous", directory / "restarted"
    for folder in (continuous, restarted):
        folder.mkdir()
    monkeypatch.chdir(continuous)
    reference = _state(_run(parameters, end))
    monkeypatch.chdir(restarted)
    first = _run(parameters, half, SaveRestart=True)
    assert _state(first)["TIME_STEP"][0] == pytest.approx(half)
    resumed = _run(parameters, end, LoadRestart=True, **{"Restart Step": half})
    _assert_identical(reference, _state(resumed))
    return continuous, restarted


def test_hertz_2d_restart_is_bit_identical_with_its_outputs(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    spec = importlib.util.spec_from_file_location("hertz_make_mesh", HERTZ / "make_mesh.py")
    make_mesh = importlib.util.module_from_spec(spec)
    assert spec.loader is not None
    spec.loader.exec_module(make_mesh)
    parameters = json.loads((HERTZ / "ProjectParameters.json").read_text())
    for folder in ("continuous", "restarted"):  # inputs are read from the working directory
        (tmp_path / folder).mkdir()
        shutil.copy(HERTZ / "materials.json", tmp_path / folder)
        make_mesh.write_mesh(str(tmp_path / folder / "hertz_2d.msh"), 1)
    continuous, restarted = tmp_path / "continuous", tmp_path / "restarted"
    monkeypatch.chdir(continuous)
    reference = _state(_run(parameters, 1.0))
    monkeypatch.chdir(restarted)
    _run(parameters, 0.5, SaveRestart=True)
    files = sorted(p.name for p in (restarted / "hertz_2d__restart_files").iterdir())
    assert files == ["hertz_2d_0.25.rest", "hertz_2d_0.5.rest"]
    resumed = _run(parameters, 1.0, LoadRestart=True, **{"Restart Step": 0.5})
    _assert_identical(reference, _state(resumed))
    written = sorted(p.name for p in (continuous / "vtk_output").iterdir())
    assert written == sorted(p.name for p in (restarted / "vtk_output").iterdir())
    for name in written:  # the .vtu of every step and the .pvd collection
        assert filecmp.cmp(
            continuous / "vtk_output" / name, restarted / "vtk_output" / name, shallow=False
        ), name


def test_frictional_stick_slip_restart_is_bit_identical(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    case = _stick_slip_module()
    case._write_case(tmp_path, case.NON_MATCHING, case.MU)
    parameters = case._parameters(tmp_path, "ALMContactFrictional", 2)
    _restarted_equals_continuous(parameters, tmp_path, monkeypatch, 4.0, 2.0)
    # The slipping steps are 3 and 4: the restart carried the stick/slip state across.
    assert (tmp_path / "restarted" / "stick_slip__restart_files" / "stick_slip_2.0.rest").is_file()


def test_updated_lagrangian_restart_is_bit_identical(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """An updated-Lagrangian element measures F from its last F0: the restart carries it.

    Without it the restarted elements started again from F0 = I (the hyperelastic tubes of the
    example collection: 4 instead of 5 active nodes one step after a restart).
    """
    case = _stick_slip_module()
    case._write_case(tmp_path, case.NON_MATCHING, case.MU)
    mesh = tmp_path / "stick_slip.mdpa"
    text = mesh.read_text()
    assert "SmallDisplacementElement2D4N" in text
    mesh.write_text(text.replace("SmallDisplacementElement2D4N", "UpdatedLagrangianElement2D4N"))
    parameters = case._parameters(tmp_path, "ALMContactFrictional", 2)
    _restarted_equals_continuous(parameters, tmp_path, monkeypatch, 4.0, 2.0)


def _checkpoint(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> tuple[dict, Path]:
    case = _stick_slip_module()
    case._write_case(tmp_path, case.NON_MATCHING, case.MU)
    parameters = case._parameters(tmp_path, "ALMContactFrictional", 2)
    monkeypatch.chdir(tmp_path)
    _run(parameters, 1.0, SaveRestart=True)
    return parameters, RestartFile("stick_slip", "1.0")


@pytest.mark.parametrize("damage", ["truncated", "bit_flipped", "empty", "foreign"])
def test_damaged_restart_file_is_refused_naming_it(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, damage: str
) -> None:
    parameters, path = _checkpoint(tmp_path, monkeypatch)
    data = bytearray(path.read_bytes())
    if damage == "truncated":
        data = data[: len(data) * 2 // 3]
    elif damage == "bit_flipped":
        data[len(data) // 2] ^= 0x04
    elif damage == "empty":
        data = bytearray()
    else:
        data = bytearray(b"Begin ModelPartData\nEnd ModelPartData\n" * 4)
    path.write_bytes(bytes(data))
    model = ca.Model()
    part = model.CreateModelPart("Structure")
    with pytest.raises(ca.InputError, match=str(path).replace(".", r"\.")):
        Load(part, path)
    assert part.NumberOfNodes() == 0 and part.NumberOfSubModelParts() == 0
    run = json.loads(json.dumps(parameters))
    run["restart_options"] = {"LoadRestart": True, "Restart Step": 1.0}
    with pytest.raises(ca.InputError, match="stick_slip_1.0.rest"):
        StructuralMechanicsAnalysis(ca.Model(), run, reporter=Reporter(quiet=True))


def test_restart_into_another_model_part_name_is_refused(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    _, path = _checkpoint(tmp_path, monkeypatch)
    assert Inspect(path)["model_part_name"] == "Structure"
    part = ca.Model().CreateModelPart("Body")
    with pytest.raises(ca.InputError, match='holds the model part "Structure", not "Body"'):
        Load(part, path)
    assert part.NumberOfNodes() == 0


_WRITER = textwrap.dedent(
    """
    import os, sys, time
    import contact_app as ca
    from contact_app.io import restart_utility
    replace = os.replace
    def slow_replace(source, destination):
        open(sys.argv[2], "w").close()  # tell the test: the temporary file is complete
        time.sleep(60)
        replace(source, destination)
    os.replace = slow_replace
    model = ca.Model()
    part = model.CreateModelPart("Structure")
    restart_utility.Load(part, sys.argv[1])
    part.ProcessInfo[ca.STEP] = 99
    data = ca._core.SaveCheckpoint(part)
    restart_utility.WriteAtomically(restart_utility.Path(sys.argv[1]), data)
    """
)


def test_kill_while_writing_leaves_the_last_checkpoint_loadable(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    _, path = _checkpoint(tmp_path, monkeypatch)
    before = path.read_bytes()
    ready = tmp_path / "ready"
    writer = subprocess.Popen([sys.executable, "-c", _WRITER, str(path), str(ready)], cwd=tmp_path)
    deadline = time.monotonic() + 120
    while not ready.exists():
        assert writer.poll() is None, "the writer ended before the pause"
        assert time.monotonic() < deadline
        time.sleep(0.05)
    os.kill(writer.pid, signal.SIGKILL)
    writer.wait()
    assert path.read_bytes() == before
    leftovers = [p.name for p in path.parent.iterdir() if p.name.endswith(".tmp")]
    assert leftovers  # the killed writer's complete but unrenamed temporary file
    part = ca.Model().CreateModelPart("Structure")
    Load(part, path)
    assert part.ProcessInfo[ca.STEP] == 1 and part.NumberOfNodes() > 0
