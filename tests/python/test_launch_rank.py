"""launch_rank: the launcher's MPI rank, and the files and table only rank 0 writes.

Under ``mpirun`` every rank runs the whole analysis; a rank other than 0 must compute the same
results and write nothing (VTK, JSON, restart files, ProjectParametersOutput.json) and print no
table. The launcher's variables are set here by hand: no MPI is needed to see what a rank writes.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import contact_app as ca
from contact_app.analysis.reporting import Reporter
from contact_app.analysis.structural_mechanics_analysis import StructuralMechanicsAnalysis
from contact_app.launch_rank import RANK_VARIABLES, is_output_rank, launch_rank

CASES_DIR = Path(__file__).resolve().parents[2].parent / "shared" / "kratos_cases"
CASE = "ALM_frictionless_contact_test_2D/hyper_simple_patch_test"

needs_cases = pytest.mark.skipif(not CASES_DIR.is_dir(), reason="../shared/kratos_cases missing")


@pytest.fixture
def no_launcher(monkeypatch: pytest.MonkeyPatch) -> pytest.MonkeyPatch:
    for name in RANK_VARIABLES:
        monkeypatch.delenv(name, raising=False)
    return monkeypatch


def test_rank_comes_from_the_launchers_variables(no_launcher: pytest.MonkeyPatch) -> None:
    assert launch_rank() == 0 and is_output_rank()
    no_launcher.setenv("PMI_RANK", "3")
    assert launch_rank() == 3 and not is_output_rank()
    no_launcher.setenv("OMPI_COMM_WORLD_RANK", "1")  # Open MPI's is read first
    assert launch_rank() == 1
    no_launcher.setenv("OMPI_COMM_WORLD_RANK", "not a rank")
    assert launch_rank() == 3
    no_launcher.delenv("PMI_RANK")
    no_launcher.setenv("PMIX_RANK", "0")
    assert launch_rank() == 0 and is_output_rank()


def _parameters(folder: Path) -> dict:
    """The case with VTK and JSON output into ``folder``, inputs by absolute path."""
    parameters = json.loads((CASES_DIR / f"{CASE}_parameters.json").read_text())
    parameters["problem_data"]["echo_level"] = 2  # ProjectParametersOutput.json
    solver = parameters["solver_settings"]
    for block, key in (
        ("model_import_settings", "input_filename"),
        ("material_import_settings", "materials_filename"),
    ):
        solver[block][key] = str(CASES_DIR / solver[block][key])
    parameters["processes"]["json_check_process"] = []
    parameters["processes"]["json_output_process"] = [
        {
            "python_module": "json_output_process",
            "Parameters": {
                "output_variables": ["DISPLACEMENT_Y"],
                "output_file_name": str(folder / "results.json"),
                "model_part_name": "Structure",
                "time_frequency": 0.0,
            },
        }
    ]
    parameters["output_processes"] = {
        "vtk_output": [
            {
                "python_module": "vtk_output_process",
                "Parameters": {"model_part_name": "Structure", "output_path": str(folder / "vtk")},
            }
        ]
    }
    parameters["restart_options"] = {"SaveRestart": True}
    return parameters


def _run_in(folder: Path, monkeypatch: pytest.MonkeyPatch) -> StructuralMechanicsAnalysis:
    folder.mkdir()
    monkeypatch.chdir(folder)
    analysis = StructuralMechanicsAnalysis(
        ca.Model(), _parameters(folder), reporter=Reporter(quiet=not is_output_rank())
    )
    analysis.Run()
    return analysis


def _displacements(analysis: StructuralMechanicsAnalysis) -> np.ndarray:
    part = analysis.model.GetModelPart("Structure")
    return np.array([n.GetSolutionStepValue(ca.DISPLACEMENT) for n in part.Nodes])


@needs_cases
def test_only_rank_0_writes_files(tmp_path: Path, no_launcher: pytest.MonkeyPatch) -> None:
    no_launcher.setenv("OMPI_COMM_WORLD_RANK", "1")
    other = _run_in(tmp_path / "rank1", no_launcher)
    assert sorted(p.name for p in (tmp_path / "rank1").iterdir()) == []
    no_launcher.setenv("OMPI_COMM_WORLD_RANK", "0")
    first = _run_in(tmp_path / "rank0", no_launcher)
    written = {p.name for p in (tmp_path / "rank0").iterdir()}
    assert {"results.json", "vtk", "ProjectParametersOutput.json"} <= written
    restart_folders = [name for name in written if name.endswith("_restart_files")]
    assert restart_folders and any((tmp_path / "rank0" / restart_folders[0]).iterdir())
    assert any((tmp_path / "rank0" / "vtk").glob("*.vtu"))
    np.testing.assert_array_equal(_displacements(other), _displacements(first))


@needs_cases
def test_a_rank_other_than_0_runs_quietly_through_the_driver(
    tmp_path: Path, no_launcher: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "ProjectParameters.json").write_text(json.dumps(_parameters(tmp_path)))
    no_launcher.chdir(tmp_path)
    no_launcher.setenv("PMI_RANK", "1")
    ca.analysis.run(tmp_path / "ProjectParameters.json")
    assert capsys.readouterr().out == ""
    assert sorted(p.name for p in tmp_path.iterdir()) == ["ProjectParameters.json"]
    no_launcher.setenv("PMI_RANK", "0")
    ca.analysis.run(tmp_path / "ProjectParameters.json")
    assert "summary: 1 steps" in capsys.readouterr().out
    assert (tmp_path / "results.json").is_file()
