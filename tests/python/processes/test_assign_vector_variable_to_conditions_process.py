"""assign_vector_variable_to_conditions_process: components on conditions, null untouched."""

from __future__ import annotations

import numpy as np
from conftest import create

import contact_app as ca


def test_assign_vector_to_conditions_components_and_null(
    model: ca.Model, plate: ca.ModelPart
) -> None:
    process = create(
        "assign_vector_variable_to_conditions_process",
        {
            "model_part_name": "Structure.Top",
            "variable_name": "LINE_LOAD",
            "value": ["t", None, -1.0],
            "interval": [0.0, "End"],
        },
        model,
    )
    plate.GetCondition(2).SetValue(ca.LINE_LOAD, [5.0, 6.0, 7.0])
    for time in (0.5, 1.5):
        plate.CloneTimeStep(time)
        process.ExecuteInitializeSolutionStep()
        np.testing.assert_allclose(plate.GetCondition(2).GetValue(ca.LINE_LOAD), [time, 6.0, -1.0])
        np.testing.assert_allclose(plate.GetCondition(1).GetValue(ca.LINE_LOAD), [time, 0.0, -1.0])
