"""from_json_check_result_process: strict time_frequency, nearest TIME, flags, messages."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from conftest import create, run_steps

import contact_app as ca
from contact_app.processes.from_json_check_result_process import ResultCheckError


def _reference(path: Path, times: list[float], nodes: dict[int, dict[str, list[Any]]]) -> str:
    data: dict[str, Any] = {"TIME": times}
    data.update({f"NODE_{node_id}": columns for node_id, columns in nodes.items()})
    path.write_text(json.dumps(data))
    return str(path)


def _x_reference(path: Path, times: list[float], columns: dict[int, list[float]]) -> str:
    """``_reference`` with only DISPLACEMENT_X: node id -> its column, what most tests check."""
    return _reference(path, times, {i: {"DISPLACEMENT_X": column} for i, column in columns.items()})


def _checker(model: ca.Model, reference: str, **settings: Any) -> Any:
    return create(
        "from_json_check_result_process",
        {
            "check_variables": ["DISPLACEMENT_X"],
            "input_file_name": reference,
            "model_part_name": "Structure.Bottom",
            **settings,
        },
        model,
    )


def _set_x(plate: ca.ModelPart, values: dict[int, float]) -> None:
    for node_id, value in values.items():
        plate.GetNode(node_id).SetSolutionStepValue(ca.DISPLACEMENT_X, 0, value)


@pytest.mark.parametrize(
    ("dt", "frequency", "checked_steps"),
    [
        (0.25, 1.0, [5, 10]),  # 4 * 0.25 = 1.0 is not > 1.0
        (0.5005, 1.0, [2, 4, 6]),  # 1.001 > 1.0 (the spec's example)
        (1.01, 1.0, [1, 2, 3]),
        (0.3, 0.0, list(range(1, 11))),  # 0.0 checks every step
    ],
)
def test_check_time_frequency_fires_only_when_strictly_exceeded(
    model: ca.Model,
    plate: ca.ModelPart,
    tmp_path: Path,
    dt: float,
    frequency: float,
    checked_steps: list[int],
) -> None:
    reference = _x_reference(tmp_path / "r.json", [0.0], {i: [0.0] for i in (1, 2, 3)})
    checker = _checker(model, reference, time_frequency=frequency)
    steps = range(1, 11 if frequency == 0.0 or dt < 0.5 else 7 if dt < 1.0 else 4)
    run_steps(plate, [checker], [dt * k for k in steps])
    assert checker.checked_times == pytest.approx([dt * k for k in checked_steps])


def test_check_uses_the_nearest_stored_time(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path
) -> None:
    columns = {i: [0.0, 10.0 * i, 20.0 * i] for i in (1, 2, 3)}
    reference = _x_reference(tmp_path / "r.json", [0.0, 1.0, 2.0], columns)
    checker = _checker(model, reference, time_frequency=0.0)
    checker.ExecuteInitialize()
    for time, stored in ((1.4, 1.0), (1.5, 2.0), (0.2, 0.0), (7.0, 2.0), (-1.0, 0.0)):
        _set_x(plate, {i: 10.0 * stored * i for i in (1, 2, 3)})
        checker.check(time)  # passes: the value at the nearest stored time (ties: the later)
    _set_x(plate, {i: 10.0 * i for i in (1, 2, 3)})
    with pytest.raises(ResultCheckError, match=r"at TIME 1\.6 \(reference TIME 2\)"):
        checker.check(1.6)


def test_check_failure_message_names_variable_node_time_values_and_tolerances(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path
) -> None:
    columns = {1: [0.5], 2: [0.25], 3: [0.0]}
    reference = _x_reference(tmp_path / "case_results.json", [1.0], columns)
    checker = _checker(model, reference, tolerance=1e-6, relative_tolerance=1e-4)
    _set_x(plate, {1: 0.5 * (1 + 5e-5), 2: 0.2, 3: 1e-7})
    plate.CloneTimeStep(1.5)
    with pytest.raises(ResultCheckError) as error:
        checker.ExecuteFinalizeSolutionStep()
    message = str(error.value)
    assert isinstance(error.value, AssertionError)
    assert (
        message.startswith('1 of 3 checked values of "Structure.Bottom" differ from "')
        and 'case_results.json" at TIME 1.5 (reference TIME 1)' in message
    )
    assert "DISPLACEMENT_X of node 2: value 0.2, reference 0.25, |difference| 0.05" in message
    assert "relative_tolerance 0.0001" in message and "tolerance 1e-06" in message
    assert "node 1" not in message and "node 3" not in message  # within the tolerances
    assert checker.worst_relative_errors["DISPLACEMENT_X"] == pytest.approx(1.0)  # 1e-7 vs 0
    assert checker.worst_absolute_errors["DISPLACEMENT_X"] == pytest.approx(0.05)


def test_check_for_flag_checks_only_flagged_nodes(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path
) -> None:
    reference = _x_reference(tmp_path / "r.json", [1.0], {1: [1.0], 2: [99.0]})  # node 3 absent
    checker = _checker(model, reference, check_for_flag="ACTIVE", time_frequency=0.0)
    _set_x(plate, {1: 1.0, 2: 0.0, 3: 0.0})
    plate.GetNode(1).Set(ca.ACTIVE, True)
    run_steps(plate, [checker], [1.0])
    assert checker.checked_times == [1.0]
    plate.GetNode(2).Set(ca.ACTIVE, True)
    with pytest.raises(ResultCheckError, match="node 2: value 0, reference 99"):
        checker.check(1.0)
    plate.GetNode(3).Set(ca.ACTIVE, True)
    with pytest.raises(ca.InputError, match=r'no results of node 3 \("NODE_3"\)'):
        checker.check(1.0)


def test_check_non_historical_values(model: ca.Model, plate: ca.ModelPart, tmp_path: Path) -> None:
    reference = _reference(
        tmp_path / "r_LM.json",
        [1.0],
        {i: {"AUGMENTED_NORMAL_CONTACT_PRESSURE": [-2.0 * i]} for i in (1, 2, 3)},
    )
    checker = create(
        "from_json_check_result_process",
        {
            "check_variables": ["AUGMENTED_NORMAL_CONTACT_PRESSURE"],
            "input_file_name": reference,
            "model_part_name": "Structure.Bottom",
            "historical_value": False,
            "relative_tolerance": 1e-5,
            "time_frequency": 0.0,
        },
        model,
    )
    for node in plate.GetSubModelPart("Bottom").Nodes:
        node.SetValue(ca.AUGMENTED_NORMAL_CONTACT_PRESSURE, -2.0 * node.Id)
    run_steps(plate, [checker], [1.0])
    plate.GetNode(3).SetValue(ca.AUGMENTED_NORMAL_CONTACT_PRESSURE, -7.0)
    with pytest.raises(ResultCheckError, match="AUGMENTED_NORMAL_CONTACT_PRESSURE of node 3"):
        checker.check(1.0)


def test_check_historical_variable_must_be_a_solution_step_variable(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path
) -> None:
    with pytest.raises(ca.InputError, match='write "historical_value": false'):
        create(
            "from_json_check_result_process",
            {
                "check_variables": ["AUGMENTED_NORMAL_CONTACT_PRESSURE"],
                "input_file_name": "x.json",
                "model_part_name": "Structure",
            },
            model,
        )


def test_check_missing_or_malformed_reference_file(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path
) -> None:
    checker = _checker(model, str(tmp_path / "missing.json"))
    with pytest.raises(
        ca.InputError, match="(?s)cannot read the reference file .*working directory"
    ):
        checker.ExecuteInitialize()
    bad = tmp_path / "bad.json"
    bad.write_text('{"NODE_1": {}}')
    with pytest.raises(ca.InputError, match='has no "TIME" list'):
        _checker(model, str(bad)).ExecuteInitialize()
    other = _reference(
        tmp_path / "r.json", [1.0], {i: {"DISPLACEMENT_Y": [0.0]} for i in (1, 2, 3)}
    )
    with pytest.raises(ca.InputError, match='no "DISPLACEMENT_X" for node 1'):
        _checker(model, other).check(1.0)


def test_check_relative_input_file_starts_from_the_working_directory(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / "case").mkdir()
    _x_reference(tmp_path / "case" / "r.json", [1.0], {i: [0.0] for i in (1, 2, 3)})
    monkeypatch.chdir(tmp_path)
    checker = _checker(model, "case/r.json", time_frequency=0.0)
    run_steps(plate, [checker], [1.0])
    assert checker.checked_times == [1.0]


def test_check_vector_variable_components_and_unknown_keys(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path
) -> None:
    reference = _reference(
        tmp_path / "r.json",
        [1.0],
        {
            i: {"DISPLACEMENT_X": [0.0], "DISPLACEMENT_Y": [0.0], "DISPLACEMENT_Z": [0.0]}
            for i in (1, 2, 3)
        },
    )
    checker = create(
        "from_json_check_result_process",
        {
            "check_variables": ["DISPLACEMENT"],
            "input_file_name": reference,
            "model_part_name": "Structure.Bottom",
            "time_frequency": 0.0,
        },
        model,
    )
    run_steps(plate, [checker], [1.0])
    assert sorted(checker.worst_relative_errors) == [
        "DISPLACEMENT_X",
        "DISPLACEMENT_Y",
        "DISPLACEMENT_Z",
    ]
    with pytest.raises(ca.InputError, match='did you mean "check_variables"'):
        _checker(model, reference, check_variable=["DISPLACEMENT_X"])
