"""assign_vector_variable_process: per-component values and fixity, null components, errors."""

from __future__ import annotations

from functools import partial

import numpy as np
import pytest
from conftest import create, create_on, run_steps

import contact_app as ca

_create = partial(create_on, "assign_vector_variable_process", variable="DISPLACEMENT")


def test_assign_vector_components_values_and_fixity_per_step(
    model: ca.Model, plate: ca.ModelPart
) -> None:
    process = _create(
        model,
        "Structure.Top",
        mesh_id=0,
        value=[0.0, "-2.0e-1*t", "0.1*y*t"],
        constrained=[False, True, True],
        interval=[0.0, "End"],
    )
    node = plate.GetNode(8)
    process.ExecuteBeforeSolutionLoop()
    np.testing.assert_allclose(node.GetSolutionStepValue(ca.DISPLACEMENT), [0.0, 0.0, 0.0])
    for time in (0.25, 0.5):
        plate.CloneTimeStep(time)
        node.SetSolutionStepValue(ca.DISPLACEMENT_X, 0, 9.0)
        process.ExecuteInitializeSolutionStep()
        np.testing.assert_allclose(
            node.GetSolutionStepValue(ca.DISPLACEMENT), [0.0, -0.2 * time, 0.2 * time]
        )
        assert [
            node.IsFixed(v) for v in (ca.DISPLACEMENT_X, ca.DISPLACEMENT_Y, ca.DISPLACEMENT_Z)
        ] == [False, True, True]
        process.ExecuteFinalizeSolutionStep()
        assert not node.IsFixed(ca.DISPLACEMENT_Y) and not node.IsFixed(ca.DISPLACEMENT_Z)


def test_assign_vector_null_component_is_untouched(model: ca.Model, plate: ca.ModelPart) -> None:
    process = _create(model, "Structure.Bottom", value=[None, 0.5, None])
    node = plate.GetNode(3)
    node.SetSolutionStepValue(ca.DISPLACEMENT, 0, [7.0, 8.0, 9.0])
    run_steps(plate, [process], [1.0])
    np.testing.assert_allclose(node.GetSolutionStepValue(ca.DISPLACEMENT), [7.0, 0.5, 9.0])
    plate.CloneTimeStep(2.0)
    process.ExecuteInitializeSolutionStep()
    assert node.IsFixed(ca.DISPLACEMENT_Y)
    assert not node.IsFixed(ca.DISPLACEMENT_X) and not node.HasDofFor(ca.DISPLACEMENT_Z)


def test_assign_vector_single_constrained_bool_is_broadcast(
    model: ca.Model, plate: ca.ModelPart
) -> None:
    process = _create(model, "Structure.Bottom", constrained=False)
    plate.CloneTimeStep(1.0)
    process.ExecuteInitializeSolutionStep()
    assert not any(n.IsFixed(ca.DISPLACEMENT_X) for n in plate.Nodes)
    default = _create(model, "Structure.Bottom")
    default.ExecuteInitializeSolutionStep()
    bottom = plate.GetSubModelPart("Bottom")
    assert all(n.IsFixed(ca.DISPLACEMENT_X) and n.IsFixed(ca.DISPLACEMENT_Z) for n in bottom.Nodes)


def test_assign_vector_interval_respected(model: ca.Model, plate: ca.ModelPart) -> None:
    process = _create(model, "Structure.Top", value=["t", "2*t", None], interval=[1.0, 2.0])
    node = plate.GetNode(9)
    seen = []
    for time in (0.5, 1.0, 2.0, 3.0):
        plate.CloneTimeStep(time)
        process.ExecuteInitializeSolutionStep()
        seen.append(
            (*node.GetSolutionStepValue(ca.DISPLACEMENT)[:2], node.IsFixed(ca.DISPLACEMENT_X))
        )
        process.ExecuteFinalizeSolutionStep()
    assert seen == [(0.0, 0.0, False), (1.0, 2.0, True), (2.0, 4.0, True), (2.0, 4.0, False)]


@pytest.mark.parametrize(
    ("parameters", "message"),
    [
        ({"variable_name": "DISPLACEMENT_X"}, "of kind Component"),
        ({"variable_name": "DISPLACEMENT", "value": [0.0, 0.0]}, "not an array of 3 entries"),
        ({"variable_name": "DISPLACEMENT", "constrained": [True, False]}, "array of 3 of them"),
        ({"variable_name": "DISPLACEMENT", "value": [0.0, "t*", 0.0]}, "not a valid expression"),
        ({"variable_name": "DISPLACEMENT", "value": [0.0, True, 0.0]}, "neither a number"),
    ],
)
def test_assign_vector_bad_settings_raise_input_error(
    model: ca.Model, plate: ca.ModelPart, parameters: dict[str, object], message: str
) -> None:
    with pytest.raises(ca.InputError, match=message):
        create(
            "assign_vector_variable_process",
            {"model_part_name": "Structure.Bottom", **parameters},
            model,
        )
