"""Nodes: coordinates, historical buffer, non-historical values and DoFs."""

from __future__ import annotations

import numpy as np
import pytest

import contact_app as ca


def test_node_coordinates_current_and_initial(rectangle: ca.ModelPart) -> None:
    node = rectangle.GetNode(6)
    assert (node.Id, node.X, node.Y, node.Z) == (6, 2.0, 3.0, 0.0)
    node.X = 2.5
    assert node.X == 2.5 and node.X0 == 2.0
    np.testing.assert_array_equal(node.Coordinates(), [2.5, 3.0, 0.0])
    np.testing.assert_array_equal(node.InitialCoordinates(), [2.0, 3.0, 0.0])
    assert node.Coordinates().shape == (3,)


def test_node_historical_values_vector_and_components(rectangle: ca.ModelPart) -> None:
    node = rectangle.GetNode(2)
    node.SetSolutionStepValue(ca.DISPLACEMENT, 0, [0.1, 0.2, 0.3])
    np.testing.assert_allclose(node.GetSolutionStepValue(ca.DISPLACEMENT), [0.1, 0.2, 0.3])
    assert node.GetSolutionStepValue(ca.DISPLACEMENT_Y) == pytest.approx(0.2)
    node.SetSolutionStepValue(ca.DISPLACEMENT_Z, 0, 7.0)
    node.SetSolutionStepValue(ca.REACTION, (1.0, 2.0, 3.0))
    node.SetSolutionStepValue(ca.REACTION_X, 4)
    np.testing.assert_allclose(node.GetSolutionStepValue(ca.DISPLACEMENT, 0), [0.1, 0.2, 7.0])
    np.testing.assert_allclose(node.GetSolutionStepValue(ca.REACTION), [4.0, 2.0, 3.0])
    assert node.SolutionStepsDataHas(ca.DISPLACEMENT_X)
    assert not node.SolutionStepsDataHas(ca.VELOCITY)


def test_node_clone_time_step_shifts_the_buffer(rectangle: ca.ModelPart) -> None:
    node = rectangle.GetNode(1)
    assert node.GetBufferSize() == 2
    node.SetSolutionStepValue(ca.DISPLACEMENT_X, 0, 1.0)
    rectangle.CloneTimeStep(0.5)
    assert node.GetSolutionStepValue(ca.DISPLACEMENT_X, 1) == 1.0
    assert node.GetSolutionStepValue(ca.DISPLACEMENT_X, 0) == 1.0  # carried forward
    node.SetSolutionStepValue(ca.DISPLACEMENT_X, 0, 2.0)
    assert node.GetSolutionStepValue(ca.DISPLACEMENT_X, 1) == 1.0
    rectangle.CloneTimeStep(0.75)
    assert node.GetSolutionStepValue(ca.DISPLACEMENT_X, 1) == 2.0
    info = rectangle.ProcessInfo
    assert (
        info[ca.TIME] == 0.75 and info[ca.DELTA_TIME] == pytest.approx(0.25) and info[ca.STEP] == 2
    )


def test_node_step_outside_buffer_raises(rectangle: ca.ModelPart) -> None:
    with pytest.raises(ca.InputError, match="buffer step 2 .* outside the buffer"):
        rectangle.GetNode(1).GetSolutionStepValue(ca.DISPLACEMENT_X, 2)


def test_node_undeclared_historical_variable_raises(rectangle: ca.ModelPart) -> None:
    with pytest.raises(ca.InputError, match=r"AddNodalSolutionStepVariable\(VELOCITY\)"):
        rectangle.GetNode(1).GetSolutionStepValue(ca.VELOCITY_X)


def test_node_non_double_historical_variable_raises(rectangle: ca.ModelPart) -> None:
    node = rectangle.GetNode(1)
    with pytest.raises(
        ca.InputError, match="STEP of type Integer cannot be stored as a solution-step"
    ):
        node.GetSolutionStepValue(ca.STEP)
    with pytest.raises(ca.InputError, match="cannot be stored as a solution-step"):
        node.SetSolutionStepValue(ca.CAUCHY_STRESS_VECTOR, 0, [1.0])
    with pytest.raises(TypeError, match="DISPLACEMENT of type Array cannot take the value 'x'"):
        node.SetSolutionStepValue(ca.DISPLACEMENT, "x")


def test_node_non_historical_values(rectangle: ca.ModelPart) -> None:
    node = rectangle.GetNode(3)
    assert not node.Has(ca.NODAL_AREA)
    assert node.GetValue(ca.NODAL_AREA) == 0.0
    node.SetValue(ca.NODAL_AREA, 0.25)
    node.SetValue(ca.NORMAL, [0.0, 1.0, 0.0])
    node.SetValue(ca.TYING_VARIABLE, "DISPLACEMENT")
    assert node.Has(ca.NODAL_AREA) and node.GetValue(ca.NODAL_AREA) == 0.25
    assert node.GetValue(ca.NORMAL_Y) == 1.0
    assert node.GetValue(ca.TYING_VARIABLE) == "DISPLACEMENT"
    # Non-historical and historical storage are separate.
    assert node.GetSolutionStepValue(ca.DISPLACEMENT_X) == 0.0


def test_node_dof_fix_and_free(rectangle: ca.ModelPart) -> None:
    node = rectangle.GetNode(4)
    dof = node.AddDof(ca.DISPLACEMENT_X, ca.REACTION_X)
    assert isinstance(dof, ca.Dof)
    assert dof.Id() == 4
    assert dof.GetVariable() == ca.DISPLACEMENT_X and dof.GetReaction().Name() == "REACTION_X"
    assert node.HasDofFor(ca.DISPLACEMENT_X) and not node.HasDofFor(ca.DISPLACEMENT_Y)
    assert not node.IsFixed(ca.DISPLACEMENT_X)
    node.Fix(ca.DISPLACEMENT_X)
    assert node.IsFixed(ca.DISPLACEMENT_X) and dof.IsFixed()
    node.Free(ca.DISPLACEMENT_X)
    assert not node.IsFixed(ca.DISPLACEMENT_X) and dof.IsFree()
    dof.EquationId = 11
    assert node.GetDof(ca.DISPLACEMENT_X).EquationId == 11
    node.SetSolutionStepValue(ca.DISPLACEMENT_X, 0, 0.5)
    assert dof.GetSolutionStepValue() == 0.5


def test_node_fix_adds_the_dof(rectangle: ca.ModelPart) -> None:
    node = rectangle.GetNode(5)
    node.Fix(ca.DISPLACEMENT_Y)
    assert node.IsFixed(ca.DISPLACEMENT_Y)
    assert [dof.GetVariable().Name() for dof in node.GetDofs()] == ["DISPLACEMENT_Y"]


def test_node_add_dof_of_non_historical_variable_raises(rectangle: ca.ModelPart) -> None:
    with pytest.raises(
        ca.InputError, match="cannot add the DoF TEMPERATURE .* not a solution-step variable"
    ):
        rectangle.GetNode(1).AddDof(ca.TEMPERATURE)


def test_node_missing_dof_raises(rectangle: ca.ModelPart) -> None:
    node = rectangle.GetNode(1)
    node.AddDof(ca.DISPLACEMENT_X)
    with pytest.raises(ca.InputError, match="node 1 has no DoF for DISPLACEMENT_Y"):
        node.GetDof(ca.DISPLACEMENT_Y)
    with pytest.raises(ca.InputError, match="has no DoF"):
        node.Free(ca.DISPLACEMENT_Z)


def test_node_dof_keeps_its_node_alive() -> None:
    model_part = ca.Model().CreateModelPart("Alive")
    model_part.AddNodalSolutionStepVariable(ca.DISPLACEMENT)
    dof = model_part.CreateNewNode(1, 0.0, 0.0, 0.0).AddDof(ca.DISPLACEMENT_X)
    del model_part
    assert dof.Id() == 1 and dof.GetSolutionStepValue() == 0.0


def test_node_identity_and_flags(rectangle: ca.ModelPart) -> None:
    node = rectangle.GetNode(1)
    assert node == rectangle.GetNode(1)
    assert node != rectangle.GetNode(2)
    node.Set(ca.SLAVE)
    assert rectangle.GetNode(1).Is(ca.SLAVE)
    assert repr(node) == "<Node 1 at (0.0, 0.0, 0.0)>"


def test_variable_utils_update_current_position(rectangle: ca.ModelPart) -> None:
    for node in rectangle.Nodes:
        node.SetSolutionStepValue(ca.DISPLACEMENT, 0, [0.1 * node.Id, 0.0, -1.0])
    node = rectangle.GetNode(3)
    node.X = 99.0
    ca.VariableUtils().UpdateCurrentPosition(rectangle.Nodes)
    np.testing.assert_allclose(node.Coordinates(), [2.3, 0.0, -1.0])
    node.SetSolutionStepValue(ca.DISPLACEMENT_X, 0, 0.0)
    ca.VariableUtils().UpdateCurrentPosition([node])
    assert node.X == 2.0 and node.X0 == 2.0


def test_variable_utils_set_flag_on_a_container_sets_exactly_its_entities(
    rectangle: ca.ModelPart,
) -> None:
    properties = rectangle.GetProperties(1)
    element = rectangle.CreateNewElement("Element2D4N", 1, [1, 2, 5, 4], properties)
    condition = rectangle.CreateNewCondition("LineCondition2D2N", 1, [1, 2], properties)
    left = rectangle.CreateSubModelPart("Left")
    left.AddNodes([1, 4])
    utils = ca.VariableUtils()
    utils.SetFlag(ca.SLIP, True, left.Nodes)  # the C++ loop over a model part's container
    assert [node.Id for node in rectangle.Nodes if node.Is(ca.SLIP)] == [1, 4]
    utils.SetFlag(ca.SLIP, False, rectangle.Nodes)
    assert not any(node.Is(ca.SLIP) for node in rectangle.Nodes)
    utils.SetFlag(ca.ACTIVE, True, rectangle.Conditions)
    utils.SetFlag(ca.MARKER, True, rectangle.Elements)
    assert condition.Is(ca.ACTIVE) and not element.Is(ca.ACTIVE)
    assert element.Is(ca.MARKER) and not condition.Is(ca.MARKER)
    utils.SetFlag(ca.SLIP, True, [rectangle.GetNode(6)])  # any iterable still works
    assert [node.Id for node in rectangle.Nodes if node.Is(ca.SLIP)] == [6]
