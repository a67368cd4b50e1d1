"""Write ironing_2d.mdpa: a die with a circular-arc face on an elastic slab, quads, plane strain.

Geometry (dimensionless, README.md says where it comes from): the slab is [0, L] x [0, H] with
L = 6 and H = 1, meshed uniformly. The die sits on the slab at x = X0 = 1.525: its lower face is
the arc of radius R = 1 centred at (X0, H + R) between the angles -THETA and +THETA from the
vertical (|x - X0| <= R sin THETA = 0.8), touching the slab at (X0, H); its sides are vertical
and its top is the line y = H + DIE_HEIGHT. The die is mapped from a rectangle: the vertical grid
lines go through the arc nodes, which are equally spaced in angle. X0 is a quarter of a slab
interval off a slab node, so that the first contact point is not a node of both surfaces (with
coincident nodes Kratos' first step diverged; ours did not mind).

``--refinement r`` multiplies every division of level 1 by 2^(r-1). Level 1: the slab 60 x 10
quads (h = 0.1), the die 24 x 8 (arc spacing 0.077): a non-matching interface on every level.

Sub model parts (the names ProjectParameters.json and materials.json use): ``Parts_slab``,
``Parts_die`` (elements and nodes), ``Contact_Slave`` (the slab's top nodes: the softer body is the
slave; with the die as slave Kratos diverged in the pressing phase), ``Contact_Master`` (the die's
arc nodes), ``DISPLACEMENT_slab_base`` (y = 0) and ``DISPLACEMENT_die_top`` (the
die's top, where the displacement is imposed and the reaction is read). The contact parts are node
sets: the contact process builds the interface conditions from the element faces.
"""

from __future__ import annotations

import argparse
import math
import sys
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

SLAB_LENGTH = 6.0
SLAB_HEIGHT = 1.0
RADIUS = 1.0
THETA = math.asin(0.8)  # half-angle of the die's arc: half-width R sin(THETA) = 0.8
DIE_HEIGHT = 1.0  # from the contact point to the die's top
DIE_START = 1.525  # x of the die's centre line before sliding
ELEMENT = "TotalLagrangianElement2D4N"

#: Divisions at refinement 1: slab (x, y), die (along the arc, height).
SLAB_DIVISIONS = (60, 10)
DIE_DIVISIONS = (24, 8)


@dataclass
class Grid:
    """A structured block of quads: node ids [i, j] (i along x or the arc), coordinates by id."""

    ids: np.ndarray
    coordinates: dict[int, tuple[float, float]]
    quads: list[tuple[int, int, int, int]] = field(default_factory=list)

    @classmethod
    def mapped(cls, x: np.ndarray, y: np.ndarray, first_node: int) -> Grid:
        """The block with node (i, j) at (x[i, j], y[i, j]); quads counter-clockwise."""
        ni, nj = x.shape
        ids = first_node + np.arange(ni * nj).reshape(ni, nj)
        coordinates = {
            int(ids[i, j]): (float(x[i, j]), float(y[i, j])) for i in range(ni) for j in range(nj)
        }
        quads = [
            (int(ids[i, j]), int(ids[i + 1, j]), int(ids[i + 1, j + 1]), int(ids[i, j + 1]))
            for i in range(ni - 1)
            for j in range(nj - 1)
        ]
        return cls(ids, coordinates, quads)


@dataclass
class IroningMesh:
    """The two blocks and the node sets of the model."""

    slab: Grid
    die: Grid

    @property
    def groups(self) -> dict[str, list[int]]:
        """Node ids of the boundary node sets, by sub model part name."""
        return {
            "Contact_Slave": sorted(int(n) for n in self.slab.ids[:, -1]),
            "Contact_Master": sorted(int(n) for n in self.die.ids[:, 0]),
            "DISPLACEMENT_slab_base": sorted(int(n) for n in self.slab.ids[:, 0]),
            "DISPLACEMENT_die_top": sorted(int(n) for n in self.die.ids[:, -1]),
        }

    @property
    def number_of_nodes(self) -> int:
        """Nodes of both blocks."""
        return len(self.slab.coordinates) + len(self.die.coordinates)

    @property
    def number_of_quads(self) -> int:
        """Quads of both blocks."""
        return len(self.slab.quads) + len(self.die.quads)


def build(refinement: int) -> IroningMesh:
    """The mesh of level ``refinement`` (1 = coarsest)."""
    if refinement < 1:
        raise ValueError(f"refinement must be >= 1, got {refinement}")
    factor = 2 ** (refinement - 1)
    nx, ny = (n * factor for n in SLAB_DIVISIONS)
    x, y = np.meshgrid(
        np.linspace(0.0, SLAB_LENGTH, nx + 1), np.linspace(0.0, SLAB_HEIGHT, ny + 1), indexing="ij"
    )
    slab = Grid.mapped(x, y, first_node=1)
    na, nh = (n * factor for n in DIE_DIVISIONS)
    angle = np.linspace(-THETA, THETA, na + 1)
    arc_x = DIE_START + RADIUS * np.sin(angle)
    arc_y = SLAB_HEIGHT + RADIUS * (1.0 - np.cos(angle))
    top = SLAB_HEIGHT + DIE_HEIGHT
    eta = np.linspace(0.0, 1.0, nh + 1)
    die_x = np.repeat(arc_x[:, None], nh + 1, axis=1)
    die_y = (1.0 - eta)[None, :] * arc_y[:, None] + eta[None, :] * top
    die = Grid.mapped(die_x, die_y, first_node=len(slab.coordinates) + 1)
    return IroningMesh(slab, die)


def contact_spacing(refinement: int) -> tuple[float, float]:
    """(slab top spacing, die arc chord at the contact point) of level ``refinement``."""
    factor = 2 ** (refinement - 1)
    slab = SLAB_LENGTH / (SLAB_DIVISIONS[0] * factor)
    die = 2.0 * RADIUS * math.sin(THETA / (DIE_DIVISIONS[0] * factor))
    return slab, die


def mdpa_text(mesh: IroningMesh) -> str:
    """The .mdpa file of ``mesh``: nodes, two element blocks (properties 1 and 2), the parts."""
    out = ["Begin ModelPartData", "End ModelPartData"]
    for properties in (0, 1, 2):  # Kratos wants every id the elements name declared
        out += ["", f"Begin Properties {properties}", "End Properties"]
    out += ["", "Begin Nodes"]
    for block in (mesh.slab, mesh.die):
        out += [f"  {i} {x!r} {y!r} 0.0" for i, (x, y) in block.coordinates.items()]
    out.append("End Nodes")
    parts: dict[str, tuple[list[int], list[int]]] = {}
    first = 1
    for name, block, properties in (("slab", mesh.slab, 1), ("die", mesh.die, 2)):
        out += ["", f"Begin Elements {ELEMENT} // {name}"]
        ids = list(range(first, first + len(block.quads)))
        out += [
            f"  {e} {properties} {' '.join(map(str, q))}"
            for e, q in zip(ids, block.quads, strict=True)
        ]
        out.append("End Elements")
        parts[f"Parts_{name}"] = (sorted(block.coordinates), ids)
        first += len(block.quads)
    parts.update({name: (nodes, []) for name, nodes in mesh.groups.items()})
    for name, (nodes, elements) in parts.items():
        out += ["", f"Begin SubModelPart {name}"]
        for kind, ids in (("Nodes", nodes), ("Elements", elements), ("Conditions", [])):
            out += [f"  Begin SubModelPart{kind}", *(f"    {i}" for i in ids)]
            out.append(f"  End SubModelPart{kind}")
        out.append("End SubModelPart")
    return "\n".join(out) + "\n"


def write_mesh(path: Path, refinement: int) -> IroningMesh:
    """Build the mesh of level ``refinement`` and write it to ``path`` (.mdpa)."""
    mesh = build(refinement)
    Path(path).write_text(mdpa_text(mesh), encoding="utf-8")
    return mesh


def main(argv: list[str] | None = None) -> int:
    """Write the mesh of the level given on the command line; print its size."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--refinement", type=int, default=1, help="1 = coarsest (default 1)")
    parser.add_argument("--output", type=Path, default=Path(__file__).with_name("ironing_2d.mdpa"))
    options = parser.parse_args(argv)
    mesh = write_mesh(options.output, options.refinement)
    size = f"{mesh.number_of_nodes} nodes, {mesh.number_of_quads} quads"
    print(f"{options.output}: {size} (refinement {options.refinement})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
