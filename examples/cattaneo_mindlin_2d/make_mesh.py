"""Write cattaneo_mindlin_2d.msh: the whole cylinder on the whole foundation, quads, via meshio.

The tangential (Cattaneo-Mindlin) problem is antisymmetric about x = 0, so the half model of
hertz_2d cannot carry it: this script builds the hertz_2d mesh of the same refinement level
(``examples/hertz_2d/make_mesh.py``, loaded as it is) and mirrors it about x = 0, merging the
nodes on the line x = 0. The cylinder is the lower half disc of radius R = 10 mm centred at
(0, R) with its flat top at y = R; the foundation is [-2R, 2R] x [-2R, 0]. Both are uniform over
FINE_LENGTH = 0.2 mm on each side of the contact point; the foundation is 1.25x coarser there
(non-matching interface). Level r halves every interval of level r - 1.

Physical groups: ``cylinder`` and ``foundation`` (quads), ``load_top`` (lines of the flat top),
``contact_slave`` (cylinder arc nodes), ``contact_master`` (foundation top nodes), ``fixed_base``
(nodes on y = -2R). hertz_2d's ``symmetry`` group is dropped: the loading is not symmetric.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import meshio
import numpy as np

HERTZ_2D = Path(__file__).resolve().parent.parent / "hertz_2d"

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from hertz_common import load_script  # noqa: E402  (examples/hertz_common.py)

hertz_mesh = load_script("hertz_2d_make_mesh", HERTZ_2D / "make_mesh.py")
RADIUS = hertz_mesh.RADIUS
FINE_LENGTH = hertz_mesh.FINE_LENGTH

#: Physical group name -> (tag, dimension).
GROUPS = {
    "cylinder": (1, 2),
    "foundation": (2, 2),
    "load_top": (3, 1),
    "contact_slave": (4, 0),
    "contact_master": (5, 0),
    "fixed_base": (7, 0),
}


def _blocks_by_group(mesh: meshio.Mesh) -> dict[str, np.ndarray]:
    """The connectivity of each physical group of a hertz_2d mesh, by group name."""
    names = {tag: name for name, (tag, _) in hertz_mesh.GROUPS.items()}
    return {
        names[int(tags[0])]: block.data
        for block, tags in zip(mesh.cells, mesh.cell_data["gmsh:physical"], strict=True)
    }


def build(refinement: int) -> meshio.Mesh:
    """The hertz_2d mesh of level ``refinement``, mirrored about x = 0 (1 = coarsest)."""
    half = hertz_mesh.build(refinement)
    blocks = _blocks_by_group(half)
    points = np.asarray(half.points, dtype=float)
    on_axis = np.abs(points[:, 0]) < 1e-9 * RADIUS
    mirror = np.arange(len(points))
    mirror[~on_axis] = len(points) + np.arange(np.count_nonzero(~on_axis))
    mirrored_points = points[~on_axis] * np.array([-1.0, 1.0, 1.0])
    all_points = np.vstack((points, mirrored_points))

    def both(connectivity: np.ndarray) -> np.ndarray:
        # Mirroring turns counter-clockwise cells clockwise: reverse their node order.
        return np.vstack((connectivity, mirror[connectivity][:, ::-1]))

    def nodes(name: str) -> np.ndarray:
        group = blocks[name].ravel()
        return np.unique(np.concatenate((group, mirror[group])))

    cells = [("quad", both(blocks["cylinder"])), ("quad", both(blocks["foundation"]))]
    cells.append(("line", both(blocks["load_top"])))
    tags = ["cylinder", "foundation", "load_top"]
    for name in ("contact_slave", "contact_master", "fixed_base"):
        cells.append(("vertex", nodes(name).reshape(-1, 1)))
        tags.append(name)
    physical = [
        np.full(len(data), GROUPS[name][0], dtype=int)
        for (_, data), name in zip(cells, tags, strict=True)
    ]
    return meshio.Mesh(
        all_points,
        cells,
        cell_data={"gmsh:physical": physical, "gmsh:geometrical": [p.copy() for p in physical]},
        field_data={name: np.array(value) for name, value in GROUPS.items()},
    )


def contact_spacing(refinement: int) -> float:
    """Length of the cylinder's surface intervals at the contact point (as hertz_2d)."""
    return hertz_mesh.contact_spacing(refinement)


def write_mesh(path: Path, refinement: int) -> meshio.Mesh:
    """Build the mesh of level ``refinement`` and write it to ``path`` (gmsh 2.2, ASCII)."""
    mesh = build(refinement)
    meshio.write(str(path), mesh, file_format="gmsh22", binary=False)
    return mesh


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--refinement", type=int, default=2, help="1 = coarsest (default 2)")
    parser.add_argument(
        "--output", type=Path, default=Path(__file__).with_name("cattaneo_mindlin_2d.msh")
    )
    args = parser.parse_args()
    written = write_mesh(args.output, args.refinement)
    quads = sum(len(block.data) for block in written.cells if block.type == "quad")
    print(
        f"{args.output}: {len(written.points)} nodes, {quads} quads (refinement {args.refinement})"
    )
