"""assign_vector_by_direction_to_condition_process: modulus times direction on conditions."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import create

import contact_app as ca


def test_by_direction_to_conditions_as_in_the_3d_kratos_case(
    model: ca.Model, plate: ca.ModelPart
) -> None:
    process = create(
        "assign_vector_by_direction_to_condition_process",
        {
            "mesh_id": 0,
            "model_part_name": "Structure.Top",
            "variable_name": "LINE_LOAD",
            "modulus": 1.0e9,
            "direction": [0.0, 0.0, -1.0],
            "interval": [0.0, "End"],
        },
        model,
    )
    plate.CloneTimeStep(1.1)
    process.ExecuteInitializeSolutionStep()
    for condition in plate.GetSubModelPart("Top").Conditions:
        np.testing.assert_allclose(condition.GetValue(ca.LINE_LOAD), [0.0, 0.0, -1.0e9])


def test_by_direction_to_conditions_time_modulus_and_inward_normal(
    model: ca.Model, plate: ca.ModelPart
) -> None:
    process = create(
        "assign_vector_by_direction_to_condition_process",
        {
            "model_part_name": "Structure.Top",
            "variable_name": "LINE_LOAD",
            "modulus": "10*t",
            "direction": "automatic_inwards_normal",
            "interval": [0.0, 1.0],
        },
        model,
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
        create(
            "assign_vector_by_direction_to_condition_process",
            {
                "model_part_name": "Structure.Top",
                "variable_name": "LINE_LOAD",
                "modulus": 1.0,
                "direction": [1e-7, 0.0, 0.0],
            },
            model,
        )
