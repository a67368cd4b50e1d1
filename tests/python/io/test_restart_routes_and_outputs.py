"""Restart of the MPC route and of mesh tying, and outputs that continue the run's files.

Each case runs N steps in one go and N/2 steps + restart + N/2 steps; the nodal results, flags
and the output files must be bit-identical. The MPC route keeps its pairs' constraints (relation,
test relation, DoFs, BLOCKED) and the stick/slip state in the restart file; mesh tying keeps the
operators it integrated on the undeformed pair.
"""

from __future__ import annotations

import filecmp
import json
from pathlib import Path

import numpy as np
import pytest
from test_restart_utility import _assert_identical, _run, _state, _stick_slip_module

import contact_app as ca
from contact_app.io.restart_utility import RestartFile

CASES_DIR = Path(__file__).resolve().parents[3].parent / "shared" / "kratos_cases"
MPC_CASE = "mpc_contact_tests/2D_contact_simplest_patch_matching_test"
TYING_CASE = "mesh_tying_test/simple_patch_test_2D"

needs_cases = pytest.mark.skipif(not CASES_DIR.is_dir(), reason="../shared/kratos_cases missing")


def _reference_case(case: str, time_step: float, imposed: list | None = None) -> dict:
    """A case of ../shared/kratos_cases in steps of ``time_step``, inputs by absolute path."""
    parameters = json.loads((CASES_DIR / f"{case}_parameters.json").read_text())
    solver = parameters["solver_settings"]
    for block, key in (
        ("model_import_settings", "input_filename"),
        ("material_import_settings", "materials_filename"),
    ):
        solver[block][key] = str(CASES_DIR / solver[block][key])
    solver["time_stepping"]["time_step"] = time_step
    parameters["output_processes"] = {}
    parameters["processes"]["json_check_process"] = []
    if imposed is not None:
        parameters["processes"]["constraints_process_list"][-1]["Parameters"]["value"] = imposed
    return parameters


def _constraints(analysis) -> list[tuple[int, bool]]:
    part = analysis.model.GetModelPart("Structure")
    return [(c.Id, c.Is(ca.ACTIVE)) for c in part.MasterSlaveConstraints]


def _continuous_and_restarted(
    parameters: dict, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, end: float, half: float
) -> tuple:
    for folder in ("continuous", "restarted"):
        (tmp_path / folder).mkdir()
    monkeypatch.chdir(tmp_path / "continuous")
    continuous = _run(parameters, end)
    monkeypatch.chdir(tmp_path / "restarted")
    _run(parameters, half, SaveRestart=True)
    restarted = _run(parameters, end, LoadRestart=True, **{"Restart Step": half})
    _assert_identical(_state(continuous), _state(restarted))
    return continuous, restarted


@needs_cases
def test_mpc_contact_restart_is_bit_identical(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The frictionless MPC patch pressed in 4 steps, restarted after 2."""
    parameters = _reference_case(MPC_CASE, 0.25)
    continuous, restarted = _continuous_and_restarted(parameters, tmp_path, monkeypatch, 1.0, 0.5)
    # The restarted run kept the saved pair and its one constraint (a new search object used to
    # erase the pair and add a second constraint next to the restored one).
    assert _constraints(continuous) == _constraints(restarted) == [(1, True)]
    part = restarted.model.GetModelPart("Structure")
    assert [c.Is(ca.BLOCKED) for c in part.GetSubModelPart("ComputingContact").Conditions] == [True]


@needs_cases
def test_mpc_frictional_restart_carries_the_slip_state(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The MPC stick-slip block restarted between its slipping steps 4 and 5.

    The slipping nodes' constraints carry a test relation (the Coulomb force, BLOCKED into step 5);
    a restart file without it (format version 1) ended step 5 elsewhere in 201 of 351 values.
    """
    case = _stick_slip_module()
    case._write_case(tmp_path, case.NON_MATCHING, case.MU)
    parameters = case._parameters(tmp_path, case.MPC, 2)
    continuous, _ = _continuous_and_restarted(parameters, tmp_path, monkeypatch, 5.0, 4.0)
    slipping = _state(continuous)["SLIP"] & _state(continuous)["ACTIVE"]
    assert slipping.any()


@needs_cases
def test_mesh_tying_restart_is_bit_identical(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The tied patch loaded in 4 steps (move_mesh), restarted after 2: same tying operators."""
    parameters = _reference_case(TYING_CASE, 0.25, [0.0, "-0.01*t", None])
    _continuous_and_restarted(parameters, tmp_path, monkeypatch, 1.0, 0.5)


def _with_outputs(
    parameters: dict,
    check_file: Path | None = None,
    slave: str = "Structure.Contact_Part_Slave",
    vtk_control: tuple[str, float] = ("step", 1),
) -> dict:
    """JSON output of ``slave`` every step, VTK output by ``vtk_control``; optionally a check."""
    run = json.loads(json.dumps(parameters))
    run["processes"]["json_output"] = [
        {
            "python_module": "json_output_process",
            "kratos_module": "KratosMultiphysics",
            "Parameters": {
                "output_variables": ["DISPLACEMENT_X", "DISPLACEMENT_Y", "REACTION_Y"],
                "output_file_name": "results.json",
                "model_part_name": slave,
                "time_frequency": 0.0,
            },
        }
    ]
    run["output_processes"] = {
        "vtk_output": [
            {
                "python_module": "vtk_output_process",
                "kratos_module": "KratosMultiphysics",
                "Parameters": {
                    "model_part_name": "Structure",
                    "output_control_type": vtk_control[0],
                    "output_interval": vtk_control[1],
                    "folder_name": "vtk_output",
                    "nodal_solution_step_data_variables": ["DISPLACEMENT", "REACTION"],
                },
            }
        ],
    }
    if check_file is not None:
        run["processes"]["json_check_process"] = [
            {
                "python_module": "from_json_check_result_process",
                "kratos_module": "KratosMultiphysics",
                "Parameters": {
                    "check_variables": ["DISPLACEMENT_X", "DISPLACEMENT_Y"],
                    "input_file_name": str(check_file),
                    "model_part_name": "Structure.Contact_Part_Slave",
                    "time_frequency": 0.3,
                    "tolerance": 0.0,
                    "relative_tolerance": 0.0,
                },
            }
        ]
    return run


def _check_process(analysis):
    from contact_app.processes.from_json_check_result_process import FromJsonCheckResultProcess

    return next(
        p for p in analysis._GetListOfProcesses() if isinstance(p, FromJsonCheckResultProcess)
    )


@needs_cases
def test_outputs_continue_the_files_of_the_interrupted_run(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """json_output, VTK and a result check over the whole run equal the continuous run's.

    The first run saves at step 2 (TIME 0.5) only and goes on to step 3 before it stops, as a run
    killed after its next outputs: the restarted run must drop that step from the files, continue
    the JSON file and the VTK collection, and the result check must check at the same TIMEs.
    """
    for folder in ("continuous", "restarted"):
        (tmp_path / folder).mkdir()
    base = _reference_case(MPC_CASE, 0.25)
    monkeypatch.chdir(tmp_path / "continuous")
    reference = tmp_path / "continuous" / "results.json"
    _run(_with_outputs(base), 1.0)
    reference_copy = tmp_path / "reference.json"
    reference_copy.write_bytes(reference.read_bytes())
    continuous = _run(_with_outputs(base, reference_copy), 1.0)
    assert reference.read_bytes() == reference_copy.read_bytes()

    monkeypatch.chdir(tmp_path / "restarted")
    parameters = _with_outputs(base, reference_copy)
    _run(parameters, 0.75, SaveRestart=True, RestartFrequency=0.5)
    assert RestartFile(MPC_CASE.split("/")[1], "0.5").is_file()
    assert len(json.loads(Path("results.json").read_text())["TIME"]) == 3
    restarted = _run(parameters, 1.0, LoadRestart=True, **{"Restart Step": 0.5})
    _assert_identical(_state(continuous), _state(restarted))

    assert (tmp_path / "restarted" / "results.json").read_bytes() == reference.read_bytes()
    written = sorted(p.name for p in (tmp_path / "continuous" / "vtk_output").iterdir())
    assert written == sorted(p.name for p in (tmp_path / "restarted" / "vtk_output").iterdir())
    for name in written:
        assert filecmp.cmp(
            tmp_path / "continuous" / "vtk_output" / name,
            tmp_path / "restarted" / "vtk_output" / name,
            shallow=False,
        ), name
    # time_frequency 0.3 with steps of 0.25: checks at 0.5 and 1.0; the restarted run resumed the
    # counter (0 after the check at 0.5), so it checked at 1.0 only, as the continuous run did.
    assert _check_process(continuous).checked_times == [0.5, 1.0]
    assert _check_process(restarted).checked_times == [1.0]


@needs_cases
def test_json_output_without_its_file_restarts_it_with_a_warning(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, caplog: pytest.LogCaptureFixture
) -> None:
    monkeypatch.chdir(tmp_path)
    parameters = _with_outputs(_reference_case(MPC_CASE, 0.25))
    _run(parameters, 0.5, SaveRestart=True)
    Path("results.json").unlink()
    _run(parameters, 1.0, LoadRestart=True, **{"Restart Step": 0.5})
    assert "results.json" in caplog.text and "after the restart only" in caplog.text
    data = json.loads(Path("results.json").read_text())
    assert data["TIME"] == [0.75, 1.0]
    assert np.all([len(v["DISPLACEMENT_X"]) == 2 for k, v in data.items() if k != "TIME"])
