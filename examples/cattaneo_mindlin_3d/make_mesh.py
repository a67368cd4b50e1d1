"""Write cattaneo_mindlin_3d.msh: half of a sphere on an elastic block (y >= 0), hexahedra, meshio.

A tangential load along x keeps y = 0 a symmetry plane (u_y = 0 there) but makes the problem
antisymmetric about x = 0, so the quarter model of hertz_3d cannot carry it. This script builds the
hertz_3d mesh of the same refinement level (``examples/hertz_3d/make_mesh.py``, loaded as it is)
and mirrors it about x = 0, merging the nodes on the plane x = 0. The sphere (R = 10 mm, centre
(0, 0, R)) touches the block [-L, L] x [0, L] x [-D, 0] at the origin; the interface is
non-matching (the block 1.25x coarser at the pole). Level r halves every interval of level r - 1.

Physical groups: ``sphere``, ``foundation`` (hexahedra), ``load_top`` (quads of the flat face
z = R, normals +z), ``contact_slave``, ``contact_master``, ``symmetry_y``, ``fixed_base`` and
``sphere_centre_plane`` (the sphere's nodes on x = 0, held in x during the normal load only; all
points). hertz_3d's ``symmetry_x`` group is dropped: the loading is not symmetric about x = 0.
"""

from __future__ import annotations

import sys
from pathlib import Path

import meshio
import numpy as np

EXAMPLES = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(EXAMPLES))
import hertz_common as common  # noqa: E402  (examples/hertz_common.py)

hertz_mesh = common.mesh_script(EXAMPLES / "hertz_3d")
RADIUS = hertz_mesh.RADIUS
FINE_LENGTH = hertz_mesh.FINE_LENGTH

#: Physical group name -> (tag, dimension): hertz_3d's but its x = 0 plane, and the sphere's
#: nodes on that plane.
GROUPS = {name: group for name, group in hertz_mesh.GROUPS.items() if name != "symmetry_x"}
GROUPS["sphere_centre_plane"] = (9, 0)
#: Mirroring turns a positive hexahedron negative: swapping its two faces restores the sign (a
#: mirrored quad is reversed, MirrorAboutX's default, to keep its normal +z).
SWAPPED_FACES = [4, 5, 6, 7, 0, 1, 2, 3]


def build(refinement: float) -> meshio.Mesh:
    """The hertz_3d mesh of level ``refinement``, mirrored about x = 0 (1 = coarsest)."""
    mirror = common.MirrorAboutX(hertz_mesh.build(refinement), hertz_mesh.GROUPS, RADIUS)
    cells = [
        ("hexahedron", mirror.cells("sphere", SWAPPED_FACES)),
        ("hexahedron", mirror.cells("foundation", SWAPPED_FACES)),
        ("quad", mirror.cells("load_top")),
    ]
    node_groups = {
        name: mirror.nodes(name)
        for name in ("contact_slave", "contact_master", "symmetry_y", "fixed_base")
    }
    sphere_nodes = np.unique(mirror.blocks["sphere"])
    node_groups["sphere_centre_plane"] = sphere_nodes[mirror.on_plane[sphere_nodes]]
    return common.gmsh_mesh(
        mirror.points, cells, ["sphere", "foundation", "load_top"], node_groups, GROUPS
    )


def contact_spacing(refinement: float) -> float:
    """Length of the sphere's surface intervals at the pole (as hertz_3d)."""
    return hertz_mesh.contact_spacing(refinement)


def write_mesh(path: Path, refinement: float) -> meshio.Mesh:
    """Build the mesh of level ``refinement`` and write it to ``path`` (gmsh 2.2, binary)."""
    return common.write_gmsh(path, build(refinement), binary=True)


if __name__ == "__main__":
    output = Path(__file__).with_name("cattaneo_mindlin_3d.msh")
    args = common.mesh_arguments(__doc__, float, output)
    written = write_mesh(args.output, args.refinement)
    hexahedra = hertz_mesh.hexahedra(written)
    worst_jacobian, worst_aspect = hertz_mesh.quality(written)
    print(
        f"{args.output}: {len(written.points)} nodes, {len(hexahedra)} hexahedra "
        f"(refinement {args.refinement}), min det J / mean {worst_jacobian:.3f}, "
        f"worst aspect ratio {worst_aspect:.1f}"
    )
