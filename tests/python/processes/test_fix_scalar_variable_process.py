"""fix_scalar_variable_process: fixity from step start to end in the interval, values untouched."""

from __future__ import annotations

from conftest import create

import contact_app as ca


def test_fix_scalar_fixes_in_interval_without_changing_values(
    model: ca.Model, plate: ca.ModelPart
) -> None:
    process = create(
        "fix_scalar_variable_process",
        {
            "model_part_name": "Structure.Bottom",
            "variable_name": "DISPLACEMENT_Y",
            "interval": [1.0, 2.0],
        },
        model,
    )
    node = plate.GetNode(2)
    node.SetSolutionStepValue(ca.DISPLACEMENT_Y, 0, 0.125)
    states = []
    for time in (0.5, 1.0, 2.0, 3.0):
        plate.CloneTimeStep(time)
        process.ExecuteInitializeSolutionStep()
        states.append(node.IsFixed(ca.DISPLACEMENT_Y))
        process.ExecuteFinalizeSolutionStep()
        assert not node.IsFixed(ca.DISPLACEMENT_Y)
    assert states == [False, True, True, False]
    assert node.GetSolutionStepValue(ca.DISPLACEMENT_Y) == 0.125
