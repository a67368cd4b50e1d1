"""Write hertz_2d.msh: a half cylinder (x >= 0) on an elastic foundation, quads, gmsh via meshio.

Geometry (mm): cylinder of radius R = 10 centred at (0, R), its lower half meshed for x >= 0
(x = 0 is a symmetry line), touching the foundation [0, 2R] x [-2R, 0] at the origin. The
cylinder is three structured blocks (a bottom block along the arc 0-45 deg from the contact point,
a side block along 45-90 deg, a rectangular core); the foundation is one tensor-product block.
Both are uniform over a fine zone of FINE_LENGTH from the contact point (along the arc, the
surface and the depth) and grow geometrically beyond it. ``--refinement r`` splits every interval
of level 1 into 2^(r-1), so the levels form one nested family with h_r = h_1 / 2^(r-1).

Physical groups (gmsh names; ProjectParameters' mesh_mapping gives them their Kratos names):
``cylinder`` and ``foundation`` (quads), ``load_top`` (lines on the flat top of the cylinder),
``contact_slave`` (cylinder arc nodes), ``contact_master`` (foundation top nodes), ``symmetry``
(nodes on x = 0) and ``fixed_base`` (nodes on y = -2R). The node groups are gmsh points (meshio
``vertex`` cells), so the contact process builds the interface conditions itself.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import meshio
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from hertz_common import (  # noqa: E402  (examples/hertz_common.py)
    gmsh_mesh,
    graded,
    mesh_arguments,
    subdivide,
    write_gmsh,
)

RADIUS = 10.0
FOUNDATION_WIDTH = 2.0 * RADIUS
FOUNDATION_DEPTH = 2.0 * RADIUS
CORE_HALF_SIZE = 0.5 * RADIUS  # the core block is [0, s] x [R - s, R]
FINE_LENGTH = 0.02 * RADIUS  # uniform zone at the contact; the Hertz half-width is 0.0117 R
FINE_INTERVALS = 8  # intervals over FINE_LENGTH at refinement 1
GROWTH = 1.3  # interval growth ratio beyond the fine zone at refinement 1
MASTER_SPACING_RATIO = 1.25  # the foundation is coarser than the cylinder: non-matching interface

#: Physical group name -> (tag, dimension).
GROUPS = {
    "cylinder": (1, 2),
    "foundation": (2, 2),
    "load_top": (3, 1),
    "contact_slave": (4, 0),
    "contact_master": (5, 0),
    "symmetry": (6, 0),
    "fixed_base": (7, 0),
}


def uniform(intervals: int) -> np.ndarray:
    """``intervals`` equal intervals of [0, 1]."""
    return np.linspace(0.0, 1.0, intervals + 1)


class NodeTable:
    """Coordinates with merging of coincident points (block edges are shared)."""

    def __init__(self, tolerance: float) -> None:
        self.tolerance = tolerance
        self.points: list[tuple[float, float, float]] = []
        self.index: dict[tuple[int, int], int] = {}

    def add(self, x: float, y: float) -> int:
        """Index of the node at (x, y), created if new."""
        key = (round(x / self.tolerance), round(y / self.tolerance))
        if key not in self.index:
            self.index[key] = len(self.points)
            self.points.append((x, y, 0.0))
        return self.index[key]


def ruled_block(
    nodes: NodeTable, bottom: np.ndarray, top: np.ndarray, across: np.ndarray
) -> tuple[list[list[int]], np.ndarray]:
    """Quads between the point rows ``bottom`` and ``top`` (same length) at parameters ``across``.

    Returns the counter-clockwise quads and the node grid (row j = across[j]).
    """
    grid = np.empty((len(across), len(bottom)), dtype=int)
    for j, t in enumerate(across):
        for i in range(len(bottom)):
            x, y = (1.0 - t) * bottom[i] + t * top[i]
            grid[j, i] = nodes.add(float(x), float(y))
    return _quads(nodes, grid), grid


def _quads(nodes: NodeTable, grid: np.ndarray) -> list[list[int]]:
    quads = []
    for j in range(grid.shape[0] - 1):
        for i in range(grid.shape[1] - 1):
            quad = [grid[j, i], grid[j, i + 1], grid[j + 1, i + 1], grid[j + 1, i]]
            p = [np.asarray(nodes.points[n][:2]) for n in quad]
            area = sum(p[k][0] * p[(k + 1) % 4][1] - p[(k + 1) % 4][0] * p[k][1] for k in range(4))
            quads.append(quad if area > 0.0 else quad[::-1])
    return quads


def arc(angles: np.ndarray) -> np.ndarray:
    """Points of the cylinder surface at angles measured from the contact point (radians)."""
    return np.column_stack((RADIUS * np.sin(angles), RADIUS - RADIUS * np.cos(angles)))


def build(refinement: int) -> meshio.Mesh:
    """The mesh of refinement level ``refinement`` (1 = coarsest)."""
    if refinement < 1:
        raise ValueError(f"refinement must be >= 1, got {refinement}")
    factor = 2 ** (refinement - 1)
    s = CORE_HALF_SIZE
    quarter = 0.25 * math.pi * RADIUS

    # Level-1 parameter distributions, then the nested subdivision.
    along_arc = graded(quarter, FINE_LENGTH, FINE_INTERVALS, GROWTH)
    last = (along_arc[-1] - along_arc[-2]) * quarter
    side_arc = uniform(max(2, round(quarter / last)))
    radial = graded(RADIUS - s, FINE_LENGTH, FINE_INTERVALS, GROWTH)
    core_y = uniform(len(side_arc) - 1)
    master_fine = max(2, round(FINE_INTERVALS / MASTER_SPACING_RATIO))
    surface = graded(FOUNDATION_WIDTH, FINE_LENGTH, master_fine, GROWTH)
    depth = graded(FOUNDATION_DEPTH, FINE_LENGTH, master_fine, GROWTH)
    along_arc, side_arc, radial, core_y, surface, depth = (
        subdivide(p, factor) for p in (along_arc, side_arc, radial, core_y, surface, depth)
    )
    # The bottom block's top edge is the core's bottom edge: as many intervals as the arc, uniform
    # (the ruled lines fan out from the graded arc, so the core does not inherit the grading).
    core_x = uniform(len(along_arc) - 1)

    cylinder = NodeTable(1e-9 * RADIUS)
    bottom_quads, bottom_grid = ruled_block(
        cylinder,
        arc(0.25 * math.pi * along_arc),
        np.column_stack((s * core_x, np.full(len(core_x), RADIUS - s))),
        radial,
    )
    side_quads, side_grid = ruled_block(
        cylinder,
        arc(0.25 * math.pi * (1.0 + side_arc)),
        np.column_stack((np.full(len(core_y), s), RADIUS - s + s * core_y)),
        radial,
    )
    core_grid = np.array(
        [[cylinder.add(s * x, RADIUS - s + s * y) for x in core_x] for y in core_y], dtype=int
    )
    cylinder_quads = bottom_quads + side_quads + _quads(cylinder, core_grid)

    foundation = NodeTable(1e-9 * RADIUS)
    foundation_grid = np.array(
        [
            [foundation.add(FOUNDATION_WIDTH * x, -FOUNDATION_DEPTH * y) for x in surface]
            for y in depth
        ],
        dtype=int,
    )
    foundation_quads = _quads(foundation, foundation_grid)
    offset = len(cylinder.points)

    # The flat top y = R: the side block's far column (D -> G), then the core's top row (G -> C).
    top_row = list(side_grid[:, -1]) + list(core_grid[-1, ::-1][1:])
    top_lines = [[a, b] for a, b in zip(top_row[:-1], top_row[1:], strict=True)]
    slave = list(bottom_grid[0, :]) + list(side_grid[0, 1:])
    master = [n + offset for n in foundation_grid[0, :]]
    symmetry = list(bottom_grid[:, 0]) + list(core_grid[1:, 0])
    symmetry += [n + offset for n in foundation_grid[:, 0]]
    base = [n + offset for n in foundation_grid[-1, :]]

    points = np.array(cylinder.points + foundation.points)
    cells = [
        ("quad", np.array(cylinder_quads)),
        ("quad", np.array(foundation_quads) + offset),
        ("line", np.array(top_lines)),
    ]
    node_groups = {
        "contact_slave": slave,
        "contact_master": master,
        "symmetry": symmetry,
        "fixed_base": base,
    }
    return gmsh_mesh(points, cells, ["cylinder", "foundation", "load_top"], node_groups, GROUPS)


def contact_spacing(refinement: int) -> float:
    """Length of the cylinder's surface intervals at the contact point for a refinement level."""
    return FINE_LENGTH / FINE_INTERVALS / 2 ** (refinement - 1)


def write_mesh(path: Path, refinement: int) -> meshio.Mesh:
    """Build the mesh of level ``refinement`` and write it to ``path`` (gmsh 2.2, ASCII)."""
    return write_gmsh(path, build(refinement), binary=False)


if __name__ == "__main__":
    args = mesh_arguments(__doc__, int, Path(__file__).with_name("hertz_2d.msh"))
    written = write_mesh(args.output, args.refinement)
    quads = sum(len(block.data) for block in written.cells if block.type == "quad")
    print(
        f"{args.output}: {len(written.points)} nodes, {quads} quads (refinement {args.refinement})"
    )
