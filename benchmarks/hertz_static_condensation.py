"""Static condensation of the linear bulk on the 3D Hertz example (issue 18 item 2; not a test).

For each refinement level the example runs with ``linear_solver_settings.static_condensation``
true, false, and false with ``solver_type`` "umfpack" (the solver before MUMPS, f9143d7), each in
its own process, so the peak resident memory
(``resource.getrusage(...).ru_maxrss``) is that run's. Printed, and written to
``build/benchmarks/hertz_static_condensation.json``: equations, interface size, Newton iterations
per step, the inner solver (the example's own: UMFPACK below 20,000 equations, MUMPS above), total
wall time of the analysis, linear-solve wall time (builder timings), the bulk
condensation time and the time per condensed solve, the peak memory, the 1-minute load average
after the run, and the largest relative differences of the displacements and contact pressures
against the condensation-off run of the level.

Usage: ``python benchmarks/hertz_static_condensation.py [levels ...]`` (default: 2 3; a fractional
level is an intermediate mesh, e.g. 3.8: 2.8e5 unknowns). One mode of one level, as JSON:
``python benchmarks/hertz_static_condensation.py --child LEVEL MODE`` with MODE one of ``MODES`` or
``on-ooc`` (condensed, the bulk kept out of core by MUMPS whatever its size:
``StaticCondensationSolver.SetBulkInCoreLimit(0)``).
"""

from __future__ import annotations

import importlib.util
import json
import os
import resource
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "hertz_3d"
OUT = ROOT / "build" / "benchmarks"
#: mode -> (static_condensation, solver_type or None for the example's own)
MODES = {"on": (True, None), "off": (False, None), "umfpack": (False, "umfpack")}


def _measure(level: float, mode: str) -> dict:
    """Run the example at ``level`` with the mode in this process and return its figures."""
    spec = importlib.util.spec_from_file_location("hertz_3d_make_mesh", EXAMPLE / "make_mesh.py")
    assert spec is not None and spec.loader is not None
    make_mesh = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(make_mesh)

    import contact_app as ca

    workdir = OUT / f"hertz_3d_condensation_level{level}_{mode}"
    workdir.mkdir(parents=True, exist_ok=True)
    parameters = json.loads((EXAMPLE / "ProjectParameters.json").read_text())
    linear = parameters["solver_settings"]["linear_solver_settings"]
    linear["static_condensation"], solver_type = MODES["on" if mode == "on-ooc" else mode]
    if mode == "on-ooc":  # every condensing solver of the run keeps its bulk out of core
        create = ca.StaticCondensationSolver

        def out_of_core(*args: object, **kwargs: object) -> object:
            solver = create(*args, **kwargs)
            solver.SetBulkInCoreLimit(0.0)
            return solver

        ca.StaticCondensationSolver = out_of_core
    if solver_type is not None:
        linear["solver_type"] = solver_type
    parameters["output_processes"] = {}
    (workdir / "ProjectParameters.json").write_text(json.dumps(parameters, indent=1))
    (workdir / "materials.json").write_text((EXAMPLE / "materials.json").read_text())
    make_mesh.write_mesh(workdir / "hertz_3d.msh", level)
    os.chdir(workdir)
    start = time.perf_counter()
    analysis = ca.analysis.run(workdir / "ProjectParameters.json", quiet=True)
    total = time.perf_counter() - start
    main = analysis.model.GetModelPart("Structure")
    nodes = sorted(main.Nodes, key=lambda node: node.Id)
    np.savez(
        workdir / "state.npz",
        displacement=np.array([node.GetSolutionStepValue(ca.DISPLACEMENT) for node in nodes]),
        pressure=np.array([node.GetValue(ca.AUGMENTED_NORMAL_CONTACT_PRESSURE) for node in nodes]),
    )
    statistics = analysis.reporter.linear_solver or {}
    solves = int(statistics.get("condensed_solves", 0))
    return {
        "level": level,
        "mode": mode,
        "equations": int(statistics.get("system_size", 0))
        or int(statistics.get("interface_size", 0)) + int(statistics.get("bulk_size", 0)),
        "interface": int(statistics.get("interface_size", 0)),
        "condensation": statistics.get("condensation", ""),
        "solver": "condensed"
        if statistics.get("condensation") == "yes"
        else statistics.get("solver"),
        "iterations": [step.iterations for step in analysis.reporter.steps],
        "wall_s": total,
        "linear_solve_s": analysis.reporter.linear_solve,
        "bulk_s": float(statistics.get("bulk_seconds", 0.0)),
        "per_condensed_solve_s": float(statistics.get("interface_seconds", 0.0)) / max(solves, 1),
        "peak_MB": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0,
        "load": os.getloadavg()[0],
        "state": str(workdir / "state.npz"),
    }


def _difference(on: dict, off: dict) -> tuple[float, float]:
    a, b = np.load(on["state"]), np.load(off["state"])
    du = np.abs(a["displacement"] - b["displacement"]).max() / np.abs(b["displacement"]).max()
    dp = np.abs(a["pressure"] - b["pressure"]).max() / max(np.abs(b["pressure"]).max(), 1e-300)
    return float(du), float(dp)


def main(argv: list[str]) -> int:
    """Run every level in both modes (each in a child process) and print the table."""
    if len(argv) == 3 and argv[0] == "--child":
        print(json.dumps(_measure(float(argv[1]), argv[2])))
        return 0
    levels = [float(a) for a in argv] or [2.0, 3.0]
    OUT.mkdir(parents=True, exist_ok=True)
    rows = []
    for level in levels:
        runs = {}
        for mode in MODES:
            child = subprocess.run(
                [sys.executable, __file__, "--child", str(level), mode],
                capture_output=True,
                text=True,
                check=True,
            )
            runs[mode] = json.loads(child.stdout.strip().splitlines()[-1])
        for run in runs.values():
            run["max_rel_diff_u"], run["max_rel_diff_p"] = _difference(run, runs["off"])
            rows.append(run)
    header = (
        f"{'level':>5} {'mode':>7} {'solver':>9} {'equations':>9} {'n_I':>5} {'iterations':>14} "
        f"{'wall s':>7} {'solve s':>7} {'bulk s':>6} {'s/solve':>7} {'peak MB':>7} {'load':>5} "
        f"{'du':>8} {'dp':>8}"
    )
    print(header)
    for r in rows:
        print(
            f"{r['level']:>5g} {r['mode']:>7} {r['solver']:>9} {r['equations']:>9} "
            f"{r['interface']:>5} {str(r['iterations']):>14} {r['wall_s']:7.1f} "
            f"{r['linear_solve_s']:7.1f} {r['bulk_s']:6.1f} {r['per_condensed_solve_s']:7.3f} "
            f"{r['peak_MB']:7.0f} {r['load']:5.1f} {r['max_rel_diff_u']:8.1e} "
            f"{r['max_rel_diff_p']:8.1e}"
        )
    (OUT / "hertz_static_condensation.json").write_text(json.dumps(rows, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
