"""End-to-end performance baseline on the Hertz examples (issue 9; never part of the test suite).

For each refinement level the example runs in its own process (so the peak memory is that run's)
and the script prints, and writes to ``build/benchmarks/<example>_baseline.json``:
DoFs, Newton iterations per step, total wall time and its split into contact search, assembly
(structural + contact, from the builder), of which contact assembly (the pair conditions' local
systems, timed separately once per build and multiplied by the number of builds), linear solve,
output, and the peak resident memory; then the share of search + contact assembly in the total.

Usage: ``python benchmarks/hertz_baseline.py [--example E] [--steps N] [levels ...]`` with E =
hertz_2d (default) or hertz_3d, levels 1 2 3 by default, ``--steps N``: the full load in N equal
steps instead of the example's own time_step. For hertz_3d a fractional level is an intermediate
mesh (``make_mesh.subdivision_factor``): ``--example hertz_3d 3.8`` has 2.8e5 displacement DoFs.
"""

from __future__ import annotations

import json
import os
import resource
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = {"hertz_2d": 2, "hertz_3d": 3}  # example folder -> displacement DoFs per node
OUT = ROOT / "build" / "benchmarks"


def _measure(example: str, level: float, steps: int | None = None) -> dict:
    """Run one level of ``example`` in this process and return its figures."""
    folder = ROOT / "examples" / example
    sys.path.insert(0, str(folder))
    import make_mesh  # the example's mesh script

    import contact_app as ca
    from contact_app.contact.search_base_process import SearchBaseProcess

    search_seconds = [0.0]
    original = SearchBaseProcess.ExecuteInitializeSolutionStep

    def timed_search(self):  # the search phase of every step
        start = time.perf_counter()
        original(self)
        search_seconds[0] += time.perf_counter() - start

    SearchBaseProcess.ExecuteInitializeSolutionStep = timed_search
    workdir = OUT / f"{example}_level{level}"
    workdir.mkdir(parents=True, exist_ok=True)
    for name in ("ProjectParameters.json", "materials.json"):
        (workdir / name).write_text((folder / name).read_text())
    if steps is not None:  # fewer steps: fewer factorisations on the largest meshes
        parameters = json.loads((workdir / "ProjectParameters.json").read_text())
        span = parameters["problem_data"]["end_time"] - parameters["problem_data"]["start_time"]
        parameters["solver_settings"]["time_stepping"]["time_step"] = span / steps
        (workdir / "ProjectParameters.json").write_text(json.dumps(parameters, indent=1))
    make_mesh.write_mesh(workdir / f"{example}.msh", level)
    os.chdir(workdir)
    start = time.perf_counter()
    analysis = ca.analysis.run(workdir / "ProjectParameters.json", quiet=True)
    total = time.perf_counter() - start
    reporter = analysis.reporter
    builds = sum(step.iterations for step in reporter.steps) + len(reporter.steps)
    main = analysis.model.GetModelPart("Structure")
    pairs = list(main.GetSubModelPart("ComputingContact").Conditions)
    info = main.ProcessInfo
    start = time.perf_counter()
    for pair in pairs:
        pair.CalculateLocalSystem(info)
    contact_assembly = (time.perf_counter() - start) * builds
    dofs = EXAMPLES[example] * main.NumberOfNodes()  # displacement DoFs (multipliers on top)
    figures = {
        "example": example,
        "level": level,
        "nodes": main.NumberOfNodes(),
        "dofs_displacement": dofs,
        "pairs": len(pairs),
        "newton_per_step": [step.iterations for step in reporter.steps],
        "converged": all(step.converged for step in reporter.steps),
        "total_s": total,
        "search_s": search_seconds[0],
        "assembly_s": reporter.assembly,
        "contact_assembly_s": contact_assembly,
        "linear_solve_s": reporter.linear_solve,
        "output_s": reporter.phases["output"],
        "peak_rss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0,
    }
    figures["search_and_contact_share"] = (figures["search_s"] + contact_assembly) / total
    return figures


def main(argv: list[str]) -> int:
    """Run the levels in child processes (or, with ``--worker EXAMPLE LEVEL``, measure one)."""
    if argv and argv[0] == "--worker":
        level = float(argv[2]) if "." in argv[2] else int(argv[2])
        steps = int(argv[3]) if len(argv) > 3 else None
        print(json.dumps(_measure(argv[1], level, steps)))
        return 0
    example = "hertz_2d"
    if argv and argv[0] == "--example":
        if len(argv) < 2 or argv[1] not in EXAMPLES:
            print(f"--example expects one of {sorted(EXAMPLES)}", file=sys.stderr)
            return 2
        example, argv = argv[1], argv[2:]
    steps: list[str] = []
    if argv and argv[0] == "--steps":
        steps, argv = argv[1:2], argv[2:]
    levels = [float(a) if "." in a else int(a) for a in argv] or [1, 2, 3]
    OUT.mkdir(parents=True, exist_ok=True)
    rows = []
    for level in levels:
        done = subprocess.run(
            [sys.executable, __file__, "--worker", example, str(level), *steps],
            capture_output=True,
            text=True,
            check=False,
        )
        if done.returncode != 0:
            print(f"level {level} failed:\n{done.stderr[-2000:]}", file=sys.stderr)
            return 1
        rows.append(json.loads(done.stdout.strip().splitlines()[-1]))
    header = (
        f"{example}\n{'level':>5} {'DoFs':>7} {'pairs':>5} {'newton/step':>14} {'total s':>8} "
        f"{'search':>7} {'assembly':>8} {'(contact)':>9} {'solve':>7} {'output':>7} "
        f"{'peak MB':>8} {'search+contact':>14}"
    )
    print(header)
    for r in rows:
        print(
            f"{r['level']:>5} {r['dofs_displacement']:>7} {r['pairs']:>5} "
            f"{str(r['newton_per_step']):>14} "
            f"{r['total_s']:8.2f} {r['search_s']:7.2f} {r['assembly_s']:8.2f} "
            f"{r['contact_assembly_s']:9.3f} {r['linear_solve_s']:7.2f} {r['output_s']:7.2f} "
            f"{r['peak_rss_mb']:8.0f} {100 * r['search_and_contact_share']:13.1f}%"
        )
    path = OUT / f"{example}_baseline.json"
    path.write_text(json.dumps(rows, indent=1) + "\n")
    print(f"written: {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
