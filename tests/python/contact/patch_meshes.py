"""Small structured meshes for the contact patch and friction tests, written as .mdpa text.

Each body is a structured grid: quadrilaterals in 2D, hexahedra or their conforming split into six
tetrahedra (Kuhn's triangulation: every cube cut along its main diagonal, so that neighbouring cubes
cut their shared face along the same diagonal) in 3D. A body's node and entity ids start at given
offsets, so several bodies go into one file without renumbering. Interface parts are node sets;
the contact process builds the interface conditions from the element faces.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

#: Local corner order of a hexahedron (Kratos / VTK): bottom face counter-clockwise, then top.
HEX_CORNERS = (
    (0, 0, 0),
    (1, 0, 0),
    (1, 1, 0),
    (0, 1, 0),
    (0, 0, 1),
    (1, 0, 1),
    (1, 1, 1),
    (0, 1, 1),
)


@dataclass
class Body:
    """One body: node coordinates by id, element connectivities, its node-id grid.

    Attributes:
        nodes: node id -> (x, y, z).
        elements: element connectivities (node ids), all of one type.
        grid: node ids on the structured grid, indexed [i, j] (2D) or [i, j, k] (3D).
        first_element: id of the first element.

    """

    nodes: dict[int, tuple[float, float, float]]
    elements: list[list[int]]
    grid: np.ndarray
    first_element: int

    @property
    def element_ids(self) -> list[int]:
        """Ids of the elements, consecutive from ``first_element``."""
        return list(range(self.first_element, self.first_element + len(self.elements)))

    def where(self, axis: int, side: int) -> list[int]:
        """Ids of the grid nodes on the face ``axis`` = first (side 0) or last (side -1) value."""
        return sorted(int(n) for n in np.take(self.grid, side, axis=axis).ravel())


def quad_block(
    corner: tuple[float, float],
    size: tuple[float, float],
    divisions: tuple[int, int],
    first_node: int,
    first_element: int,
) -> Body:
    """A rectangle [x0, x0 + a] x [y0, y0 + b] of counter-clockwise quadrilaterals."""
    xs = [np.linspace(c, c + s, n + 1) for c, s, n in zip(corner, size, divisions, strict=True)]
    grid = first_node + np.arange((divisions[0] + 1) * (divisions[1] + 1)).reshape(
        divisions[0] + 1, divisions[1] + 1
    )
    nodes = {
        int(grid[i, j]): (float(xs[0][i]), float(xs[1][j]), 0.0)
        for i, j in itertools.product(range(divisions[0] + 1), range(divisions[1] + 1))
    }
    elements = [
        [int(grid[i, j]), int(grid[i + 1, j]), int(grid[i + 1, j + 1]), int(grid[i, j + 1])]
        for i, j in itertools.product(range(divisions[0]), range(divisions[1]))
    ]
    return Body(nodes, elements, grid, first_element)


def box(
    corner: tuple[float, float, float],
    size: tuple[float, float, float],
    divisions: tuple[int, int, int],
    first_node: int,
    first_element: int,
    tetrahedra: bool,
) -> Body:
    """A box of hexahedra, or of tetrahedra (six per grid cell, conforming) if ``tetrahedra``."""
    xs = [np.linspace(c, c + s, n + 1) for c, s, n in zip(corner, size, divisions, strict=True)]
    shape = tuple(n + 1 for n in divisions)
    grid = first_node + np.arange(np.prod(shape)).reshape(shape)
    nodes = {
        int(grid[i, j, k]): (float(xs[0][i]), float(xs[1][j]), float(xs[2][k]))
        for i, j, k in itertools.product(*(range(n) for n in shape))
    }
    elements = []
    for i, j, k in itertools.product(*(range(n) for n in divisions)):
        if not tetrahedra:
            elements.append([int(grid[i + a, j + b, k + c]) for a, b, c in HEX_CORNERS])
            continue
        for order in itertools.permutations(range(3)):
            # Kuhn simplex: walk from corner (0,0,0) to (1,1,1) one axis at a time.
            step = [0, 0, 0]
            path = [tuple(step)]
            for axis in order:
                step[axis] = 1
                path.append(tuple(step))
            tet = [int(grid[i + a, j + b, k + c]) for a, b, c in path]
            points = np.array([nodes[n] for n in tet])
            if np.linalg.det(points[1:] - points[0]) < 0.0:
                tet[2], tet[3] = tet[3], tet[2]
            elements.append(tet)
    return Body(nodes, elements, grid, first_element)


def faces_on(body: Body, axis: int, side: int) -> list[list[int]]:
    """Faces of the body's elements lying on its grid face ``axis``/``side``, outward oriented.

    Works for quads (edges), hexahedra (quads) and tetrahedra (triangles): a face is a set of
    element nodes all on that grid face; its orientation follows the outward normal.
    """
    on_face = set(body.where(axis, side))
    faces = []
    for element in body.elements:
        nodes = [n for n in element if n in on_face]
        if len(nodes) < (2 if body.grid.ndim == 2 else 3):
            continue
        if len(nodes) == 4:  # a hexahedron face: order the corners around the face centre
            points = np.array([body.nodes[n] for n in nodes])
            plane = [a for a in range(3) if a != axis]
            centre = points.mean(axis=0)
            angles = np.arctan2(*(points[:, plane[::-1]] - centre[plane[::-1]]).T)
            nodes = [nodes[m] for m in np.argsort(angles)]
        points = np.array([body.nodes[n] for n in nodes])
        outward = np.zeros(3)
        outward[axis] = 1.0 if side == -1 else -1.0
        if len(nodes) == 2:
            normal = np.array([points[1, 1] - points[0, 1], points[0, 0] - points[1, 0], 0.0])
        else:
            normal = np.cross(points[1] - points[0], points[2] - points[0])
        faces.append(nodes if normal @ outward > 0.0 else nodes[::-1])
    return faces


@dataclass
class Mdpa:
    """An .mdpa file being assembled: nodes, typed entity blocks and sub model parts."""

    nodes: dict[int, tuple[float, float, float]] = field(default_factory=dict)
    elements: list[tuple[str, int, list[list[int]], int]] = field(default_factory=list)
    conditions: list[tuple[str, int, list[list[int]], int]] = field(default_factory=list)
    parts: dict[str, dict[str, list[int]]] = field(default_factory=dict)
    _next_condition: int = 1

    def add_body(self, name: str, element: str, body: Body, properties: int) -> None:
        """Add a body's nodes and elements as the sub model part ``name``."""
        self.nodes.update(body.nodes)
        self.elements.append((element, body.first_element, body.elements, properties))
        self.add_part(name, nodes=list(body.nodes), elements=body.element_ids)

    def add_conditions(self, name: str, condition: str, faces: list[list[int]]) -> None:
        """Add one condition per face, in the sub model part ``name`` (with their nodes)."""
        first = self._next_condition
        self.conditions.append((condition, first, faces, 0))
        self._next_condition += len(faces)
        nodes = sorted({n for face in faces for n in face})
        self.add_part(name, nodes=nodes, conditions=list(range(first, first + len(faces))))

    def add_part(
        self, name: str, nodes: list[int], elements: list[int] = (), conditions: list[int] = ()
    ) -> None:
        """Add a sub model part (or extend it)."""
        part = self.parts.setdefault(name, {"Nodes": [], "Elements": [], "Conditions": []})
        part["Nodes"] = sorted(set(part["Nodes"]) | set(nodes))
        part["Elements"] += list(elements)
        part["Conditions"] += list(conditions)

    def write(self, path: Path) -> None:
        """Write the file (``path`` ends in .mdpa)."""
        lines = [
            "Begin ModelPartData",
            "End ModelPartData",
            "",
            "Begin Properties 0",
            "End Properties",
            "",
            "Begin Nodes",
        ]
        lines += [f"  {i} {x!r} {y!r} {z!r}" for i, (x, y, z) in sorted(self.nodes.items())]
        lines.append("End Nodes")
        for kind, blocks in (("Elements", self.elements), ("Conditions", self.conditions)):
            for name, first, connectivity, properties in blocks:
                lines.append(f"Begin {kind} {name}")
                lines += [
                    f"  {first + k} {properties} " + " ".join(map(str, entity))
                    for k, entity in enumerate(connectivity)
                ]
                lines.append(f"End {kind}")
        for name, part in self.parts.items():
            lines.append(f"Begin SubModelPart {name}")
            for kind, ids in part.items():
                lines.append(f"  Begin SubModelPart{kind}")
                lines += [f"    {i}" for i in ids]
                lines.append(f"  End SubModelPart{kind}")
            lines.append("End SubModelPart")
        path.write_text("\n".join(lines) + "\n")
