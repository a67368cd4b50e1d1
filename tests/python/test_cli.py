"""The command line: ``contact-app info`` / ``python -m contact_app`` exit codes and output."""

from __future__ import annotations

import json
import shutil
import subprocess
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from cli_runner import run_cli
from process_descriptors import core_process

import contact_app as ca
from contact_app import cli

SMALL_MDPA = """\
Begin ModelPartData
End ModelPartData

Begin Properties 1
    YOUNG_MODULUS 210e9
End Properties

Begin Nodes
    1 0.0 0.0 0.0
    2 1.0 0.0 0.0
    3 1.0 1.0 0.0
    4 0.0 1.0 0.0
    5 2.0 0.0 0.0
    6 2.0 1.0 0.0
End Nodes

Begin Elements Element2D4N // two quadrilaterals
    1 1 1 2 3 4
    2 1 2 5 6 3
End Elements

Begin Conditions LineCondition2D2N
    1 1 1 2
    2 1 2 5
End Conditions

Begin Conditions PointCondition2D1N
    3 1 6
End Conditions

Begin SubModelPart Contact
    Begin SubModelPartNodes
        1
        2
    End SubModelPartNodes
    Begin SubModelPartConditions
        1
    End SubModelPartConditions
End SubModelPart
"""

MALFORMED_MDPA = "Begin Nodes\n    1 0.0 0.0\nEnd Nodes\n"


@pytest.fixture
def small_mdpa(tmp_path: Path) -> Path:
    path = tmp_path / "small.mdpa"
    path.write_text(SMALL_MDPA)
    return path


@pytest.fixture
def malformed_mdpa(tmp_path: Path) -> Path:
    path = tmp_path / "malformed.mdpa"
    path.write_text(MALFORMED_MDPA)
    return path


def test_cli_info_prints_tree_and_type_counts(
    small_mdpa: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert cli.main(["info", str(small_mdpa)]) == 0
    out = capsys.readouterr().out
    assert "ModelPart Structure: 6 nodes, 2 elements, 3 conditions" in out
    assert "  ModelPart Structure.Contact: 2 nodes, 0 elements, 1 conditions" in out
    assert "elements by type:\n  Element2D4N: 2\n" in out
    assert "conditions by type:\n  LineCondition2D2N: 2\n  PointCondition2D1N: 1\n" in out
    assert f"read {small_mdpa} in " in out


def test_cli_info_accepts_the_name_without_extension(
    small_mdpa: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert cli.main(["info", str(small_mdpa.with_suffix(""))]) == 0
    assert "6 nodes" in capsys.readouterr().out


def test_cli_python_m_info_exits_zero(small_mdpa: Path) -> None:
    result = run_cli("info", str(small_mdpa), cwd=None, timeout=None)
    assert result.returncode == 0, result.stderr
    assert "Element2D4N: 2" in result.stdout


@pytest.mark.skipif(shutil.which("contact-app") is None, reason="console script not installed")
def test_cli_console_script_info_exits_zero(small_mdpa: Path) -> None:
    result = subprocess.run(
        ["contact-app", "info", str(small_mdpa)], capture_output=True, text=True, check=False
    )
    assert result.returncode == 0, result.stderr
    assert "conditions by type:" in result.stdout


def test_cli_info_malformed_file_exits_two_without_traceback(malformed_mdpa: Path) -> None:
    result = run_cli("info", str(malformed_mdpa), cwd=None, timeout=None)
    assert result.returncode == 2
    assert result.stderr.startswith("error: ")
    assert "malformed.mdpa:2" in result.stderr
    assert "Traceback" not in result.stderr
    assert result.stdout == ""


def test_cli_info_missing_file_exits_two(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert cli.main(["info", str(tmp_path / "nothing")]) == 2
    assert capsys.readouterr().err.startswith("error: cannot open")


@pytest.mark.parametrize("argv", [["--debug", "info"], ["info", "--debug"]])
def test_cli_debug_reraises(malformed_mdpa: Path, argv: list[str]) -> None:
    with pytest.raises(ca.InputError, match="malformed.mdpa:2"):
        cli.main([*argv, str(malformed_mdpa)])


def test_cli_without_command_is_a_usage_error() -> None:
    with pytest.raises(SystemExit) as exit_info:
        cli.main([])
    assert exit_info.value.code == 2


def test_cli_count_entity_types_ignores_comments_and_sub_model_parts(small_mdpa: Path) -> None:
    counts = cli.count_entity_types(str(small_mdpa))
    assert counts["Elements"] == {"Element2D4N": 2}
    assert counts["Conditions"] == {"LineCondition2D2N": 2, "PointCondition2D1N": 1}


# -- contact-app run: bad inputs --

CASE_DATA = Path(__file__).parent / "analysis" / "data"
PARAMETERS = "plate_static_parameters.json"


def _edit_json(case: Path, name: str, edit: Callable[[dict[str, Any]], Any]) -> None:
    data = json.loads((case / name).read_text())
    edit(data)
    (case / name).write_text(json.dumps(data, indent=4))


def _solver(edit: Callable[[dict[str, Any]], Any]) -> Callable[[Path], None]:
    return lambda case: _edit_json(case, PARAMETERS, lambda p: edit(p["solver_settings"]))


def _params(edit: Callable[[dict[str, Any]], Any]) -> Callable[[Path], None]:
    return lambda case: _edit_json(case, PARAMETERS, edit)


def _material(edit: Callable[[dict[str, Any]], Any]) -> Callable[[Path], None]:
    return lambda case: _edit_json(
        case, "plate_materials.json", lambda m: edit(m["properties"][0]["Material"])
    )


def _constraint(edit: Callable[[dict[str, Any]], Any]) -> Callable[[Path], None]:
    return _params(lambda p: edit(p["processes"]["constraints_process_list"][0]))


def _load(edit: Callable[[dict[str, Any]], Any]) -> Callable[[Path], None]:
    return _params(lambda p: edit(p["processes"]["loads_process_list"][0]["Parameters"]))


def _malformed(case: Path) -> None:
    text = (case / PARAMETERS).read_text().replace('"plate_static",', '"plate_static"', 1)
    (case / PARAMETERS).write_text(text)


def _bad_element(case: Path) -> None:
    text = (case / "plate.mdpa").read_text()
    (case / "plate.mdpa").write_text(
        text.replace("SmallDisplacementElement2D4N", "SmallDisplacement2D4N")
    )


INJECTION = "__import__('os').system('touch pwned')"

BAD_INPUTS: list[tuple[str, Callable[[Path], None], str]] = [
    ("malformed_json", _malformed, "malformed JSON in plate_static_parameters.json"),
    ("unknown_top_level_key", _params(lambda p: p.update(proceses={})), 'did you mean "processes"'),
    (
        "unknown_solver_key",
        _solver(lambda s: s.update(max_iterations=5)),
        'unknown key "max_iterations"',
    ),
    (
        "unknown_linear_solver_key",
        _solver(lambda s: s["linear_solver_settings"].update(solvertype="x")),
        'did you mean "solver_type"',
    ),
    (
        "unknown_time_stepping_key",
        _solver(lambda s: s["time_stepping"].update(timestep=1.0)),
        'did you mean "time_step"',
    ),
    (
        "wrong_type",
        _solver(lambda s: s.update(max_iteration="10")),
        '"max_iteration" has the wrong type',
    ),
    (
        "missing_domain_size",
        _solver(lambda s: s.pop("domain_size")),
        'missing required key "domain_size"',
    ),
    (
        "missing_input_filename",
        _solver(lambda s: s["model_import_settings"].pop("input_filename")),
        'missing required key "input_filename"',
    ),
    (
        "missing_mdpa",
        _solver(lambda s: s["model_import_settings"].update(input_filename="nothing")),
        'mdpa file "nothing.mdpa" not found',
    ),
    (
        "missing_materials",
        _solver(lambda s: s["material_import_settings"].update(materials_filename="none.json")),
        'materials file "none.json" not found',
    ),
    (
        "unknown_law",
        _material(lambda m: m["constitutive_law"].update(name="LinearElasticPlaneStrain2DLow")),
        'did you mean "LinearElasticPlaneStrain2DLaw"',
    ),
    (
        "unknown_material_variable",
        _material(lambda m: m["Variables"].update(YOUNGS_MODULUS=1.0)),
        'unknown variable "YOUNGS_MODULUS"',
    ),
    (
        "wrong_material_value",
        _material(lambda m: m["Variables"].update(POISSON_RATIO="0.3")),
        "wrong type: found a string",
    ),
    (
        "unknown_process_module",
        _constraint(lambda c: c.update(python_module="assign_vector_variable_proces")),
        'did you mean "assign_vector_variable_process"',
    ),
    (
        "unknown_kratos_module",
        _constraint(
            lambda c: c.update(kratos_module="KratosMultiphysics.FluidDynamicsApplication")
        ),
        'unknown kratos_module "KratosMultiphysics.FluidDynamicsApplication"',
    ),
    (
        "missing_python_module",
        _constraint(lambda c: c.pop("python_module")),
        'missing required key "python_module"',
    ),
    ("bad_function", _load(lambda p: p.update(modulus="2.0*t+")), "is not a valid expression"),
    ("injection", _load(lambda p: p.update(modulus=INJECTION)), "which is not allowed"),
    (
        "unknown_linear_solver",
        _solver(
            lambda s: s["linear_solver_settings"].update(solver_type="skyline_lu_factorisation")
        ),
        'did you mean "skyline_lu_factorization"',
    ),
    (
        "unknown_criterion",
        _solver(lambda s: s.update(convergence_criterion="residual_criterium")),
        'did you mean "residual_criterion"',
    ),
    (
        "contact_criterion",
        _solver(lambda s: s.update(convergence_criterion="contact_residual_criterion")),
        "contact criteria are available with",
    ),
    (
        "unknown_solver_type",
        _solver(lambda s: s.update(solver_type="Statik")),
        'did you mean "static"',
    ),
    (
        "contact_settings",
        _solver(lambda s: s.update(contact_settings={"mortar_type": "ALMContactFrictionless"})),
        'no "Contact" sub model part',
    ),
    (
        "contact_process",
        _params(
            lambda p: p["processes"].update(
                contact_process_list=[
                    {
                        "python_module": "alm_contact_process",
                        "kratos_module": "ContactStructuralMechanicsApplication",
                        "Parameters": {},
                    }
                ]
            )
        ),
        'mortar_type = "ALMContactFrictionless"',
    ),
    (
        "legacy_process_lists",
        _params(lambda p: p.update(loads_process_list=p["processes"].pop("loads_process_list"))),
        "mixing of process initialization is not allowed",
    ),
    (
        "old_way_process_lists",
        _params(lambda p: p.update(constraints_process_list=[], processes={})),
        "the old way to create the processes was removed",
    ),
    (
        "model_part_not_found",
        _constraint(
            lambda c: c["Parameters"].update(model_part_name="Structure.DISPLACEMENT_lefft")
        ),
        'did you mean "Structure.DISPLACEMENT_left"',
    ),
    (
        "materials_model_part_not_found",
        lambda case: _edit_json(
            case,
            "plate_materials.json",
            lambda m: m["properties"][0].update(model_part_name="Parts_plat"),
        ),
        'no model part "Parts_plat"',
    ),
    (
        "end_before_start",
        _params(lambda p: p["problem_data"].update(start_time=2.0)),
        "end_time 1.0 is before start_time 2.0",
    ),
    (
        "negative_time_step",
        _solver(lambda s: s["time_stepping"].update(time_step=-0.1)),
        '"time_step" is -0.1',
    ),
    ("unknown_element", _bad_element, "plate.mdpa:"),
    (
        "explicit_dynamics",
        _solver(lambda s: s.update(solver_type="Dynamic", time_integration_method="explicit")),
        "the explicit dynamic solver is not supported yet",
    ),
]


@pytest.fixture
def run_case(tmp_path: Path) -> Path:
    """The static plate case without result check in tmp_path/case (run from tmp_path)."""
    shutil.copytree(CASE_DATA, tmp_path / "case")
    _params(lambda p: p["processes"].pop("json_check_process"))(tmp_path / "case")
    return tmp_path / "case"


@pytest.mark.parametrize(
    ("edit", "fragment"), [case[1:] for case in BAD_INPUTS], ids=[case[0] for case in BAD_INPUTS]
)
def test_cli_run_bad_input_exits_two_with_one_message(
    run_case: Path, edit: Callable[[Path], None], fragment: str
) -> None:
    edit(run_case)
    result = run_cli("run", f"case/{PARAMETERS}", cwd=run_case.parent)
    assert result.returncode == 2, result.stderr
    assert "Traceback" not in result.stderr
    errors = [line for line in result.stderr.splitlines() if line.startswith("error: ")]
    assert len(errors) == 1, result.stderr
    assert fragment in result.stderr
    assert not (run_case / "pwned").exists() and not (run_case.parent / "pwned").exists()
    assert "step " not in result.stdout  # nothing was solved


def test_cli_run_error_names_the_location(run_case: Path) -> None:
    _solver(lambda s: s.update(max_iterations=5))(run_case)
    result = run_cli("run", f"case/{PARAMETERS}", cwd=run_case.parent)
    assert (
        "where:    plate_static_parameters.json › solver_settings › max_iterations" in result.stderr
    )
    assert 'fix:      did you mean "max_iteration"' in result.stderr


def test_cli_run_malformed_json_gives_line_and_column(run_case: Path) -> None:
    _malformed(run_case)
    result = run_cli("run", f"case/{PARAMETERS}", cwd=run_case.parent)
    assert "where:    line 4, column" in result.stderr


def test_cli_run_debug_shows_the_traceback(run_case: Path) -> None:
    _solver(lambda s: s.update(max_iterations=5))(run_case)
    result = run_cli("run", "--debug", f"case/{PARAMETERS}", cwd=run_case.parent)
    assert result.returncode != 0
    assert "Traceback" in result.stderr
    assert "InputError" in result.stderr


def test_cli_run_missing_parameters_file(tmp_path: Path) -> None:
    result = run_cli("run", "nothing.json", cwd=tmp_path)
    assert result.returncode == 2
    assert result.stderr.startswith('error: cannot read the settings file "nothing.json"')


def test_cli_run_ctrl_c_exits_130_with_one_line(run_case: Path) -> None:
    (run_case / "interrupt_process.py").write_text(
        "import os, signal\n\n\nclass Interrupt:\n"
        "    def __getattr__(self, hook):\n"
        "        if hook == 'ExecuteInitializeSolutionStep':\n"
        "            return self.interrupt\n"
        "        return lambda: None\n\n"
        "    @staticmethod\n"
        "    def interrupt():\n"
        # A shell that starts the test run in the background ignores SIGINT (POSIX): restore
        # Python's handler so the signal becomes the KeyboardInterrupt a Ctrl-C gives.
        "        signal.signal(signal.SIGINT, signal.default_int_handler)\n"
        "        os.kill(os.getpid(), signal.SIGINT)\n\n\n"
        "def Factory(settings, model):\n    return Interrupt()\n"
    )
    _params(lambda p: p["processes"].update(interrupt=[{"python_module": "interrupt_process"}]))(
        run_case
    )
    result = run_cli("run", f"case/{PARAMETERS}", cwd=run_case.parent)
    assert result.returncode == 130
    assert result.stderr.strip().splitlines()[-1] == "interrupted (Ctrl-C)"
    assert "Traceback" not in result.stderr


def test_cli_run_success_in_process(
    run_case: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.chdir(run_case.parent)
    assert cli.main(["run", f"case/{PARAMETERS}"]) == 0
    captured = capsys.readouterr()
    assert "summary: 2 steps" in captured.out
    assert "files written (3): vtk_output/Structure.pvd" in captured.out
    assert "warning: " in captured.err


def test_cli_run_unexpected_exception_is_one_paragraph(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    def broken(*args: Any, **kwargs: Any) -> None:
        raise RuntimeError("boom")

    monkeypatch.setattr(ca.analysis, "run", broken)
    assert cli.main(["run", "x.json"]) == 3
    err = capsys.readouterr().err
    assert err.startswith(
        "internal error (a bug in contact_app; please report it): RuntimeError: boom"
    )
    with pytest.raises(RuntimeError):
        cli.main(["run", "--debug", "x.json"])


def test_cli_run_quiet_prints_no_table(
    run_case: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.chdir(run_case.parent)
    assert cli.main(["run", "--quiet", f"case/{PARAMETERS}"]) == 0
    assert capsys.readouterr().out == ""


# -- untrusted inputs (issue 16): each refused before any step, naming the file, key or line --


def _text(name: str, old: str, new: str) -> Callable[[Path], None]:
    def edit(case: Path) -> None:
        text = (case / name).read_text()
        assert old in text
        (case / name).write_text(text.replace(old, new, 1))

    return edit


def _bytes(name: str, data: bytes) -> Callable[[Path], None]:
    return lambda case: (case / name).write_bytes(data)


def _process(list_name: str, python_module: str, **settings: Any) -> Callable[[Path], None]:
    descriptor = core_process(python_module, {"model_part_name": "Structure", **settings})
    return _params(lambda p: p.setdefault(list_name, {}).update(extra=[descriptor]))


def _chain(*edits: Callable[[Path], None]) -> Callable[[Path], None]:
    return lambda case: [edit(case) for edit in edits] and None


def _stepping(**stepping: Any) -> Callable[[Path], None]:
    return _solver(lambda s: s.update(time_stepping=stepping))


def _problem(**values: Any) -> Callable[[Path], None]:
    return _params(lambda p: p["problem_data"].update(values))


_MATERIAL = "plate_materials.json › properties › [0] › Material › Variables › "
_CHECK = {"check_variables": ["DISPLACEMENT_X"]}

UNTRUSTED_INPUTS: list[tuple[str, Callable[[Path], None], list[str]]] = [
    (
        "nan_time_step",
        _stepping(time_step=float("nan")),
        ["number NaN", f"{PARAMETERS} › solver_settings › time_stepping › time_step, line "],
    ),
    (
        "infinite_time_step",
        _stepping(time_step=float("inf")),
        ["number Infinity", "time_stepping › time_step, line "],
    ),
    (
        "overflowing_number",
        _text(PARAMETERS, '"time_step": 0.5', '"time_step": 1e999'),
        ["1e999", "solver_settings › time_stepping › time_step, line "],
    ),
    (
        "nan_end_time",
        _problem(end_time=float("nan")),
        ["number NaN", f"{PARAMETERS} › problem_data › end_time, line "],
    ),
    (
        "nan_in_time_step_table",
        _stepping(time_step_table=[[0.0, 0.1], [1.0, float("nan")]]),
        ["number NaN", "time_stepping › time_step_table › [1] › [1], line "],
    ),
    (
        "time_not_finite",
        _chain(_problem(end_time=1.7e308), _stepping(time_step=1.5e308)),
        ["TIME would become inf", "solver_settings › time_stepping"],
    ),
    (
        "time_does_not_advance",
        _chain(_problem(start_time=1.0e10, end_time=1.0e10 + 1.0), _stepping(time_step=1.0e-10)),
        ["floating-point resolution of TIME", "solver_settings › time_stepping"],
    ),
    (
        "too_many_steps",
        _stepping(time_step=1.0e-9),
        ["1e+09 steps from start_time 0 to end_time 1", "at most 10000000 steps"],
    ),
    (
        "negative_time_step",
        _stepping(time_step=-0.5),
        ["solver_settings › time_stepping › time_step", "a number > 0"],
    ),
    (
        "key_written_twice",
        _text(PARAMETERS, '"end_time"', '"end_time": 5.0,\n        "end_time"'),
        ['"end_time" is written twice', "lines 6 and 7", PARAMETERS],
    ),
    (
        "negative_thickness",
        _material(lambda m: m["Variables"].update(THICKNESS=-1.0)),
        [_MATERIAL + "THICKNESS", "a number > 0"],
    ),
    (
        "negative_friction",
        _material(lambda m: m["Variables"].update(FRICTION_COEFFICIENT=-0.5)),
        [_MATERIAL + "FRICTION_COEFFICIENT", "a number ≥ 0"],
    ),
    (
        "negative_density",
        _material(lambda m: m["Variables"].update(DENSITY=-1.0)),
        [_MATERIAL + "DENSITY"],
    ),
    (
        "absurd_young_modulus",
        _material(lambda m: m["Variables"].update({"KratosMultiphysics.YOUNG_MODULUS": 1e300})),
        [_MATERIAL + "KratosMultiphysics.YOUNG_MODULUS", "beyond any physical value"],
    ),
    (
        "negative_thickness_in_the_mesh",
        _text("plate.mdpa", "Begin Properties 0\n", "Begin Properties 0\n    THICKNESS -1.0\n"),
        ["THICKNESS = -1 is out of range", "properties 0 of the mesh plate.mdpa"],
    ),
    (
        "non_utf8_parameters",
        _bytes(PARAMETERS, b'{"problem_data": {"problem_name": "caf\xe9"}}'),
        [PARAMETERS, "is not UTF-8", "byte offset 38"],
    ),
    (
        "non_utf8_materials",
        _bytes("plate_materials.json", b'{"properties": []}\n\xff'),
        ["plate_materials.json is not UTF-8", "byte offset 19 (line 2)"],
    ),
    ("deep_json", _bytes(PARAMETERS, b"[" * 100_000), [PARAMETERS, "deeper than 64 levels"]),
    (
        "long_operator_chain",
        _load(lambda p: p.update(modulus="+".join(["t"] * 900))),
        ["nested more than 100 levels", "loads_process_list › [0] › Parameters › modulus"],
    ),
    (
        "relative_module",
        _constraint(lambda c: c.update(python_module="..evil")),
        ['"..evil" is not a module name', "constraints_process_list › [0] › python_module"],
    ),
    (
        "device_as_materials",
        _solver(lambda s: s["material_import_settings"].update(materials_filename="/dev/zero")),
        ['"/dev/zero" is not a regular file', "material_import_settings › materials_filename"],
    ),
    (
        "device_as_reference_results",
        _process(
            "processes", "from_json_check_result_process", input_file_name="/dev/zero", **_CHECK
        ),
        ['"/dev/zero" is not a regular file', "extra › [0] › Parameters › input_file_name"],
    ),
    (
        "empty_mesh",
        _bytes("plate.mdpa", b""),
        ['plate.mdpa" defines no nodes: it is empty or unreadable', "input_filename"],
    ),
    (
        "nan_coordinate_in_the_mesh",
        _text("plate.mdpa", "    2 0.500000 0.000000", "    2 nan 0.000000"),
        ['plate.mdpa:10: non-finite coordinate x "nan"'],
    ),
    (
        "node_id_beyond_64_bits_in_the_mesh",
        _text("plate.mdpa", "    1 0.000000", "    99999999999999999999 0.000000"),
        ['plate.mdpa:9: node id "99999999999999999999" is beyond the largest id'],
    ),
    (
        "infinite_property_in_the_mesh",
        _text("plate.mdpa", "Begin Properties 0\n", "Begin Properties 0\n    DENSITY inf\n"),
        ['plate.mdpa:6: non-finite real value "inf"'],
    ),
    (
        "non_utf8_sub_model_part_name_in_the_mesh",
        lambda case: (case / "plate.mdpa").write_bytes(
            (case / "plate.mdpa").read_bytes().replace(b"Parts_plate", b"Parts_pl\xe4te", 1)
        ),
        ["plate.mdpa:42: byte 0xe4 at byte offset", "(column 28) is not UTF-8"],
    ),
    (
        "degenerate_face_in_the_mesh",
        _text("plate.mdpa", "    1 0 5 10\n", "    1 0 5 5\n"),
        [
            "plate.mdpa:38: condition 1 (Line2D2 with nodes [5, 5]) of model part "
            '"Structure.LineLoad2D_right" is a degenerate face, zero length: node 5 is listed twice'
        ],
    ),
    (
        "mesh_is_a_folder",
        lambda case: (
            (case / "folder.mdpa").mkdir()
            or _solver(lambda s: s["model_import_settings"].update(input_filename="case/folder"))(
                case
            )
        ),
        ["folder.mdpa", "is a folder", "model_import_settings › input_filename"],
    ),
    (
        "output_overwrites_materials",
        _process(
            "output_processes", "json_output_process", output_file_name="case/plate_materials.json"
        ),
        [
            "is an input of this run",
            "extra › [0] › Parameters › output_file_name",
            "material_import_settings › materials_filename",
        ],
    ),
    (
        "output_overwrites_mesh",
        _process("output_processes", "json_output_process", output_file_name="case/plate.mdpa"),
        ["is an input of this run", "model_import_settings › input_filename"],
    ),
    (
        "output_overwrites_parameters",
        _process("output_processes", "json_output_process", output_file_name=f"case/{PARAMETERS}"),
        ["is an input of this run", "input:    the parameters file"],
    ),
    (
        "output_written_twice",
        _params(
            lambda p: p["output_processes"].update(
                twice=[
                    core_process(
                        "json_output_process",
                        {"model_part_name": "Structure", "output_file_name": name},
                    )
                    for name in ("out.json", "./out.json")
                ]
            )
        ),
        [
            'the output file "./out.json" is written twice',
            "twice › [0] › Parameters › output_file_name",
            "twice › [1] › Parameters › output_file_name",
        ],
    ),
    (
        "output_folder_under_a_file",
        _process("output_processes", "vtk_output_process", output_path="case/plate.mdpa/vtk"),
        ["cannot be written", "is a file, not a folder", "extra › [0] › Parameters › output_path"],
    ),
]


@pytest.mark.parametrize(
    ("edit", "fragments"),
    [case[1:] for case in UNTRUSTED_INPUTS],
    ids=[case[0] for case in UNTRUSTED_INPUTS],
)
def test_cli_run_untrusted_input_exits_two_naming_the_place(
    run_case: Path,
    edit: Callable[[Path], None],
    fragments: list[str],
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
) -> None:
    edit(run_case)
    inputs = {path: path.read_bytes() for path in run_case.iterdir() if path.is_file()}
    monkeypatch.chdir(run_case.parent)
    assert cli.main(["run", f"case/{PARAMETERS}"]) == 2
    captured = capsys.readouterr()
    errors = [line for line in captured.err.splitlines() if line.startswith("error: ")]
    assert len(errors) == 1, captured.err
    for fragment in fragments:
        assert fragment in captured.err
    assert "step " not in captured.out  # nothing was solved
    assert all(path.read_bytes() == data for path, data in inputs.items())  # nothing overwritten


def test_cli_run_parameters_echo_never_overwrites_the_parameters_file(
    run_case: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    _problem(echo_level=2)(run_case)
    echo = run_case / "ProjectParametersOutput.json"
    (run_case / PARAMETERS).rename(echo)
    original = echo.read_bytes()
    monkeypatch.chdir(run_case)
    assert cli.main(["run", "--quiet", echo.name]) == 2
    err = capsys.readouterr().err
    assert 'the output file "ProjectParametersOutput.json" is an input of this run' in err
    assert "ProjectParametersOutput.json › problem_data › echo_level (> 1: written to" in err
    assert "input:    the parameters file" in err
    assert echo.read_bytes() == original
    # From another working folder the echo is written there, next to nothing it could overwrite.
    monkeypatch.chdir(run_case.parent)
    assert cli.main(["run", "--quiet", f"case/{echo.name}"]) == 0
    assert (run_case.parent / echo.name).is_file()
    assert echo.read_bytes() == original


def test_cli_run_messages_quote_huge_values_briefly_and_escape_nul(
    run_case: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    _solver(lambda s: s.update({"max_iteration": "x" * 20_000, "k\x00": 1}))(run_case)
    monkeypatch.chdir(run_case.parent)
    assert cli.main(["run", f"case/{PARAMETERS}"]) == 2
    err = capsys.readouterr().err
    assert len(err) < 1500 and "\x00" not in err
    assert "characters)" in err


def test_cli_run_safe_refuses_case_modules_before_importing_them(
    run_case: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    (run_case / "case_process.py").write_text(
        "from pathlib import Path\nPath(__file__).with_name('imported').touch()\n\n\n"
        "def Factory(settings, model):\n    return None\n"
    )
    _params(lambda p: p["processes"].update(own=[{"python_module": "case_process"}]))(run_case)
    monkeypatch.chdir(run_case.parent)
    assert cli.main(["run", "--safe", f"case/{PARAMETERS}"]) == 2
    err = capsys.readouterr().err
    assert "--safe refuses to import a module from the case folder" in err
    assert "processes › own › [0] › python_module" in err
    assert not (run_case / "imported").exists()
    # the project's own processes still run with --safe
    _params(lambda p: p["processes"].pop("own"))(run_case)
    assert cli.main(["run", "--safe", "--quiet", f"case/{PARAMETERS}"]) == 0


def test_cli_info_refuses_devices_and_folders(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "mesh.mdpa").mkdir()
    for name, kind in (
        ("/dev/zero", "is not a regular file"),
        (str(tmp_path / "mesh"), "is a folder"),
    ):
        assert cli.main(["info", name]) == 2
        assert kind in capsys.readouterr().err
