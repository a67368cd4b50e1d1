"""Scaling of the contact search (ContactSearchProcess through the Python binding).

Flat interfaces of N faces in all (N/2 slave, N/2 master, non-matching: the master mesh is shifted
by a fraction of a face), 2D (Line2D2) and 3D (Quadrilateral3D4), in_radius + check_mapping, no pair
conditions (condition_name ""). The time per search is split into the kd-tree build and the queries
(candidate search and checks of every slave face), plus the whole UpdateMortarConditions (normals,
gaps, active set). The growth exponent p of time ~ N^p is fitted by least squares on log-log
data; n log n shows as p slightly above 1. Sizes grow until one takes longer than the budget
(60 s, mesh + searches); it is reported and that dimension stops.

Usage: python benchmarks/search_benchmark.py [--max-faces 1000000] [--budget 60] [--repeats 3]
"""

from __future__ import annotations

import argparse
import math
import time

import contact_app as ca


def _build_case(dim: int, n_faces: int) -> tuple[ca.Model, ca.ModelPart]:
    """Main model part with a Contact part of about n_faces faces (half slave, half master)."""
    model = ca.Model()
    main = model.CreateModelPart("Structure")
    main.AddNodalSolutionStepVariable(ca.NORMAL)
    props = main.CreateNewProperties(1)
    contact = main.CreateSubModelPart("Contact")
    node_id = 1
    cond_id = 1
    nodes: list[int] = []
    faces: list[int] = []

    def add_node(x: float, y: float, z: float) -> int:
        nonlocal node_id
        main.CreateNewNode(node_id, x, y, z)
        nodes.append(node_id)
        node_id += 1
        return node_id - 1

    def add_face(ids: list[int], slave: bool) -> None:
        nonlocal cond_id
        name = "LineCondition2D2N" if dim == 2 else "SurfaceCondition3D4N"
        condition = main.CreateNewCondition(name, cond_id, ids, props)
        condition.Set(ca.SLAVE, slave)
        condition.Set(ca.MASTER, not slave)
        faces.append(cond_id)
        cond_id += 1

    gap = 0.01
    if dim == 2:
        n = max(n_faces // 2, 1)
        # Slave y = 0 right to left (normal +y); master y = gap, shifted by 0.37 (normal -y).
        slave = [add_node(float(n - i), 0.0, 0.0) for i in range(n + 1)]
        master = [add_node(i + 0.37 - 0.5, gap, 0.0) for i in range(n + 1)]
        for i in range(n):
            add_face([slave[i], slave[i + 1]], True)
            add_face([master[i], master[i + 1]], False)
    else:
        k = max(int(round(math.sqrt(n_faces / 2))), 1)

        def grid(z: float, dx: float, dy: float) -> list[list[int]]:
            return [[add_node(i + dx, j + dy, z) for j in range(k + 1)] for i in range(k + 1)]

        slave = grid(0.0, 0.0, 0.0)
        master = grid(gap, 0.37, 0.21)
        for i in range(k):
            for j in range(k):
                add_face([slave[i][j], slave[i + 1][j], slave[i + 1][j + 1], slave[i][j + 1]], True)
                quad = [master[i][j], master[i][j + 1], master[i + 1][j + 1], master[i + 1][j]]
                add_face(quad, False)
    contact.AddNodes(nodes)
    contact.AddConditions(faces)
    return model, main


def _run(dim: int, n_faces: int, repeats: int) -> dict[str, float]:
    start = time.perf_counter()
    model, main = _build_case(dim, n_faces)
    mesh_time = time.perf_counter() - start
    settings = ca.ContactSearchSettings(type_search="in_radius", check_gap="check_mapping")
    search = ca.ContactSearchProcess(main, settings)
    search.ExecuteInitialize()
    best: dict[str, float] = {}
    for _ in range(repeats):
        search.ExecuteInitializeSolutionStep()
        timings = search.GetLastSearchTimings()
        search.ExecuteFinalizeSolutionStep()
        if not best or timings["total"] < best["total"]:
            best = dict(timings)
    best["faces"] = best["slave_faces"] + best["master_faces"]
    best["mesh"] = mesh_time
    best["wall"] = time.perf_counter() - start
    del model
    return best


def _exponent(sizes: list[float], times: list[float]) -> float:
    """Least-squares slope of log(time) against log(size)."""
    xs = [math.log(s) for s in sizes]
    ys = [math.log(max(t, 1e-9)) for t in times]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    covariance = sum((x - mx) * (y - my) for x, y in zip(xs, ys, strict=True))
    return covariance / sum((x - mx) ** 2 for x in xs)


def main() -> None:
    """Run the sizes of each dimension, print the table and the fitted exponents."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--max-faces", type=int, default=1_000_000)
    parser.add_argument(
        "--budget", type=float, default=60.0, help="seconds per size (mesh + searches)"
    )
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    sizes = [10**3, 3 * 10**3, 10**4, 3 * 10**4, 10**5, 3 * 10**5, 10**6]
    sizes = [s for s in sizes if s <= args.max_faces]
    header = (
        f"{'dim':>3} {'faces':>9} {'cand/slave':>10} {'build [s]':>10} {'query [s]':>10} "
        f"{'search [s]':>10} {'us/face':>8} {'mesh [s]':>9} {'wall [s]':>9}"
    )
    print(header)
    print("-" * len(header))
    for dim in (2, 3):
        rows = []
        for size in sizes:
            row = _run(dim, size, args.repeats)
            rows.append(row)
            print(
                f"{dim:>3} {int(row['faces']):>9} {row['candidates'] / row['slave_faces']:>10.2f} "
                f"{row['tree_build']:>10.4f} {row['queries']:>10.4f} {row['total']:>10.4f} "
                f"{1e6 * row['total'] / row['faces']:>8.2f} {row['mesh']:>9.1f} "
                f"{row['wall']:>9.1f}",
                flush=True,
            )
            if row["wall"] > args.budget:
                faces = int(row["faces"])
                print(f"    stop: {faces} faces took {row['wall']:.0f} s > {args.budget:.0f} s")
                break
        if len(rows) >= 2:
            faces = [r["faces"] for r in rows]
            print(
                f"    {dim}D growth exponent (time ~ N^p): build p = "
                f"{_exponent(faces, [r['tree_build'] for r in rows]):.3f}, queries p = "
                f"{_exponent(faces, [r['queries'] for r in rows]):.3f}, search p = "
                f"{_exponent(faces, [r['total'] for r in rows]):.3f}; largest size run: "
                f"{int(rows[-1]['faces'])} faces"
            )


if __name__ == "__main__":
    main()
