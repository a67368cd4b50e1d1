"""Process blocks of the Kratos reference cases: every key accepted, reference files checkable."""

from __future__ import annotations

import importlib
import json
from pathlib import Path
from typing import Any

import pytest

import contact_app as ca
from contact_app.parameters import Parameters
from contact_app.processes.from_json_check_result_process import ResultCheckError

CASES = Path(__file__).resolve().parents[4] / "shared" / "kratos_cases"
PARAMETER_FILES = sorted(CASES.glob("*/*_parameters.json"))
HISTORICAL = (
    "DISPLACEMENT",
    "REACTION",
    "NORMAL",
    "WEIGHTED_GAP",
    "WEIGHTED_SLIP",
    "LAGRANGE_MULTIPLIER_CONTACT_PRESSURE",
    "VECTOR_LAGRANGE_MULTIPLIER",
    "VELOCITY",
    "ACCELERATION",
    "VOLUME_ACCELERATION",
)
BLOCKS = ("processes", "output_processes", "_output_processes", "_json_output_process")

pytestmark = pytest.mark.skipif(not PARAMETER_FILES, reason=f"no Kratos cases in {CASES}")


def _read_case(parameters: Parameters) -> ca.Model:
    """Read the case mesh as the solver would (historical variables, computing_domain)."""
    solver = parameters["solver_settings"]
    model = ca.Model()
    root = model.CreateModelPart(solver["model_part_name"].GetString(), 2)
    for name in HISTORICAL:
        root.AddNodalSolutionStepVariable(ca.get_variable(name))
    ca.ModelPartIO(
        str(CASES / solver["model_import_settings"]["input_filename"].GetString())
    ).ReadModelPart(root)
    root.ProcessInfo[ca.DOMAIN_SIZE] = solver["domain_size"].GetInt()
    domain = root.CreateSubModelPart("computing_domain")
    domain.AddNodes([n.Id for n in root.Nodes])
    domain.AddElements([e.Id for e in root.Elements])
    domain.AddConditions([c.Id for c in root.Conditions])
    return model


def _core_descriptors(parameters: Parameters) -> list[Parameters]:
    found = []
    for block in BLOCKS:
        if not parameters.Has(block):
            continue
        lists = parameters[block]
        for process_list in [lists] if lists.IsArray() else list(lists.values()):
            for item in process_list:
                module = item["python_module"].GetString()
                if (
                    module == "gid_output_process"
                    or not item.Has("kratos_module")
                    or (item["kratos_module"].GetString() != "KratosMultiphysics")
                ):
                    continue
                found.append(item)
    return found


@pytest.mark.parametrize("path", PARAMETER_FILES, ids=lambda p: p.parent.name + "/" + p.stem)
def test_kratos_case_core_processes_accept_every_key(
    path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(CASES)
    parameters = Parameters.from_file(path)
    model = _read_case(parameters)
    descriptors = _core_descriptors(parameters)
    assert descriptors
    for item in descriptors:
        module = importlib.import_module(
            f"contact_app.processes.{item['python_module'].GetString()}"
        )
        process = module.Factory(item, model)
        if item["python_module"].GetString() == "from_json_check_result_process":
            process.ExecuteInitialize()  # reads the reference file (never writes)


def _checks(path: Path) -> list[tuple[Parameters, Any]]:
    parameters = Parameters.from_file(path)
    model = _read_case(parameters)
    from contact_app.processes import from_json_check_result_process as module

    return [
        (item["Parameters"], module.Factory(item, model))
        for item in parameters["processes"]["json_check_process"]
    ]


@pytest.mark.parametrize("path", PARAMETER_FILES, ids=lambda p: p.parent.name + "/" + p.stem)
def test_kratos_case_reference_values_pass_and_perturbed_fail(
    path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(CASES)
    for settings, check in _checks(path):
        data = json.loads(Path(settings["input_file_name"].GetString()).read_text())
        final = data["TIME"][-1]
        historical = check.historical
        nodes = list(check.model_part.Nodes)
        for node in nodes:
            for column in check.columns:
                value = data[f"NODE_{node.Id}"][column.name][-1]
                if historical:
                    node.SetSolutionStepValue(column.variable, 0, value)
                else:
                    node.SetValue(column.variable, value)
        check.check(final)
        assert max(check.worst_absolute_errors.values()) == 0.0
        column, node = check.columns[0], nodes[0]
        if historical:
            node.SetSolutionStepValue(
                column.variable, 0, node.GetSolutionStepValue(column.variable) + 0.01
            )
        else:
            node.SetValue(column.variable, node.GetValue(column.variable) * 1.01 + 0.01)
        with pytest.raises(ResultCheckError, match=f"{column.name} of node {node.Id}"):
            check.check(final)
