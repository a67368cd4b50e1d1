"""Meshes read through meshio: cell blocks → entities, physical groups → sub model parts."""

from __future__ import annotations

import meshio
import numpy as np
import pytest

import contact_app as ca
from contact_app.io import ImportMeshioModelPart


def _write_two_quads(path):
    """Two unit quads side by side, their top edges as lines; groups body (2D) and top (1D)."""
    points = np.array(
        [[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0]], dtype=float
    )
    cells = [("quad", np.array([[0, 1, 4, 3], [1, 2, 5, 4]])), ("line", np.array([[3, 4], [4, 5]]))]
    mesh = meshio.Mesh(
        points,
        cells,
        cell_data={
            "gmsh:physical": [np.array([1, 1]), np.array([2, 2])],
            "gmsh:geometrical": [np.array([1, 1]), np.array([2, 2])],
        },
        field_data={"body": np.array([1, 2]), "top": np.array([2, 1])},
    )
    meshio.write(str(path), mesh, file_format="gmsh22", binary=False)


MAPPING = {
    "elements": {"quad": "SmallDisplacementElement2D4N"},
    "conditions": {"line": "LineCondition2D2N"},
}


@pytest.fixture
def part():
    model = ca.Model()
    mp = model.CreateModelPart("Structure")
    mp.AddNodalSolutionStepVariable(ca.DISPLACEMENT)
    return mp


def test_cells_and_groups_become_entities_and_sub_model_parts(part, tmp_path):
    path = tmp_path / "two_quads.msh"
    _write_two_quads(path)
    ImportMeshioModelPart(
        part, path, {**MAPPING, "sub_model_parts": {"top": "Contact_Top"}}, "test"
    )
    assert part.NumberOfNodes() == 6
    assert part.NumberOfElements() == 2
    assert part.NumberOfConditions() == 2
    body = part.GetSubModelPart("body")
    top = part.GetSubModelPart("Contact_Top")
    assert body.NumberOfElements() == 2 and body.NumberOfNodes() == 6
    assert top.NumberOfConditions() == 2 and sorted(n.Id for n in top.Nodes) == [4, 5, 6]
    assert part.GetNode(5).X == pytest.approx(1.0) and part.GetNode(5).Y == pytest.approx(1.0)


@pytest.mark.parametrize(
    ("mapping", "message"),
    [
        ({"elements": {"quad": "SmallDisplacementElement2D4N"}}, 'has "line" cells'),
        ({**MAPPING, "elements": {"quad": "SmallDisplacementElement2D3N"}}, "has 3 nodes"),
        ({**MAPPING, "elements": {"quad": "SmalDisplacementElement2D4N"}}, "not a registered"),
        ({**MAPPING, "elements": {"quadrangle": "X"}}, "unknown meshio cell type"),
        ({**MAPPING, "sub_model_parts": {"bottom": "B"}}, 'group "bottom"'),
        ({**MAPPING, "element": {}}, 'unknown key "element"'),
        ({**MAPPING, "conditions": {"line": "LineCondition2D2N", "triangle": "X"}}, "triangle"),
    ],
)
def test_bad_mappings_are_clear_errors(part, tmp_path, mapping, message):
    path = tmp_path / "two_quads.msh"
    _write_two_quads(path)
    with pytest.raises(ca.InputError, match=message):
        ImportMeshioModelPart(part, path, mapping, "ProjectParameters.json › mesh_mapping")


def test_unreadable_file_names_the_file(part, tmp_path):
    path = tmp_path / "broken.msh"
    path.write_text("not a mesh")
    with pytest.raises(ca.InputError, match="broken.msh"):
        ImportMeshioModelPart(part, path, MAPPING, "test")
