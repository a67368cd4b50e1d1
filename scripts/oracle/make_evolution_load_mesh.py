"""Write the mesh of the frictional evolution-load oracle cases (our own model, plane strain).

The reference suite's ``ALM_frictional_contact_test_2D/static_evolution_load_test`` and
``evolution_load_test`` (of the 2019 Kratos contact test suite: 60
SmallDisplacementElement2D4N, 20 LineLoadCondition2D2N) come without their meshes. This script
writes a model of the same character: an elastic block [-1, 1] x [0, 0.5] (10 x 3 quads) on an
elastic base [-1.5, 1.5] x [-0.5, 0] (15 x 2 quads), touching with zero gap, the interface nodes
at the same places (h = 0.2 on both sides) but not shared. The block's top carries two sets of
LineLoadCondition2D2N on the same 10 edges, one for the normal and one for the tangential line
load, so the two components can evolve separately.

Sub model parts: ``Parts_Base``, ``Parts_Block`` (bodies), ``Contact_Part`` (block bottom and
base top nodes; the block is the slave), ``Load_Normal`` and ``Load_Tangent`` (the line loads),
``DISPLACEMENT_Base`` (base bottom, fixed) and ``DISPLACEMENT_Pull`` (top centre node of the
block, dragged in the static case). The file is small (96 nodes) and kept in the repository, so
the oracle and our tests read the same bytes; this script rewrites it identically.

Usage::

    python scripts/oracle/make_evolution_load_mesh.py [output.mdpa]
"""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests" / "python" / "contact"))
from patch_meshes import Mdpa, quad_block  # noqa: E402  (tests/python/contact/patch_meshes.py)

MESH = ROOT / "tests/python/contact/data/kratos_oracle/cases/frictional_evolution_load_2d.mdpa"
BASE_DIVISIONS = (15, 2)
BLOCK_DIVISIONS = (10, 3)


def build() -> Mdpa:
    """The base, the block, the two line-load sets and the node sets of the model."""
    base = quad_block((-1.5, -0.5), (3.0, 0.5), BASE_DIVISIONS, 1, 1)
    block = quad_block(
        (-1.0, 0.0), (2.0, 0.5), BLOCK_DIVISIONS, len(base.nodes) + 1, len(base.elements) + 1
    )
    mesh = Mdpa()
    mesh.add_body("Parts_Base", "SmallDisplacementElement2D4N", base, 0)
    mesh.add_body("Parts_Block", "SmallDisplacementElement2D4N", block, 0)
    top = block.where(1, -1)
    # Counter-clockwise around the block: along the top from right to left (outward normal +y).
    edges = [[b, a] for a, b in zip(top[:-1], top[1:], strict=True)]
    mesh.add_conditions("Load_Normal", "LineLoadCondition2D2N", edges)
    mesh.add_conditions("Load_Tangent", "LineLoadCondition2D2N", edges)
    mesh.add_part("Contact_Part", block.where(1, 0) + base.where(1, -1))
    mesh.add_part("DISPLACEMENT_Base", base.where(1, 0))
    mesh.add_part("DISPLACEMENT_Pull", [top[len(top) // 2]])
    return mesh


def main() -> int:
    """Write the mesh (to the path given, else to the oracle case folder)."""
    target = Path(sys.argv[1]) if len(sys.argv) > 1 else MESH
    build().write(target)
    print(f"wrote {target}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
