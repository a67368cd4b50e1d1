"""assign_vector_by_direction_process: unit direction times modulus, 2D/3D, automatic normals."""

from __future__ import annotations

from functools import partial

import numpy as np
import pytest
from conftest import create_on

import contact_app as ca

_create = partial(create_on, "assign_vector_by_direction_process", variable="DISPLACEMENT")


def test_assign_by_direction_normalises_and_fixes_per_step(
    model: ca.Model, plate: ca.ModelPart
) -> None:
    process = _create(
        model, "Structure.Top", modulus="0.5*t", direction=[3.0, 4.0, 0.0], interval=[0.0, "End"]
    )
    node = plate.GetNode(7)
    for time in (1.0, 2.0):
        plate.CloneTimeStep(time)
        process.ExecuteInitializeSolutionStep()
        np.testing.assert_allclose(
            node.GetSolutionStepValue(ca.DISPLACEMENT), [0.3 * time, 0.4 * time, 0.0], rtol=1e-14
        )
        assert node.IsFixed(ca.DISPLACEMENT_X) and node.IsFixed(ca.DISPLACEMENT_Y)
        assert not node.HasDofFor(ca.DISPLACEMENT_Z)  # 2D: only X and Y
        process.ExecuteFinalizeSolutionStep()
        assert not node.IsFixed(ca.DISPLACEMENT_X)


def test_assign_by_direction_3d_assigns_z_and_numeric_modulus(
    model: ca.Model, plate: ca.ModelPart
) -> None:
    plate.ProcessInfo[ca.DOMAIN_SIZE] = 3
    process = _create(
        model, "Structure.Bottom", modulus=2.0, direction=[0.0, 0.0, -5.0], constrained=False
    )
    process.ExecuteBeforeSolutionLoop()
    np.testing.assert_allclose(plate.GetNode(1).GetSolutionStepValue(ca.DISPLACEMENT), [0, 0, -2])
    assert not plate.GetNode(1).IsFixed(ca.DISPLACEMENT_Z)


def test_assign_by_direction_automatic_normals(model: ca.Model, plate: ca.ModelPart) -> None:
    for kind, sign in (("automatic_outwards_normal", 1.0), ("automatic_inwards_normal", -1.0)):
        process = _create(model, "Structure.Top", modulus=3.0, direction=kind)
        process.ExecuteBeforeSolutionLoop()
        np.testing.assert_allclose(
            plate.GetNode(8).GetSolutionStepValue(ca.DISPLACEMENT),
            [0.0, 3.0 * sign, 0.0],
            atol=1e-15,
        )


def test_assign_by_direction_function_direction_is_not_normalised(
    model: ca.Model, plate: ca.ModelPart
) -> None:
    process = _create(model, "Structure.Top", modulus=2.0, direction=["t", 1.0, 0.0])
    plate.CloneTimeStep(3.0)
    process.ExecuteInitializeSolutionStep()
    np.testing.assert_allclose(plate.GetNode(9).GetSolutionStepValue(ca.DISPLACEMENT), [6, 2, 0])


@pytest.mark.parametrize(
    ("parameters", "message"),
    [
        ({"direction": [0.0, 0.0, 0.0]}, "has length 0"),
        ({"direction": "inwards"}, 'unknown direction "inwards"'),
        ({"direction": [1.0, 0.0]}, "is not valid"),
        ({"modulus": [1.0]}, "a number or a function string"),
        ({"modulus": "2*tt"}, 'unknown name "tt"'),
    ],
)
def test_assign_by_direction_bad_settings_raise_input_error(
    model: ca.Model, plate: ca.ModelPart, parameters: dict[str, object], message: str
) -> None:
    settings = {"modulus": 1.0, "direction": [1.0, 0.0, 0.0], **parameters}
    with pytest.raises(ca.InputError, match=message):
        _create(model, "Structure.Top", **settings)


def test_assign_by_direction_needs_a_domain_size(model: ca.Model, plate: ca.ModelPart) -> None:
    plate.ProcessInfo[ca.DOMAIN_SIZE] = 0
    with pytest.raises(ca.InputError, match="set solver_settings.domain_size"):
        _create(model, "Structure.Top", modulus=1.0, direction=[1.0, 0.0, 0.0])


def test_assign_by_direction_automatic_without_conditions_is_an_error(
    model: ca.Model, plate: ca.ModelPart
) -> None:
    with pytest.raises(ca.InputError, match="it has no conditions"):
        _create(model, "Structure.Bottom", modulus=1.0, direction="automatic_inwards_normal")
