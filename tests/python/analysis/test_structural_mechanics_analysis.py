"""End-to-end structural analyses (static plate, Bossak bar) and the top-level parameter checks."""

from __future__ import annotations

import json
import logging
from pathlib import Path
from typing import Any

import meshio
import numpy as np
import pytest
from analysis_cases import (
    DATA,
    bar_constants,
    bar_dynamic_results,
    load,
    node_coordinates,
    plate_displacements,
)
from cli_runner import run_cli

import contact_app as ca
from contact_app.analysis import StructuralMechanicsAnalysis, ValidateProjectParameters
from contact_app.parameters import Parameters
from contact_app.processes.from_json_check_result_process import ResultCheckError


def _check_plate(model: ca.Model) -> None:
    exx, eyy = plate_displacements(2.0)
    for node in model.GetModelPart("Structure").Nodes:
        u = node.GetSolutionStepValue(ca.DISPLACEMENT)
        assert u[0] == pytest.approx(exx * node.X0, rel=1e-10, abs=1e-15)
        assert u[1] == pytest.approx(eyy * node.Y0, rel=1e-10, abs=1e-15)


def test_static_plate_runs_through_python_api(case_dir: Path, in_tmp: Path) -> None:
    analysis = ca.analysis.run(case_dir / "plate_static_parameters.json", quiet=True)
    _check_plate(analysis.model)
    assert [r.time for r in analysis.reporter.steps] == [0.5, 1.0]
    assert all(r.converged for r in analysis.reporter.steps)
    # the right edge moved: loads act on the current geometry (move_mesh_flag)
    node = analysis.model.GetModelPart("Structure").GetNode(15)
    assert node.X == pytest.approx(2.0 + plate_displacements(2.0)[0] * 2.0)
    # reactions of the left supports balance the line load on the current edge length
    part = analysis.model.GetModelPart("Structure.DISPLACEMENT_left")
    reaction = sum(n.GetSolutionStepValue(ca.REACTION_X) for n in part.Nodes)
    assert reaction == pytest.approx(-2.0 * (1.0 + plate_displacements(2.0)[1]), rel=1e-10)


def test_static_plate_vtk_files_carry_displacement(case_dir: Path, in_tmp: Path) -> None:
    analysis = ca.analysis.run(case_dir / "plate_static_parameters.json", quiet=True)
    files = sorted((in_tmp / "vtk_output").glob("*.vtu"))
    assert [f.name for f in files] == ["Structure_0_1.vtu", "Structure_0_2.vtu"]
    mesh = meshio.read(files[-1])
    assert mesh.points.shape == (15, 3)
    exx, eyy = plate_displacements(2.0)
    np.testing.assert_allclose(
        mesh.point_data["DISPLACEMENT"][:, :2],
        np.column_stack([exx * mesh.points[:, 0], eyy * mesh.points[:, 1]]),
        rtol=1e-9,
        atol=1e-12,
    )
    assert "vtk_output/Structure_0_2.vtu" in analysis.reporter.files


def test_dynamic_bar_follows_the_bossak_recurrence(case_dir: Path, in_tmp: Path) -> None:
    analysis = ca.analysis.run(case_dir / "bar_dynamic_parameters.json", quiet=True)
    reference = bar_dynamic_results()
    part = analysis.model.GetModelPart("Structure")
    for node_id in (2, 3):
        node = part.GetNode(node_id)
        assert node.GetSolutionStepValue(ca.DISPLACEMENT_X) == pytest.approx(
            reference["NODE_2"]["DISPLACEMENT_X"][-1], rel=1e-10
        )
        assert node.GetSolutionStepValue(ca.ACCELERATION_X) == pytest.approx(
            reference["NODE_2"]["ACCELERATION_X"][-1], rel=1e-9
        )
    assert len(analysis.reporter.steps) == 5
    # the independent model: the element's consistent mass and stiffness of the stretching mode
    element = part.GetElement(1)
    mode = np.array([0, 0, 1, 0, 1, 0, 0, 0], dtype=float)  # u_x = x on nodes 2 and 3
    mass, stiffness, _ = bar_constants()
    assert mode @ element.CalculateMassMatrix(part.ProcessInfo) @ mode == pytest.approx(mass)
    lhs, _ = element.CalculateLocalSystem(part.ProcessInfo)
    assert mode @ lhs @ mode == pytest.approx(stiffness)


@pytest.mark.parametrize("case", ["plate_static", "bar_dynamic"])
def test_cli_runs_the_cases_from_another_directory(
    case_dir: Path, tmp_path: Path, case: str
) -> None:
    # cwd = tmp_path, the case in tmp_path/case: the relative paths fall back to the case folder
    result = run_cli("run", f"case/{case}_parameters.json", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert "Traceback" not in result.stderr
    assert "summary:" in result.stdout
    assert "all converged" in result.stdout
    assert "warning: " in result.stderr  # the deprecated keys were converted with a warning
    assert "block_builder is deprecated" in result.stderr


def test_cli_result_check_failure_exits_one(case_dir: Path, tmp_path: Path) -> None:
    results = load(case_dir / "plate_static_results.json")
    results["NODE_15"]["DISPLACEMENT_X"] = [1.0, 1.0]
    (case_dir / "plate_static_results.json").write_text(json.dumps(results))
    result = run_cli("run", "case/plate_static_parameters.json", cwd=tmp_path)
    assert result.returncode == 1
    assert result.stderr.count("result check failed: ") == 1
    assert "NODE_15" in result.stderr or "node 15" in result.stderr
    assert "Traceback" not in result.stderr


def test_result_check_failure_raises_in_python(case_dir: Path, in_tmp: Path) -> None:
    results = load(case_dir / "bar_dynamic_results.json")
    results["NODE_3"]["VELOCITY_X"] = [0.0] * 5
    (case_dir / "bar_dynamic_results.json").write_text(json.dumps(results))
    with pytest.raises(ResultCheckError):
        ca.analysis.run(case_dir / "bar_dynamic_parameters.json", quiet=True)


def _hyperelastic_plate(case_dir: Path, **solver_settings: Any) -> Path:
    """The plate, Neo-Hookean, with a stretch that only step 2 cannot follow in 3 iterations."""
    params = load(case_dir / "plate_static_parameters.json")
    params["solver_settings"].update(solver_settings)
    materials = load(case_dir / "plate_materials.json")
    materials["properties"][0]["Material"]["constitutive_law"]["name"] = (
        "HyperElasticPlaneStrain2DLaw"
    )
    (case_dir / "hyper_materials.json").write_text(json.dumps(materials))
    params["solver_settings"]["material_import_settings"]["materials_filename"] = (
        "hyper_materials.json"
    )
    params["solver_settings"]["max_iteration"] = 3
    params["processes"]["loads_process_list"] = [
        {
            "python_module": "assign_vector_variable_process",
            "kratos_module": "KratosMultiphysics",
            "Parameters": {
                "model_part_name": "Structure.LineLoad2D_right",
                "variable_name": "DISPLACEMENT",
                "constrained": [True, False, False],
                "value": ["0.02*t*t*t*t*t*t*t*t", None, None],
            },
        }
    ]
    del params["processes"]["json_check_process"]
    path = case_dir / "hyper_parameters.json"
    path.write_text(json.dumps(params))
    return path


def test_non_convergence_stops_by_default(case_dir: Path, tmp_path: Path) -> None:
    _hyperelastic_plate(case_dir)
    result = run_cli("run", "case/hyper_parameters.json", cwd=tmp_path)
    assert result.returncode == 1, result.stderr
    assert "error: step 2 (TIME = 1) did not converge in 3 iterations" in result.stderr
    assert (
        'on_non_converged_step is "stop", the default: a step that did not converge is not an '
        "equilibrium" in result.stderr
    )
    assert 'on_non_converged_step: "continue"' in result.stderr  # the fix names the setting
    assert "Traceback" not in result.stderr
    # the summary says which default was chosen and why
    summary = (
        "  a step that does not converge: the run stops (solver_settings.on_non_converged_step"
    )
    assert summary in result.stdout
    outputs = sorted(p.name for p in (tmp_path / "vtk_output").glob("*.vtu"))
    assert outputs == ["Structure_0_1.vtu"]


def test_non_convergence_goes_on_when_the_settings_ask(case_dir: Path, tmp_path: Path) -> None:
    _hyperelastic_plate(case_dir, on_non_converged_step="continue")
    result = run_cli("run", "case/hyper_parameters.json", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert (
        "warning: step 2 (TIME = 1) did not converge in 3 iterations; last norms: res ratio"
        in result.stderr
    )
    assert 'goes on with this state, as solver_settings.on_non_converged_step = "continue"' in (
        result.stderr
    )
    assert "1 NOT converged (steps 2)" in result.stdout
    assert "a step that does not converge: the run goes on from it" in result.stdout
    assert (tmp_path / "vtk_output" / "Structure_0_2.vtu").exists()


def test_non_converged_step_policy_is_checked(case_dir: Path, in_tmp: Path) -> None:
    path = _hyperelastic_plate(case_dir, on_non_converged_step="carry_on")
    with pytest.raises(ca.InputError, match="on_non_converged_step"):
        ca.analysis.run(path, quiet=True)


def test_stop_on_non_convergence_keeps_the_last_converged_output(
    case_dir: Path, tmp_path: Path
) -> None:
    _hyperelastic_plate(case_dir, on_non_converged_step="continue")  # the flag wins
    result = run_cli("run", "case/hyper_parameters.json", "--stop-on-non-convergence", cwd=tmp_path)
    assert result.returncode == 1
    assert "error: step 2 (TIME = 1) did not converge in 3 iterations" in result.stderr
    assert "--stop-on-non-convergence" in result.stderr
    assert "Traceback" not in result.stderr
    outputs = sorted(p.name for p in (tmp_path / "vtk_output").glob("*.vtu"))
    assert outputs == ["Structure_0_1.vtu"]


def test_stop_on_non_convergence_raises_in_python(case_dir: Path, in_tmp: Path) -> None:
    with pytest.raises(ca.ConvergenceError, match="step 2"):
        ca.analysis.run(_hyperelastic_plate(case_dir), quiet=True, stop_on_non_convergence=True)


def test_run_accepts_a_dict_with_paths_from_the_working_directory(
    case_dir: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(case_dir)
    parameters = load(case_dir / "plate_static_parameters.json")
    analysis = ca.analysis.run(parameters, quiet=True)
    _check_plate(analysis.model)


def test_kratos_style_construction_and_phases(
    case_dir: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.chdir(case_dir)
    model = ca.Model()
    parameters = Parameters.from_file(case_dir / "plate_static_parameters.json")
    analysis = StructuralMechanicsAnalysis(model, parameters)
    # variables are declared in the constructor, before the mesh is read
    assert model.GetModelPart("Structure").HasNodalSolutionStepVariable(ca.LINE_LOAD)
    assert model.GetModelPart("Structure").NumberOfNodes() == 0
    analysis.Initialize()
    assert model.GetModelPart("Structure").NumberOfNodes() == 15
    analysis.RunSolutionLoop()
    analysis.Finalize()
    _check_plate(model)
    out = capsys.readouterr().out
    assert "step          time  iter" in out
    assert "summary: 2 steps, 2 Newton iterations, all converged" in out


def test_materials_are_assigned_to_elements_of_the_bare_named_part(
    case_dir: Path, in_tmp: Path
) -> None:
    analysis = ca.analysis.run(case_dir / "plate_static_parameters.json", quiet=True)
    part = analysis.model.GetModelPart("Structure")
    for element in part.Elements:
        assert element.Properties.Id == 1
        assert element.Properties[ca.YOUNG_MODULUS] == 1000.0
    for condition in part.Conditions:  # not in Parts_plate: keep the mdpa properties 0
        assert condition.Properties.Id == 0


def test_echo_level_two_writes_project_parameters_output(
    case_dir: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(case_dir)
    parameters = load(case_dir / "bar_dynamic_parameters.json")
    parameters["problem_data"]["echo_level"] = 2
    analysis = ca.analysis.run(parameters, quiet=True)
    written = load(case_dir / "ProjectParametersOutput.json")
    assert written["solver_settings"]["builder_and_solver_settings"]["type"] == "block"
    assert "block_builder" not in written["solver_settings"]
    assert "ProjectParametersOutput.json" in analysis.reporter.files


# -- top-level validation (no files needed) --


def _minimal() -> dict[str, Any]:
    return {
        "problem_data": {"end_time": 1.0},
        "solver_settings": {
            "solver_type": "Static",
            "domain_size": 2,
            "time_stepping": {"time_step": 1.0},
        },
    }


@pytest.mark.parametrize(
    ("edit", "message"),
    [
        (lambda p: p.update(solver_setings={}), 'did you mean "solver_settings"'),
        (
            lambda p: p.update(loads_process_list=[]),
            "the old way to create the processes was removed",
        ),
        (
            lambda p: p.update(loads_process_list=[], processes={"a": [{"python_module": "x"}]}),
            "mixing of process initialization is not allowed",
        ),
        (lambda p: p.update(output_configuration={}), "output_configuration"),
        (lambda p: p["problem_data"].pop("end_time"), 'missing required key "end_time"'),
        (lambda p: p["problem_data"].update(domain_size=2), "old way"),
        (
            lambda p: p["problem_data"].update(start_time=2.0),
            "end_time 1.0 is before start_time 2.0",
        ),
        (
            lambda p: p["solver_settings"].pop("time_stepping"),
            'missing required key "time_stepping"',
        ),
        (lambda p: p.update(processes={"list": {}}), '"list" is not a list of processes'),
        (lambda p: p.pop("solver_settings"), 'missing required key "solver_settings"'),
    ],
)
def test_top_level_validation_messages(edit: Any, message: str) -> None:
    parameters = _minimal()
    edit(parameters)
    with pytest.raises(ca.InputError, match=message):
        ValidateProjectParameters(Parameters(parameters, source="case.json"))


def test_top_level_ignores_disabled_blocks_and_checks_restart_options(
    caplog: pytest.LogCaptureFixture,
) -> None:
    parameters = _minimal()
    parameters.update(_output_processes={"whatever": 1}, restart_options={"SaveRestart": True})
    ValidateProjectParameters(Parameters(parameters))
    parameters["restart_options"] = {"RestartControl": "steps"}
    with pytest.raises(ca.InputError, match="RestartControl"):
        ValidateProjectParameters(Parameters(parameters))
    parameters["restart_options"] = {"RestartFrequncy": 1.0}
    with pytest.raises(ca.InputError, match="RestartFrequency"):
        ValidateProjectParameters(Parameters(parameters))
    parameters["restart_options"] = {"Serializer Trace": "trace_all"}
    with caplog.at_level(logging.WARNING, logger="contact_app"):
        ValidateProjectParameters(Parameters(parameters))
    assert "always binary" in caplog.text
    parameters["restart_options"] = {"LoadRestart": True, "Restart_Step": 2}
    checked = Parameters(parameters)
    ValidateProjectParameters(checked)
    imports = checked["solver_settings"]["model_import_settings"]
    assert imports["input_type"].GetString() == "rest"
    assert imports["restart_load_file_label"].GetString() == "2.0"


def test_modelers_and_mpi_are_configuration_errors() -> None:
    parameters = _minimal()
    parameters["modelers"] = [{"modeler_name": "x"}]
    with pytest.raises(ca.ConfigurationError, match="modelers"):
        ValidateProjectParameters(Parameters(parameters))
    parameters = _minimal()
    parameters["problem_data"]["parallel_type"] = "MPI"
    with pytest.raises(ca.ConfigurationError, match="MPI"):
        ValidateProjectParameters(Parameters(parameters))


def test_data_mdpa_matches_the_documented_layout() -> None:
    nodes = node_coordinates(DATA / "plate.mdpa")
    assert len(nodes) == 15
    assert max(x for x, _ in nodes.values()) == 2.0
    assert max(y for _, y in nodes.values()) == 1.0
