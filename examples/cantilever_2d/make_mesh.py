"""Write cantilever.mdpa: a 10 x 1 plane-stress beam of nx x ny bilinear quads, clamped at x = 0."""

from __future__ import annotations

import argparse
from pathlib import Path


def write_mesh(path: Path, nx: int, ny: int, length: float = 10.0, height: float = 1.0) -> None:
    """Write the mesh with sub model parts Parts_beam, DISPLACEMENT_clamped and LineLoad2D_tip."""

    def node_id(i: int, j: int) -> int:
        return 1 + i + j * (nx + 1)

    lines = ["Begin ModelPartData", "End ModelPartData", ""]
    lines += ["Begin Properties 0", "End Properties", ""]
    lines.append("Begin Nodes")
    for j in range(ny + 1):
        for i in range(nx + 1):
            lines.append(f"  {node_id(i, j)} {length * i / nx:.10g} {height * j / ny:.10g} 0.0")
    lines += ["End Nodes", "", "Begin Elements SmallDisplacementElement2D4N // beam"]
    element = 1
    for j in range(ny):
        for i in range(nx):
            quad = (node_id(i, j), node_id(i + 1, j), node_id(i + 1, j + 1), node_id(i, j + 1))
            lines.append(f"  {element} 0 " + " ".join(map(str, quad)))
            element += 1
    lines += ["End Elements", "", "Begin Conditions LineLoadCondition2D2N // tip"]
    for j in range(ny):
        lines.append(f"  {j + 1} 0 {node_id(nx, j)} {node_id(nx, j + 1)}")
    lines += ["End Conditions", ""]

    def block(name: str, nodes: list[int], elements: list[int], conditions: list[int]) -> None:
        lines.append(f"Begin SubModelPart {name}")
        for kind, ids in (("Nodes", nodes), ("Elements", elements), ("Conditions", conditions)):
            lines.append(f"  Begin SubModelPart{kind}")
            lines.extend(f"    {i}" for i in ids)
            lines.append(f"  End SubModelPart{kind}")
        lines.append("End SubModelPart")

    all_nodes = [node_id(i, j) for j in range(ny + 1) for i in range(nx + 1)]
    block("Parts_beam", all_nodes, list(range(1, element)), [])
    block("DISPLACEMENT_clamped", [node_id(0, j) for j in range(ny + 1)], [], [])
    block("LineLoad2D_tip", [node_id(nx, j) for j in range(ny + 1)], [], list(range(1, ny + 1)))
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--nx", type=int, default=80)
    parser.add_argument("--ny", type=int, default=8)
    args = parser.parse_args()
    write_mesh(Path(__file__).with_name("cantilever.mdpa"), args.nx, args.ny)
