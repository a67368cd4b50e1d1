"""fix_vector_variable_process: chosen components fixed per step, the others left alone."""

from __future__ import annotations

import pytest
from conftest import create

import contact_app as ca


def test_fix_vector_fixes_chosen_components_per_step(model: ca.Model, plate: ca.ModelPart) -> None:
    process = create(
        "fix_vector_variable_process",
        {
            "model_part_name": "Structure.Top",
            "variable_name": "DISPLACEMENT",
            "constrained": [True, False, False],
        },
        model,
    )
    process.ExecuteBeforeSolutionLoop()
    node = plate.GetNode(7)
    assert node.IsFixed(ca.DISPLACEMENT_X) and not node.IsFixed(ca.DISPLACEMENT_Y)
    process.ExecuteFinalizeSolutionStep()
    assert not node.IsFixed(ca.DISPLACEMENT_X)
    assert node.GetSolutionStepValue(ca.DISPLACEMENT_X) == 0.0


def test_fix_vector_refuses_scalar_variables(model: ca.Model, plate: ca.ModelPart) -> None:
    with pytest.raises(ca.InputError, match="of kind Component"):
        create(
            "fix_vector_variable_process",
            {"model_part_name": "Structure.Top", "variable_name": "DISPLACEMENT_X"},
            model,
        )
