"""assign_scalar_variable_to_conditions_process: condition values per step, centres, interval."""

from __future__ import annotations

from functools import partial

import pytest
from conftest import create_on

import contact_app as ca

_create = partial(create_on, "assign_scalar_variable_to_conditions_process")


def test_assign_to_conditions_time_function_per_step(model: ca.Model, plate: ca.ModelPart) -> None:
    process = _create(
        model, "Structure.Top", "NEGATIVE_FACE_PRESSURE", value="0.2*t", interval=[0.0, "End"]
    )
    process.ExecuteBeforeSolutionLoop()  # conditions are only set at step start
    assert plate.GetCondition(1).GetValue(ca.NEGATIVE_FACE_PRESSURE) == 0.0
    for time in (0.5, 1.0):
        plate.CloneTimeStep(time)
        process.ExecuteInitializeSolutionStep()
        process.ExecuteFinalizeSolutionStep()
        for condition in plate.GetSubModelPart("Top").Conditions:
            assert condition.GetValue(ca.NEGATIVE_FACE_PRESSURE) == pytest.approx(0.2 * time)
    assert not plate.GetNode(8).Has(ca.NEGATIVE_FACE_PRESSURE)


def test_assign_to_conditions_space_function_at_centres_and_interval(
    model: ca.Model, plate: ca.ModelPart
) -> None:
    process = _create(
        model, "Structure.Top", "LINE_LOAD_Y", value="x*t + 100*X", interval=[0.5, 1.0]
    )
    plate.GetNode(9).X = 2.5  # current centre of condition 1 = 1.75, initial 1.5
    plate.CloneTimeStep(1.0)
    process.ExecuteInitializeSolutionStep()
    assert plate.GetCondition(1).GetValue(ca.LINE_LOAD_Y) == pytest.approx(1.75 + 150.0)
    assert plate.GetCondition(2).GetValue(ca.LINE_LOAD_Y) == pytest.approx(0.5 + 50.0)
    plate.CloneTimeStep(2.0)
    process.ExecuteInitializeSolutionStep()  # outside the interval: the value persists
    assert plate.GetCondition(2).GetValue(ca.LINE_LOAD_Y) == pytest.approx(0.5 + 50.0)


def test_assign_to_conditions_refuses_vector_variables(
    model: ca.Model, plate: ca.ModelPart
) -> None:
    with pytest.raises(ca.InputError, match="of kind Array"):
        _create(model, "Structure.Top", "LINE_LOAD", value=1.0)
