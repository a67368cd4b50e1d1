"""Geometries through Python: measures, shape functions, mappings and node access."""

from __future__ import annotations

import numpy as np
import pytest

import contact_app as ca


@pytest.fixture
def quad(rectangle: ca.ModelPart) -> ca.Geometry:
    """Return the 2 x 3 rectangle [0, 2] x [0, 3] as one Element2D4N (nodes 1, 3, 6, 4)."""
    element = rectangle.CreateNewElement("Element2D4N", 1, [1, 3, 6, 4], rectangle.GetProperties(1))
    return element.GetGeometry()


def test_geometry_rectangle_area(quad: ca.Geometry) -> None:
    assert quad.Name() == "Quadrilateral2D4"
    assert quad.Area() == pytest.approx(6.0)
    assert quad.DomainSize() == pytest.approx(6.0)
    np.testing.assert_allclose(quad.Center(), [1.0, 1.5, 0.0])
    assert (quad.WorkingSpaceDimension(), quad.LocalSpaceDimension()) == (2, 2)


def test_geometry_wrong_measure_raises(quad: ca.Geometry) -> None:
    with pytest.raises(ca.InputError, match="DomainSize"):
        quad.Length()


def test_geometry_nodes_are_the_model_part_nodes(
    rectangle: ca.ModelPart, quad: ca.Geometry
) -> None:
    assert len(quad) == quad.PointsNumber() == 4
    assert [node.Id for node in quad] == [1, 3, 6, 4]
    assert quad[0] == rectangle.GetNode(1) and quad[-1].Id == 4
    with pytest.raises(IndexError):
        quad[4]
    rectangle.GetNode(6).X = 4.0  # moving a node moves the geometry: trapezoid of area 9
    assert quad.Area() == pytest.approx(9.0)


def test_geometry_shape_functions_partition_unity(quad: ca.Geometry) -> None:
    values = quad.ShapeFunctionsValues([0.3, -0.2])
    assert values.shape == (4,) and values.sum() == pytest.approx(1.0)
    np.testing.assert_allclose(quad.ShapeFunctionsValues([-1.0, -1.0, 0.0]), [1.0, 0.0, 0.0, 0.0])
    gradients = quad.ShapeFunctionsLocalGradients([0.0, 0.0])
    assert gradients.shape == (4, 2)
    np.testing.assert_allclose(gradients.sum(axis=0), [0.0, 0.0], atol=1e-14)
    assert quad.ShapeFunctionValue(2, [1.0, 1.0]) == pytest.approx(1.0)


def test_geometry_jacobian_and_mapping(quad: ca.Geometry) -> None:
    np.testing.assert_allclose(quad.Jacobian([0.0, 0.0]), [[1.0, 0.0], [0.0, 1.5]])
    assert quad.DeterminantOfJacobian([0.5, 0.5]) == pytest.approx(1.5)
    np.testing.assert_allclose(quad.InverseOfJacobian([0.0, 0.0]), [[1.0, 0.0], [0.0, 1.0 / 1.5]])
    np.testing.assert_allclose(quad.GlobalCoordinates([1.0, 1.0]), [2.0, 3.0, 0.0])
    np.testing.assert_allclose(
        quad.PointLocalCoordinates([1.5, 0.75]), [0.5, -0.5, 0.0], atol=1e-12
    )


def test_geometry_is_inside(quad: ca.Geometry) -> None:
    inside, local = quad.IsInside([1.0, 1.5, 0.0])
    assert inside and np.allclose(local, [0.0, 0.0, 0.0])
    outside, local = quad.IsInside([3.0, 1.5])
    assert not outside and local[0] == pytest.approx(2.0)


def test_geometry_integration_points_sum_to_reference_measure(quad: ca.Geometry) -> None:
    points = quad.IntegrationPoints()
    assert len(points) == 4 and quad.DefaultIntegrationOrder() == 2
    assert sum(weight for _, weight in points) == pytest.approx(4.0)
    assert all(local.shape == (3,) for local, _ in points)
    assert len(quad.IntegrationPoints(3)) == 9
    area = sum(weight * quad.DeterminantOfJacobian(local) for local, weight in points)
    assert area == pytest.approx(6.0)


def test_geometry_line_length_and_unit_normal(rectangle: ca.ModelPart) -> None:
    condition = rectangle.CreateNewCondition(
        "LineCondition2D2N", 1, [1, 3], rectangle.GetProperties(1)
    )
    line = condition.GetGeometry()
    assert line.Name() == "Line2D2" and line.Length() == pytest.approx(2.0)
    # The tangent (1, 0) rotated clockwise.
    np.testing.assert_allclose(line.UnitNormal([0.0]), [0.0, -1.0, 0.0], atol=1e-14)
    assert line.LocalFacesConnectivity() == [[0], [1]]


def test_geometry_tetrahedron_volume(structure: ca.ModelPart) -> None:
    for node_id, xyz in enumerate([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)], start=1):
        structure.CreateNewNode(node_id, *map(float, xyz))
    element = structure.CreateNewElement(
        "Element3D4N", 1, [1, 2, 3, 4], structure.CreateNewProperties(1)
    )
    assert element.GetGeometry().Volume() == pytest.approx(1.0 / 6.0)
    assert element.GetGeometry().FacesNumber() == 4


def test_create_geometry_by_registered_name() -> None:
    assert "Triangle2D3" in ca.registered_geometries()
    assert ca.registered_geometries() == sorted(ca.registered_geometries())
    nodes = [ca.Node(1, 0.0, 0.0, 0.0), ca.Node(2, 2.0, 0.0, 0.0), ca.Node(3, 0.0, 2.0, 0.0)]
    triangle = ca.create_geometry("Triangle2D3", nodes)
    assert triangle.Area() == pytest.approx(2.0)
    assert repr(triangle) == "<Triangle2D3 [1, 2, 3]>"
    with pytest.raises(ca.InputError, match='did you mean "Triangle2D3"'):
        ca.create_geometry("Triangle2D4", nodes)
