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

import sys
from pathlib import Path

import meshio

EXAMPLES = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(EXAMPLES))
import hertz_common as common  # noqa: E402  (examples/hertz_common.py)

hertz_mesh = common.mesh_script(EXAMPLES / "hertz_2d")
RADIUS = hertz_mesh.RADIUS
FINE_LENGTH = hertz_mesh.FINE_LENGTH

#: Physical group name -> (tag, dimension): hertz_2d's but its symmetry line.
GROUPS = {name: group for name, group in hertz_mesh.GROUPS.items() if name != "symmetry"}


def build(refinement: int) -> meshio.Mesh:
    """The hertz_2d mesh of level ``refinement``, mirrored about x = 0 (1 = coarsest)."""
    mirror = common.MirrorAboutX(hertz_mesh.build(refinement), hertz_mesh.GROUPS, RADIUS)
    cells = [
        ("quad", mirror.cells("cylinder")),
        ("quad", mirror.cells("foundation")),
        ("line", mirror.cells("load_top")),
    ]
    node_groups = {
        name: mirror.nodes(name) for name in ("contact_slave", "contact_master", "fixed_base")
    }
    return common.gmsh_mesh(
        mirror.points, cells, ["cylinder", "foundation", "load_top"], node_groups, GROUPS
    )


def contact_spacing(refinement: int) -> float:
    """Length of the cylinder's surface intervals at the contact point (as hertz_2d)."""
    return hertz_mesh.contact_spacing(refinement)


def write_mesh(path: Path, refinement: int) -> meshio.Mesh:
    """Build the mesh of level ``refinement`` and write it to ``path`` (gmsh 2.2, ASCII)."""
    return common.write_gmsh(path, build(refinement), binary=False)


if __name__ == "__main__":
    output = Path(__file__).with_name("cattaneo_mindlin_2d.msh")
    args = common.mesh_arguments(__doc__, int, output)
    written = write_mesh(args.output, args.refinement)
    quads = sum(len(block.data) for block in written.cells if block.type == "quad")
    print(
        f"{args.output}: {len(written.points)} nodes, {quads} quads (refinement {args.refinement})"
    )
