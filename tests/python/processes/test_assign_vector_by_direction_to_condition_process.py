"""assign_vector_by_direction_to_condition_process: modulus times direction on conditions."""

from __future__ import annotations

from functools import partial

import numpy as np
import pytest
from conftest import create_on

import contact_app as ca

_create = partial(
    create_on, "assign_vector_by_direction_to_condition_process", variable="LINE_LOAD"
)


def test_by_direction_to_conditions_as_in_the_3d_kratos_case(
    model: ca.Model, plate: ca.ModelPart
) -> None:
    down = [0.0, 0.0, -1.0]
    process = _create(
        model, "Structure.Top", mesh_id=0, modulus=1.0e9, direction=down, interval=[0.0, "End"]
    )
    plate.CloneTimeStep(1.1)
    process.ExecuteInitializeSolutionStep()
    for condition in plate.GetSubModelPart("Top").Conditions:
        np.testing.assert_allclose(condition.GetValue(ca.LINE_LOAD), [0.0, 0.0, -1.0e9])


def test_by_direction_to_conditions_time_modulus_and_inward_normal(
    model: ca.Model, plate: ca.ModelPart
) -> None:
    inwards = "automatic_inwards_normal"
    process = _create(
        model, "Structure.Top", modulus="10*t", direction=inwards, interval=[0.0, 1.0]
    )
    # Kratos' interval: with begin 0 the end itself (t = 1.0) is outside; values persist after
    for time, load in ((0.5, -5.0), (0.75, -7.5), (1.0, -7.5), (2.0, -7.5)):
        plate.CloneTimeStep(time)
        process.ExecuteInitializeSolutionStep()
        np.testing.assert_allclose(
            plate.GetCondition(1).GetValue(ca.LINE_LOAD), [0.0, load, 0.0], atol=1e-14
        )


def test_by_direction_to_conditions_tiny_direction_is_an_error(
    model: ca.Model, plate: ca.ModelPart
) -> None:
    with pytest.raises(ca.InputError, match="has length 1e-07"):
        _create(model, "Structure.Top", modulus=1.0, direction=[1e-7, 0.0, 0.0])
