"""Assembly and solve cost of a 3D hexahedral block (SmallDisplacementElement3D8N, linear elastic).

Prints, per refinement: DoFs, setup (DoF set + sparsity graph), assembly time per element, linear
solve time and the peak resident memory of the process. A benchmark, not a test: it asserts nothing.

    python benchmarks/structural_block_benchmark.py     # n = 10, 20, 40 elements per side
    python benchmarks/structural_block_benchmark.py --sizes 10 20 --solver cg
"""

from __future__ import annotations

import argparse
import json
import resource
import sys
import time
from pathlib import Path

import contact_app as ca

# The tests' builder of the "Structure" model part (tests/python is no package).
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "python"))
from structure_model_part import create_structure  # noqa: E402


def build_block(n: int) -> tuple[ca.Model, ca.ModelPart]:
    """Create a unit cube of n^3 hexahedra, clamped at z = 0, with a prescribed top displacement."""
    model = ca.Model()
    mp, props = create_structure(model, 3, 210e9, "LinearElastic3DLaw", thickness=None)
    h = 1.0 / n
    stride = n + 1
    for k in range(n + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                mp.CreateNewNode(1 + i + stride * (j + stride * k), i * h, j * h, k * h)
    element_id = 1
    for k in range(n):
        for j in range(n):
            for i in range(n):
                a = 1 + i + stride * (j + stride * k)
                b, c, d = a + 1, a + 1 + stride, a + stride
                top = stride * stride
                nodes = [a, b, c, d, a + top, b + top, c + top, d + top]
                mp.CreateNewElement("SmallDisplacementElement3D8N", element_id, nodes, props)
                element_id += 1
    for node in mp.Nodes:
        for dof, reaction in (
            (ca.DISPLACEMENT_X, ca.REACTION_X),
            (ca.DISPLACEMENT_Y, ca.REACTION_Y),
            (ca.DISPLACEMENT_Z, ca.REACTION_Z),
        ):
            node.AddDof(dof, reaction)
        if node.Z0 == 0.0:
            for dof in (ca.DISPLACEMENT_X, ca.DISPLACEMENT_Y, ca.DISPLACEMENT_Z):
                node.Fix(dof)
        elif node.Z0 == 1.0:
            node.Fix(ca.DISPLACEMENT_Z)
            node.SetSolutionStepValue(ca.DISPLACEMENT_Z, 0, -1.0e-4)
    return model, mp


def run(n: int, solver: str) -> dict[str, float]:
    """Build, assemble and solve one block; return its figures."""
    start = time.perf_counter()
    model, mp = build_block(n)
    mesh_time = time.perf_counter() - start
    builder = ca.ResidualBasedBlockBuilderAndSolver(ca.CreateLinearSolver(solver, 1e-8, 5000))
    strategy = ca.ResidualBasedLinearStrategy(
        mp, ca.ResidualBasedIncrementalUpdateStaticScheme(), builder, compute_reactions=False
    )
    strategy.Initialize()
    strategy.Solve()
    timings = builder.GetTimings()
    elements = mp.NumberOfElements()
    del model
    return {
        "elements_per_side": n,
        "dofs": builder.GetEquationSystemSize(),
        "elements": elements,
        "mesh_s": mesh_time,
        "setup_s": timings["setup"],
        "assembly_s": timings["build"],
        "assembly_us_per_element": 1e6 * timings["build"] / elements,
        "solve_s": timings["solve"],
        "peak_rss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0,
    }


def main() -> None:
    """Run the refinements given on the command line and print a table (and optionally JSON)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[10, 20, 40])
    parser.add_argument(
        "--solver",
        default="cholmod",
        help="linear solver_type (cholmod for this SPD block, umfpack, cg, ...)",
    )
    parser.add_argument("--json", help="also write the figures to this JSON file")
    args = parser.parse_args()
    rows = []
    columns = ("n", "DoFs", "setup s", "asm s", "asm us/el", "solve s", "peak MB")
    widths = (4, 9, 8, 8, 10, 8, 8)
    header = " ".join(f"{name:>{width}}" for name, width in zip(columns, widths, strict=True))
    print(header)
    for n in args.sizes:
        row = run(n, args.solver)
        rows.append(row)
        print(
            f"{n:>4} {row['dofs']:>9} {row['setup_s']:>8.3f} {row['assembly_s']:>8.3f} "
            f"{row['assembly_us_per_element']:>10.2f} {row['solve_s']:>8.2f} "
            f"{row['peak_rss_mb']:>8.0f}"
        )
    if len(rows) > 1:
        first, last = rows[0], rows[-1]
        ratio = (last["assembly_s"] / first["assembly_s"]) / (last["elements"] / first["elements"])
        print(f"assembly time per element, largest vs smallest: {ratio:.2f} (1.0 = linear)")
    if args.json:
        with open(args.json, "w", encoding="utf-8") as stream:
            json.dump({"solver": args.solver, "rows": rows}, stream, indent=2)


if __name__ == "__main__":
    main()
