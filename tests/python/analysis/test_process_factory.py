"""Process descriptors → processes: module names, prefixes, user modules, skipped and bad blocks."""

from __future__ import annotations

import copy
import json
import logging
import sys
from pathlib import Path
from typing import Any

import pytest

import contact_app as ca
from contact_app.analysis import KratosProcessFactory, PathResolver
from contact_app.parameters import Parameters
from contact_app.processes.assign_vector_variable_process import AssignVectorVariableProcess


@pytest.fixture
def model() -> ca.Model:
    model = ca.Model()
    part = model.CreateModelPart("Structure")
    part.AddNodalSolutionStepVariable(ca.DISPLACEMENT)
    part.CreateSubModelPart("Support").CreateNewNode(1, 0.0, 0.0, 0.0)
    return model


def _descriptor(**changes: Any) -> dict[str, Any]:
    item: dict[str, Any] = {
        "python_module": "assign_vector_variable_process",
        "kratos_module": "KratosMultiphysics",
        "process_name": "AssignVectorVariableProcess",
        "help": "",
        "Parameters": {"model_part_name": "Support", "variable_name": "DISPLACEMENT"},
    }
    item.update(changes)
    return item


def _list(*items: dict[str, Any]) -> Parameters:
    return Parameters({"list": list(items)}, source="case.json")["list"]


@pytest.mark.parametrize(
    "kratos_module",
    [
        "KratosMultiphysics",
        "KratosMultiphysics.StructuralMechanicsApplication",
        "StructuralMechanicsApplication",
    ],
)
def test_kratos_modules_with_and_without_prefix(model: ca.Model, kratos_module: str) -> None:
    processes = KratosProcessFactory(model).ConstructListOfProcesses(
        _list(_descriptor(kratos_module=kratos_module))
    )
    assert [type(p) for p in processes] == [AssignVectorVariableProcess]


def test_without_kratos_module_and_by_registry_name(model: ca.Model) -> None:
    plain = _descriptor()
    del plain["kratos_module"]
    named = _descriptor(name="Processes.KratosMultiphysics.AssignVectorVariableProcess")
    del named["python_module"], named["kratos_module"]
    processes = KratosProcessFactory(model).ConstructListOfProcesses(_list(plain, named))
    assert [type(p) for p in processes] == [AssignVectorVariableProcess] * 2


def test_gid_output_is_skipped_with_a_warning(
    model: ca.Model, caplog: pytest.LogCaptureFixture
) -> None:
    gid = {
        "python_module": "gid_output_process",
        "kratos_module": "KratosMultiphysics",
        "Parameters": {},
    }
    with caplog.at_level(logging.WARNING, logger="contact_app"):
        assert KratosProcessFactory(model).ConstructListOfProcesses(_list(gid)) == []
    assert "GiD output is not available" in caplog.text
    assert "case.json › list › [0]" in caplog.text


@pytest.mark.parametrize(
    ("changes", "message"),
    [
        (
            {"python_module": "assign_vector_variable_proces"},
            'did you mean "assign_vector_variable_process"',
        ),
        ({"kratos_module": "KratosMultiphysics.FluidDynamicsApplication"}, "unknown kratos_module"),
        (
            {"kratos_module": "KratosMultiphysics.StructuralMechanicsApp"},
            'did you mean "KratosMultiphysics.StructuralMechanicsApplication"',
        ),
        ({"Parameter": {}}, 'did you mean "Parameters"'),
        ({"python_module": 3}, "wrong type"),
        (
            {
                "python_module": "alm_contact_process",
                "kratos_module": "ContactStructuralMechanicsApplication",
            },
            'unknown key "variable_name"',
        ),
    ],
)
def test_descriptor_errors(model: ca.Model, changes: dict[str, Any], message: str) -> None:
    with pytest.raises(ca.InputError, match=message):
        KratosProcessFactory(model).ConstructListOfProcesses(_list(_descriptor(**changes)))


def test_missing_python_module(model: ca.Model) -> None:
    item = _descriptor()
    del item["python_module"]
    with pytest.raises(ca.InputError, match='missing required key "python_module"') as failure:
        KratosProcessFactory(model).ResolveModule(_list(item)[0])
    assert "case.json › list › [0] › python_module" in str(failure.value)


def test_a_list_must_be_an_array(model: ca.Model) -> None:
    with pytest.raises(ca.InputError, match="not an array"):
        KratosProcessFactory(model).ConstructListOfProcesses(Parameters({"a": {}})["a"])


def test_user_module_next_to_the_parameters(model: ca.Model, tmp_path: Path) -> None:
    (tmp_path / "my_user_process.py").write_text(
        "class Mine:\n    def __init__(self, settings):\n"
        "        self.value = settings['Parameters']['value'].GetInt()\n\n\n"
        "def Factory(settings, model):\n    return Mine(settings)\n"
    )
    (tmp_path / "no_factory_process.py").write_text("X = 1\n")
    sys.modules.pop("my_user_process", None)
    factory = KratosProcessFactory(model, PathResolver(tmp_path))
    (process,) = factory.ConstructListOfProcesses(
        _list({"python_module": "my_user_process", "Parameters": {"value": 4}})
    )
    assert process.value == 4
    with pytest.raises(ca.InputError, match="has no Factory"):
        factory.ResolveModule(_list({"python_module": "no_factory_process"})[0])
    assert str(tmp_path) not in sys.path


def test_input_files_fall_back_to_the_parameters_folder(
    model: ca.Model, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    case = tmp_path / "case"
    case.mkdir()
    (case / "results.json").write_text(json.dumps({"TIME": [1.0]}))
    monkeypatch.chdir(tmp_path)
    check = {
        "python_module": "from_json_check_result_process",
        "kratos_module": "KratosMultiphysics",
        "Parameters": {"input_file_name": "results.json", "model_part_name": "Structure"},
    }
    items = _list(copy.deepcopy(check))
    KratosProcessFactory(model, PathResolver(case)).ConstructListOfProcesses(items)
    assert items[0]["Parameters"]["input_file_name"].GetString() == str(case / "results.json")
    with pytest.raises(ca.InputError, match='file "results.json" not found'):
        KratosProcessFactory(model, PathResolver(None)).ConstructListOfProcesses(
            _list(copy.deepcopy(check))
        )
