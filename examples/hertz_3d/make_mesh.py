"""Write hertz_3d.msh: a quarter sphere (x, y >= 0) on an elastic block, hexahedra, gmsh via meshio.

Geometry (mm): a ball of radius R = 10 centred at (0, 0, R); its lower octant (x, y >= 0, z <= R)
touches the block [0, L] x [0, L] x [-D, 0] at the origin (the pole). x = 0 and y = 0 are symmetry
planes. The sphere is the unit cube mapped onto the ball octant, p -> p |p|_inf / |p|_2 (scaled by
R, the cube corner (0, 0, 1) going to the pole), so the cube face w = 1 becomes the square-shaped
cap around the pole where R - z >= x, y, the faces u = 1 and v = 1 the rest of the spherical
surface and w = 0 the flat quarter disc z = R. The cube's parameters are uniform over
FINE_LENGTH from the pole and grow geometrically beyond it; the block is a tensor-product grid
graded the same way toward the origin, MASTER_SPACING_RATIO times coarser, so the interface is
non-matching. ``--refinement r`` splits every interval of level 1 into 2^(r-1): one nested family
with h_r = h_1 / 2^(r-1).

Physical groups (gmsh names; ProjectParameters' mesh_mapping renames them): ``sphere`` and
``foundation`` (hexahedra), ``load_top`` (quads of the flat face z = R, normals +z),
``contact_slave`` (sphere surface nodes with x^2 + y^2 <= CONTACT_ZONE^2), ``contact_master``
(block top nodes in the same zone, scaled by MASTER_SPACING_RATIO), ``symmetry_x`` (nodes on
x = 0), ``symmetry_y`` (nodes on y = 0) and ``fixed_base`` (nodes on z = -D). The node groups are
gmsh points (meshio ``vertex`` cells); the contact process builds the interface faces itself.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from pathlib import Path

import meshio
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from hertz_common import (  # noqa: E402  (examples/hertz_common.py)
    gmsh_mesh,
    graded,
    mesh_parser,
    subdivide,
    write_gmsh,
)

RADIUS = 10.0
FOUNDATION_WIDTH = RADIUS  # L
FOUNDATION_DEPTH = RADIUS  # D
FINE_LENGTH = 0.08 * RADIUS  # uniform zone at the pole; the Hertz radius is a = 0.059 R
FINE_INTERVALS = 2  # intervals over FINE_LENGTH at refinement 1
GROWTH = 3.0  # largest interval growth ratio beyond the fine zone at refinement 1
MASTER_SPACING_RATIO = 1.25  # the block is coarser than the sphere: non-matching interface
CONTACT_ZONE = 0.3 * RADIUS  # radius of the slave interface part (about 5 a)

#: Physical group name -> (tag, dimension).
GROUPS = {
    "sphere": (1, 3),
    "foundation": (2, 3),
    "load_top": (3, 2),
    "contact_slave": (4, 0),
    "contact_master": (5, 0),
    "symmetry_x": (6, 0),
    "symmetry_y": (7, 0),
    "fixed_base": (8, 0),
}

#: Hexahedron corners in reference coordinates (gmsh / Kratos order).
HEX_CORNERS = np.array(
    [[x, y, z] for z in (-1, 1) for x, y in ((-1, -1), (1, -1), (1, 1), (-1, 1))], dtype=float
)
#: The 12 edges of a hexahedron as corner pairs.
HEX_EDGES = (
    tuple((k, (k + 1) % 4) for k in range(4))
    + tuple((4 + k, 4 + (k + 1) % 4) for k in range(4))
    + tuple((k, k + 4) for k in range(4))
)


def ball_octant(u: np.ndarray, v: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Map cube parameters (u, v, w) in [0, 1]^3 onto the unit ball octant: p |p|_inf / |p|_2."""
    p = np.stack((u, v, w), axis=-1)
    norm = np.linalg.norm(p, axis=-1, keepdims=True)
    scale = np.divide(p.max(axis=-1, keepdims=True), norm, out=np.ones_like(norm), where=norm > 0)
    return p * scale


def _hexahedra(grid: np.ndarray, points: np.ndarray) -> np.ndarray:
    """Hexahedra of a structured node grid (i, j, k), ordered so the Jacobian is positive."""
    i, j, k = (np.arange(n - 1) for n in grid.shape)
    ii, jj, kk = (a.ravel() for a in np.meshgrid(i, j, k, indexing="ij"))
    hexes = np.column_stack(
        [
            grid[ii, jj, kk],
            grid[ii + 1, jj, kk],
            grid[ii + 1, jj + 1, kk],
            grid[ii, jj + 1, kk],
            grid[ii, jj, kk + 1],
            grid[ii + 1, jj, kk + 1],
            grid[ii + 1, jj + 1, kk + 1],
            grid[ii, jj + 1, kk + 1],
        ]
    )
    flip = jacobians(points, hexes)[:, 0] < 0.0
    hexes[flip] = hexes[flip][:, [4, 5, 6, 7, 0, 1, 2, 3]]
    return hexes


def jacobians(points: np.ndarray, hexes: np.ndarray) -> np.ndarray:
    """Jacobian determinants at the 2x2x2 Gauss points of each hexahedron, shape (elements, 8)."""
    g = 1.0 / np.sqrt(3.0)
    result = np.empty((len(hexes), 8))
    coordinates = points[hexes]  # (elements, 8, 3)
    for q, (xi, eta, zeta) in enumerate(g * HEX_CORNERS):
        c = HEX_CORNERS
        d_xi = 0.125 * c[:, 0] * (1 + c[:, 1] * eta) * (1 + c[:, 2] * zeta)
        d_eta = 0.125 * c[:, 1] * (1 + c[:, 0] * xi) * (1 + c[:, 2] * zeta)
        d_zeta = 0.125 * c[:, 2] * (1 + c[:, 0] * xi) * (1 + c[:, 1] * eta)
        jac = np.einsum("enc,dn->edc", coordinates, np.stack((d_xi, d_eta, d_zeta)))
        result[:, q] = np.linalg.det(jac)
    return result


def aspect_ratios(points: np.ndarray, hexes: np.ndarray) -> np.ndarray:
    """Longest over shortest edge of every hexahedron."""
    lengths = np.stack(
        [np.linalg.norm(points[hexes[:, a]] - points[hexes[:, b]], axis=1) for a, b in HEX_EDGES],
        axis=1,
    )
    return lengths.max(axis=1) / lengths.min(axis=1)


@dataclass
class Level:
    """The level-1 parameter distributions refined to one level."""

    sphere_lateral: np.ndarray  # u and v: 0 at the symmetry planes' axis, 1 at the cube's far faces
    sphere_depth: np.ndarray  # 0 at the pole, 1 at the centre (w = 1 - depth)
    block_lateral: np.ndarray  # x / L and y / L
    block_depth: np.ndarray  # -z / D


def subdivision_factor(refinement: float) -> int:
    """Intervals per level-1 interval: 2^(r-1) for the nested levels r = 1, 2, ...

    A fractional r gives an intermediate, non-nested mesh (r = 3.8: factor 7, 2.8e5 DoFs, the
    performance baseline's largest 3D case).
    """
    if refinement < 1:
        raise ValueError(f"refinement must be >= 1, got {refinement}")
    return round(2 ** (refinement - 1))


def distributions(refinement: float) -> Level:
    """Parameter distributions of a refinement level (1 = coarsest)."""
    factor = subdivision_factor(refinement)
    sphere = graded(RADIUS, FINE_LENGTH, FINE_INTERVALS, GROWTH)  # in units of R
    fine_master = MASTER_SPACING_RATIO * FINE_LENGTH
    lateral = graded(FOUNDATION_WIDTH, fine_master, FINE_INTERVALS, GROWTH)
    depth = graded(FOUNDATION_DEPTH, fine_master, FINE_INTERVALS, GROWTH)
    return Level(*(subdivide(p, factor) for p in (sphere, sphere, lateral, depth)))


def build(refinement: float) -> meshio.Mesh:
    """The mesh of refinement level ``refinement`` (1 = coarsest)."""
    level = distributions(refinement)
    tolerance = 1e-9 * RADIUS

    # Sphere: grid (i, j, k) over (u, v, depth); depth 0 is the pole (w = 1).
    u, v, depth = np.meshgrid(
        level.sphere_lateral, level.sphere_lateral, level.sphere_depth, indexing="ij"
    )
    unit = ball_octant(u, v, 1.0 - depth)
    sphere_points = np.stack(
        (RADIUS * unit[..., 0], RADIUS * unit[..., 1], RADIUS * (1.0 - unit[..., 2])), axis=-1
    )
    sphere_grid = np.arange(u.size).reshape(u.shape)
    sphere_points = sphere_points.reshape(-1, 3)
    sphere_hexes = _hexahedra(sphere_grid, sphere_points)

    # Block: grid (i, j, k) over (x, y, depth).
    x, y, d = np.meshgrid(
        FOUNDATION_WIDTH * level.block_lateral,
        FOUNDATION_WIDTH * level.block_lateral,
        -FOUNDATION_DEPTH * level.block_depth,
        indexing="ij",
    )
    block_points = np.column_stack((x.ravel(), y.ravel(), d.ravel()))
    offset = len(sphere_points)
    block_grid = offset + np.arange(x.size).reshape(x.shape)
    points = np.vstack((sphere_points, block_points))
    block_hexes = _hexahedra(block_grid, points)

    # Flat face z = R (w = 0: the last depth layer), quads with outward normal +z.
    top = sphere_grid[:, :, -1]
    top_quads = np.column_stack(
        (top[:-1, :-1].ravel(), top[1:, :-1].ravel(), top[1:, 1:].ravel(), top[:-1, 1:].ravel())
    )
    a, b, c = (points[top_quads[:, n]] for n in range(3))
    downward = np.cross(b - a, c - a)[:, 2] < 0.0
    top_quads[downward] = top_quads[downward][:, ::-1]

    # Spherical surface: the cube faces w = 1 (depth index 0), u = 1 and v = 1.
    surface = np.unique(
        np.concatenate(
            (sphere_grid[:, :, 0].ravel(), sphere_grid[-1].ravel(), sphere_grid[:, -1].ravel())
        )
    )
    radial = np.hypot(points[surface, 0], points[surface, 1])
    slave = surface[radial <= CONTACT_ZONE + tolerance]
    block_top = block_grid[:, :, 0].ravel()
    radial = np.hypot(points[block_top, 0], points[block_top, 1])
    master = block_top[radial <= MASTER_SPACING_RATIO * CONTACT_ZONE + tolerance]
    everything = np.arange(len(points))
    symmetry_x = everything[np.abs(points[:, 0]) <= tolerance]
    symmetry_y = everything[np.abs(points[:, 1]) <= tolerance]
    base = block_grid[:, :, -1].ravel()

    cells = [
        ("hexahedron", sphere_hexes),
        ("hexahedron", block_hexes),
        ("quad", top_quads),
    ]
    node_groups = {
        "contact_slave": slave,
        "contact_master": master,
        "symmetry_x": symmetry_x,
        "symmetry_y": symmetry_y,
        "fixed_base": base,
    }
    return gmsh_mesh(points, cells, ["sphere", "foundation", "load_top"], node_groups, GROUPS)


def contact_spacing(refinement: float) -> float:
    """Length of the sphere's surface intervals at the pole for a refinement level (mm)."""
    return FINE_LENGTH / FINE_INTERVALS / subdivision_factor(refinement)


def hexahedra(mesh: meshio.Mesh) -> np.ndarray:
    """All hexahedra of a mesh written by ``build``."""
    return np.vstack([block.data for block in mesh.cells if block.type == "hexahedron"])


def quality(mesh: meshio.Mesh) -> tuple[float, float]:
    """(smallest det J over all Gauss points relative to its element's mean, worst aspect ratio)."""
    hexes = hexahedra(mesh)
    det = jacobians(mesh.points, hexes)
    return float((det.min(axis=1) / det.mean(axis=1)).min()), float(
        aspect_ratios(mesh.points, hexes).max()
    )


def write_mesh(path: Path, refinement: float) -> meshio.Mesh:
    """Build the mesh of level ``refinement`` and write it to ``path`` (gmsh 2.2, binary)."""
    return write_gmsh(path, build(refinement), binary=True)


if __name__ == "__main__":
    parser = mesh_parser(
        __doc__,
        float,
        Path(__file__).with_name("hertz_3d.msh"),
        "1 = coarsest (default 2); a fractional level is an intermediate mesh",
    )
    parser.add_argument("--check", action="store_true", help="only print sizes and quality")
    args = parser.parse_args()
    written = build(args.refinement) if args.check else write_mesh(args.output, args.refinement)
    worst_jacobian, worst_aspect = quality(written)
    where = "" if args.check else f"{args.output}: "
    print(
        f"{where}{len(written.points)} nodes ({3 * len(written.points)} displacement DoFs), "
        f"{len(hexahedra(written))} hexahedra (refinement {args.refinement}), "
        f"min det J / mean {worst_jacobian:.3f}, worst aspect ratio {worst_aspect:.1f}"
    )
