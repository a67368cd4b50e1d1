"""Legacy keys of older reference files: converted from one table, with a warning naming the key."""

from __future__ import annotations

import json
import logging
from pathlib import Path
from typing import Any

import pytest

import contact_app as ca
from contact_app.analysis.reporting import Reporter
from contact_app.analysis.solvers.mechanical_solver import MechanicalSolver
from contact_app.analysis.solvers.settings_validation import MODEL_IMPORT_KEYS
from contact_app.legacy_keys import LEGACY_KEYS, convert_legacy_keys
from contact_app.parameters import Parameters
from contact_app.processes.vtk_output_process import DEFAULTS as VTK_DEFAULTS

DATA = Path(__file__).parent / "analysis" / "data"


def _plate(tmp_path: Path, edit: Any) -> Path:
    """The plate case of the analysis tests in ``tmp_path``, its parameters changed by ``edit``."""
    for name in ("plate.mdpa", "plate_materials.json"):
        (tmp_path / name).write_bytes((DATA / name).read_bytes())
    parameters = json.loads((DATA / "plate_static_parameters.json").read_text())
    parameters["output_processes"] = {}
    parameters["processes"].pop("json_check_process", None)
    edit(parameters)
    path = tmp_path / "parameters.json"
    path.write_text(json.dumps(parameters))
    return path


def _run(path: Path) -> ca.analysis.StructuralMechanicsAnalysis:
    analysis = ca.analysis.StructuralMechanicsAnalysis(
        ca.Model(),
        Parameters.from_file(path),
        base_dir=path.parent,
        reporter=Reporter(quiet=True),
    )
    analysis.Run()
    return analysis


def test_input_file_label_of_the_double_arch_runs_with_a_warning_naming_the_current_key(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    def edit(parameters: dict[str, Any]) -> None:
        parameters["solver_settings"]["model_import_settings"]["input_file_label"] = 0

    with caplog.at_level(logging.WARNING, logger="contact_app"):
        analysis = _run(_plate(tmp_path, edit))
    assert '"input_file_label" is the old name of "restart_load_file_label"' in caplog.text
    assert "model_import_settings › input_file_label" in caplog.text
    imports = analysis._GetSolver().settings["model_import_settings"]
    assert not imports.Has("input_file_label")
    assert imports["restart_load_file_label"].GetString() == "0"  # a number then, a string now


def test_mesh_id_zero_in_process_parameters_is_dropped_with_a_warning(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    # plate_static_parameters.json writes "mesh_id": 0 in its 3 processes, as the double arch does.
    with caplog.at_level(logging.WARNING, logger="contact_app"):
        analysis = _run(_plate(tmp_path, lambda parameters: None))
    assert caplog.text.count('"mesh_id" is a key of older versions with no current equivalent') == 3
    assert "model_part_name selects the entities" in caplog.text
    assert all(s.converged for s in analysis.reporter.steps)


def test_mesh_id_other_than_zero_is_an_error(tmp_path: Path) -> None:
    def edit(parameters: dict[str, Any]) -> None:
        process = parameters["processes"]["constraints_process_list"][0]
        process["Parameters"]["mesh_id"] = 2

    with pytest.raises(ca.InputError, match=r'(?s)"mesh_id" = 2 .*can only be 0.*fix: .*remove'):
        _run(_plate(tmp_path, edit))


def test_an_old_key_given_with_its_current_key_is_an_error() -> None:
    settings = Parameters({"input_file_label": 0, "restart_load_file_label": "0.5"})
    with pytest.raises(
        ca.InputError, match='both "input_file_label" and "restart_load_file_label"'
    ):
        convert_legacy_keys(settings, "model_import_settings")


def test_old_frictional_tolerances_set_the_stick_and_slip_ones() -> None:
    settings = Parameters({"frictional_contact_residual_relative_tolerance": 1e-3})
    convert_legacy_keys(settings, "contact_settings")
    assert settings.GetValue() == {
        "frictional_stick_contact_residual_relative_tolerance": 1e-3,
        "frictional_slip_contact_residual_relative_tolerance": 1e-3,
    }


def test_a_key_in_no_row_gets_the_usual_unknown_key_error(tmp_path: Path) -> None:
    """What the current reference also rejects is not in the table: the usual error."""

    def edit(parameters: dict[str, Any]) -> None:
        parameters["solver_settings"]["model_import_settings"]["input_file_labels"] = 0

    with pytest.raises(ca.InputError, match=r'(?s)unknown key "input_file_labels".*did you mean'):
        _run(_plate(tmp_path, edit))


def _defaults(block: str) -> dict[str, Any]:
    from contact_app.contact.auxiliary_methods_solvers import CONTACT_SETTINGS_DEFAULTS

    if block == "model_import_settings":
        return MODEL_IMPORT_KEYS
    if block == "contact_settings":
        return CONTACT_SETTINGS_DEFAULTS
    if block == "vtk_output_process":
        return VTK_DEFAULTS
    return MechanicalSolver.GetDefaultParameters()


@pytest.mark.parametrize("row", [r for r in LEGACY_KEYS if r.current], ids=lambda r: r.old)
def test_every_current_key_of_the_table_exists(row: Any) -> None:
    defaults = _defaults(row.block)
    assert row.old not in defaults
    for current in row.current.split(","):
        head, _, tail = current.partition(".")
        assert head in defaults, current
        if tail:
            assert tail in defaults[head], current
