"""Elements, conditions and constraints: the Kratos entity API through Python."""

from __future__ import annotations

import numpy as np
import pytest

import contact_app as ca


@pytest.fixture
def element(rectangle: ca.ModelPart) -> ca.Element:
    return rectangle.CreateNewElement("Element2D4N", 1, [1, 2, 5, 4], rectangle.GetProperties(1))


def test_registered_entities_are_sorted_and_complete() -> None:
    for names in (
        ca.registered_elements(),
        ca.registered_conditions(),
        ca.registered_constraints(),
        ca.registered_constitutive_laws(),
    ):
        assert names == sorted(names)
    assert {"Element2D3N", "Element2D4N", "Element3D8N"} <= set(ca.registered_elements())
    assert {"LineCondition2D2N", "SurfaceCondition3D4N"} <= set(ca.registered_conditions())
    assert "LinearMasterSlaveConstraint" in ca.registered_constraints()


def test_mesh_element_local_system_is_empty(rectangle: ca.ModelPart, element: ca.Element) -> None:
    info = rectangle.ProcessInfo
    lhs, rhs = element.CalculateLocalSystem(info)
    assert isinstance(lhs, np.ndarray) and lhs.shape == (0, 0)
    assert isinstance(rhs, np.ndarray) and rhs.shape == (0,)
    assert element.CalculateLeftHandSide(info).shape == (0, 0)
    assert element.CalculateRightHandSide(info).shape == (0,)
    assert element.CalculateMassMatrix(info).shape == (0, 0)
    assert element.CalculateDampingMatrix(info).shape == (0, 0)
    assert element.EquationIdVector(info) == []
    assert element.GetDofList(info) == []
    assert element.GetValuesVector().shape == (0,)


@pytest.mark.parametrize("name", ["LineCondition2D2N", "Condition2D"])
def test_mesh_condition_local_system_is_empty(rectangle: ca.ModelPart, name: str) -> None:
    condition = rectangle.CreateNewCondition(name, 1, [1, 2], rectangle.GetProperties(1))
    lhs, rhs = condition.CalculateLocalSystem(rectangle.ProcessInfo)
    assert lhs.shape == (0, 0) and rhs.shape == (0,)
    assert condition.EquationIdVector(rectangle.ProcessInfo) == []


def test_entity_life_cycle_hooks_and_check(rectangle: ca.ModelPart, element: ca.Element) -> None:
    info = rectangle.ProcessInfo
    element.Initialize(info)
    element.InitializeSolutionStep(info)
    element.InitializeNonLinearIteration(info)
    element.FinalizeNonLinearIteration(info)
    element.FinalizeSolutionStep(info)
    element.AddExplicitContribution(info)
    assert element.Check(info) == 0


def test_entity_geometry_and_properties(rectangle: ca.ModelPart, element: ca.Element) -> None:
    assert element.Id == 1
    assert [node.Id for node in element.GetGeometry()] == [1, 2, 5, 4]
    assert element.GetNodes() == list(element.GetGeometry())
    assert element.GetGeometry().Area() == pytest.approx(3.0)
    assert element.GetProperties() == rectangle.GetProperties(1)
    assert element.Properties.Id == 1
    element.Properties = rectangle.CreateNewProperties(2)
    assert element.GetProperties().Id == 2


def test_entity_without_properties_raises_on_get_properties(rectangle: ca.ModelPart) -> None:
    element = rectangle.CreateNewElement("Element2D2N", 5, [1, 2], None)
    assert element.Properties is None
    with pytest.raises(ca.InputError, match="element 5 has no properties"):
        element.GetProperties()


def test_entity_values_and_flags(rectangle: ca.ModelPart, element: ca.Element) -> None:
    element.SetValue(ca.NORMAL, [0.0, 0.0, 1.0])
    element.SetValue(ca.TYING_VARIABLE, "DISPLACEMENT")
    element.Set(ca.ACTIVE)
    element.Set(ca.SLIP, False)
    same = rectangle.GetElement(1)
    np.testing.assert_array_equal(same.GetValue(ca.NORMAL), [0.0, 0.0, 1.0])
    assert same.GetValue(ca.NORMAL_Z) == 1.0 and same.Has(ca.NORMAL)
    assert same.GetValue(ca.TYING_VARIABLE) == "DISPLACEMENT"
    assert same.Is(ca.ACTIVE) and same.IsNot(ca.SLIP) and not same.IsDefined(ca.SLAVE)
    assert same == element


def test_entity_info_and_repr(rectangle: ca.ModelPart, element: ca.Element) -> None:
    condition = rectangle.CreateNewCondition(
        "LineCondition2D2N", 3, [1, 2], rectangle.GetProperties(1)
    )
    assert element.Info() == "Element #1 (Quadrilateral2D4)"
    assert repr(condition) == "<Condition #3 (Line2D2)>"


def test_entity_integration_point_results_raise_for_mesh_entities(
    rectangle: ca.ModelPart, element: ca.Element
) -> None:
    with pytest.raises(ca.InputError, match="cannot compute VON_MISES_STRESS"):
        element.CalculateOnIntegrationPoints(ca.VON_MISES_STRESS, rectangle.ProcessInfo)


def test_constraint_dof_lists_stay_valid(rectangle: ca.ModelPart) -> None:
    # The DoF objects of a constraint stay usable after the Python constraint object is gone.
    node = rectangle.GetNode(1)
    node.AddDof(ca.DISPLACEMENT_X)
    rectangle.GetNode(2).AddDof(ca.DISPLACEMENT_X)
    constraint = rectangle.CreateNewMasterSlaveConstraint(
        "LinearMasterSlaveConstraint",
        1,
        node,
        ca.DISPLACEMENT_X,
        rectangle.GetNode(2),
        ca.DISPLACEMENT_X,
        1.0,
        0.0,
    )
    slave_dofs = constraint.GetSlaveDofsVector()
    del constraint
    assert slave_dofs[0].Id() == 2 and slave_dofs[0].GetVariable().Name() == "DISPLACEMENT_X"
