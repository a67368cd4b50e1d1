"""assign_scalar_variable_process: values, fixity per step, interval, tables, local axes, errors."""

from __future__ import annotations

from functools import partial
from pathlib import Path

import pytest
from conftest import create, create_on

import contact_app as ca
from contact_app.processes.process import Process

_create = partial(create_on, "assign_scalar_variable_process")


def _start_step(model_part: ca.ModelPart, process: Process, time: float) -> None:
    model_part.CloneTimeStep(time)
    process.ExecuteInitializeSolutionStep()


def _values(model_part: ca.ModelPart, variable: object) -> dict[int, float]:
    return {n.Id: n.GetSolutionStepValue(variable) for n in model_part.Nodes}


def test_assign_scalar_function_of_time_and_space_per_step(
    model: ca.Model, plate: ca.ModelPart
) -> None:
    process = _create(
        model, "Structure.Top", "DISPLACEMENT_Y", value="-0.1*t + 0.01*x", interval=[0.0, "End"]
    )
    top = plate.GetSubModelPart("Top")
    process.ExecuteBeforeSolutionLoop()  # applied at the start time
    assert _values(top, ca.DISPLACEMENT_Y) == pytest.approx({7: 0.0, 8: 0.01, 9: 0.02})
    for time in (0.5, 1.0):
        _start_step(plate, process, time)
        expected = {7: -0.1 * time, 8: -0.1 * time + 0.01, 9: -0.1 * time + 0.02}
        assert _values(top, ca.DISPLACEMENT_Y) == pytest.approx(expected, abs=1e-15)
        assert all(n.IsFixed(ca.DISPLACEMENT_Y) for n in top.Nodes)
        assert not any(n.IsFixed(ca.DISPLACEMENT_X) for n in top.Nodes)
        process.ExecuteFinalizeSolutionStep()
        assert not any(n.IsFixed(ca.DISPLACEMENT_Y) for n in top.Nodes)
    # nodes outside the part are untouched
    assert plate.GetNode(5).GetSolutionStepValue(ca.DISPLACEMENT_Y) == 0.0
    assert not plate.GetNode(5).IsFixed(ca.DISPLACEMENT_Y)


def test_assign_scalar_interval_limits_value_and_fixity(
    model: ca.Model, plate: ca.ModelPart
) -> None:
    # A bare sub-model-part name, as old Kratos files write it.
    process = _create(model, "Bottom", "DISPLACEMENT_X", value="t", interval=[0.4, 0.6])
    node = plate.GetNode(2)
    process.ExecuteBeforeSolutionLoop()
    assert node.GetSolutionStepValue(ca.DISPLACEMENT_X) == 0.0
    for time, value, fixed in ((0.2, 0.0, False), (0.4, 0.4, True), (0.6, 0.6, True)):
        _start_step(plate, process, time)
        assert node.GetSolutionStepValue(ca.DISPLACEMENT_X) == pytest.approx(value)
        assert node.IsFixed(ca.DISPLACEMENT_X) is fixed
        process.ExecuteFinalizeSolutionStep()
    node.SetSolutionStepValue(ca.DISPLACEMENT_X, 0, 0.75)  # as if solved
    _start_step(plate, process, 0.8)
    assert node.GetSolutionStepValue(ca.DISPLACEMENT_X) == 0.75  # untouched after the interval
    assert not node.IsFixed(ca.DISPLACEMENT_X)


def test_assign_scalar_unconstrained_writes_value_without_fixing(
    model: ca.Model, plate: ca.ModelPart
) -> None:
    process = _create(model, "Structure.Bottom", "DISPLACEMENT_X", value=2.5, constrained=False)
    _start_step(plate, process, 1.0)
    bottom = plate.GetSubModelPart("Bottom")
    assert set(_values(bottom, ca.DISPLACEMENT_X).values()) == {2.5}
    assert not any(n.IsFixed(ca.DISPLACEMENT_X) for n in bottom.Nodes)


def test_assign_scalar_fix_adds_a_missing_dof(model: ca.Model, plate: ca.ModelPart) -> None:
    node = plate.GetNode(1)
    assert not node.HasDofFor(ca.DISPLACEMENT_Z)
    process = _create(model, "Structure.Bottom", "DISPLACEMENT_Z", value=0.0)
    _start_step(plate, process, 1.0)
    assert node.HasDofFor(ca.DISPLACEMENT_Z) and node.IsFixed(ca.DISPLACEMENT_Z)


def test_assign_scalar_csv_table_interpolates_and_extrapolates(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / "table.csv").write_text("time;value\n0.0;0.0\n1.0;2.0\n2.0;3.0\n")
    monkeypatch.chdir(tmp_path)
    table = {"name": "csv_table", "filename": "table.csv", "delimiter": ";", "skiprows": 1}
    process = _create(model, "Structure.Bottom", "DISPLACEMENT_X", value=table)
    node = plate.GetNode(1)
    for time, expected in ((0.25, 0.5), (1.5, 2.5), (3.0, 4.0)):
        _start_step(plate, process, time)
        assert node.GetSolutionStepValue(ca.DISPLACEMENT_X) == pytest.approx(expected)
        process.ExecuteFinalizeSolutionStep()


def test_assign_scalar_local_axes_rotate_the_coordinates(
    model: ca.Model, plate: ca.ModelPart
) -> None:
    axes = {"origin": [0.0, 1.0, 0.0], "axes": [[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]}
    # local x = global y - 1 with these axes
    process = _create(model, "Structure.Bottom", "DISPLACEMENT_X", value="x", local_axes=axes)
    _start_step(plate, process, 1.0)
    assert set(_values(plate.GetSubModelPart("Bottom"), ca.DISPLACEMENT_X).values()) == {-1.0}


@pytest.mark.parametrize(
    ("parameters", "message"),
    [
        ({"variable_name": "DISPLACEMENT_X", "valeu": 1.0}, 'unknown key "valeu"'),
        ({"variable_name": "DISPLACEMENT_X", "valeu": 1.0}, 'did you mean "value"'),
        ({"value": 1.0}, 'missing key "variable_name"'),
        ({"variable_name": "DISPLACEMENT"}, "of kind Array"),
        ({"variable_name": "DISPLACMENT_X"}, 'did you mean "DISPLACEMENT_X"'),
        ({"variable_name": "TEMPERATURE"}, "not a historical"),
        ({"variable_name": "DISPLACEMENT_X", "value": [1.0]}, "neither a number nor a function"),
        ({"variable_name": "DISPLACEMENT_X", "value": "t.x"}, "attribute access"),
        ({"variable_name": "DISPLACEMENT_X", "interval": [0.0, "end"]}, 'a number or "End"'),
        ({"variable_name": "DISPLACEMENT_X", "interval": [1.0, 0.5]}, "ends before it begins"),
        ({"variable_name": "DISPLACEMENT_X", "constrained": "yes"}, '"constrained" has the wrong'),
    ],
)
def test_assign_scalar_bad_settings_raise_input_error(
    model: ca.Model, plate: ca.ModelPart, parameters: dict[str, object], message: str
) -> None:
    with pytest.raises(ca.InputError, match=message) as error:
        create(
            "assign_scalar_variable_process",
            {"model_part_name": "Structure.Bottom", **parameters},
            model,
        )
    assert "ProjectParameters.json › processes › test_list › [0] › Parameters" in str(error.value)


def test_assign_scalar_unknown_model_part_suggests_a_name(
    model: ca.Model, plate: ca.ModelPart
) -> None:
    with pytest.raises(ca.InputError, match='did you mean "Structure.Bottom"'):
        _create(model, "Structure.Botom", "DISPLACEMENT_X")
