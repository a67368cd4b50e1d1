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

import argparse
import sys
from pathlib import Path

import meshio
import numpy as np

HERTZ_3D = Path(__file__).resolve().parent.parent / "hertz_3d"

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from hertz_common import load_script  # noqa: E402  (examples/hertz_common.py)

hertz_mesh = load_script("hertz_3d_make_mesh", HERTZ_3D / "make_mesh.py")
RADIUS = hertz_mesh.RADIUS
FINE_LENGTH = hertz_mesh.FINE_LENGTH

#: Physical group name -> (tag, dimension).
GROUPS = {
    "sphere": (1, 3),
    "foundation": (2, 3),
    "load_top": (3, 2),
    "contact_slave": (4, 0),
    "contact_master": (5, 0),
    "symmetry_y": (7, 0),
    "fixed_base": (8, 0),
    "sphere_centre_plane": (9, 0),
}


def _blocks_by_group(mesh: meshio.Mesh) -> dict[str, np.ndarray]:
    """The connectivity of each physical group of a hertz_3d mesh, by group name."""
    names = {tag: name for name, (tag, _) in hertz_mesh.GROUPS.items()}
    return {
        names[int(tags[0])]: block.data
        for block, tags in zip(mesh.cells, mesh.cell_data["gmsh:physical"], strict=True)
    }


def build(refinement: float) -> meshio.Mesh:
    """The hertz_3d mesh of level ``refinement``, mirrored about x = 0 (1 = coarsest)."""
    quarter = hertz_mesh.build(refinement)
    blocks = _blocks_by_group(quarter)
    points = np.asarray(quarter.points, dtype=float)
    on_plane = np.abs(points[:, 0]) < 1e-9 * RADIUS
    mirror = np.arange(len(points))
    mirror[~on_plane] = len(points) + np.arange(np.count_nonzero(~on_plane))
    all_points = np.vstack((points, points[~on_plane] * np.array([-1.0, 1.0, 1.0])))

    # Mirroring turns a positive hexahedron negative: swapping its two faces restores the sign;
    # a mirrored quad is reversed to keep its normal +z.
    def hexes(connectivity: np.ndarray) -> np.ndarray:
        return np.vstack((connectivity, mirror[connectivity][:, [4, 5, 6, 7, 0, 1, 2, 3]]))

    def quads(connectivity: np.ndarray) -> np.ndarray:
        return np.vstack((connectivity, mirror[connectivity][:, ::-1]))

    def nodes(name: str) -> np.ndarray:
        group = blocks[name].ravel()
        return np.unique(np.concatenate((group, mirror[group])))

    cells = [
        ("hexahedron", hexes(blocks["sphere"])),
        ("hexahedron", hexes(blocks["foundation"])),
        ("quad", quads(blocks["load_top"])),
    ]
    node_groups = {
        name: nodes(name)
        for name in ("contact_slave", "contact_master", "symmetry_y", "fixed_base")
    }
    sphere_nodes = np.unique(blocks["sphere"])
    node_groups["sphere_centre_plane"] = sphere_nodes[on_plane[sphere_nodes]]
    return hertz_mesh.gmsh_mesh(
        all_points, cells, ["sphere", "foundation", "load_top"], node_groups, GROUPS
    )


def contact_spacing(refinement: float) -> float:
    """Length of the sphere's surface intervals at the pole (as hertz_3d)."""
    return hertz_mesh.contact_spacing(refinement)


def write_mesh(path: Path, refinement: float) -> meshio.Mesh:
    """Build the mesh of level ``refinement`` and write it to ``path`` (gmsh 2.2, binary)."""
    mesh = build(refinement)
    meshio.write(str(path), mesh, file_format="gmsh22", binary=True)
    return mesh


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--refinement", type=float, default=2, help="1 = coarsest (default 2)")
    parser.add_argument(
        "--output", type=Path, default=Path(__file__).with_name("cattaneo_mindlin_3d.msh")
    )
    args = parser.parse_args()
    written = write_mesh(args.output, args.refinement)
    hexahedra = hertz_mesh.hexahedra(written)
    worst_jacobian, worst_aspect = hertz_mesh.quality(written)
    print(
        f"{args.output}: {len(written.points)} nodes, {len(hexahedra)} hexahedra "
        f"(refinement {args.refinement}), min det J / mean {worst_jacobian:.3f}, "
        f"worst aspect ratio {worst_aspect:.1f}"
    )
