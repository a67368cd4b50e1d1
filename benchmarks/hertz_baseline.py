"""End-to-end performance baseline on the Hertz examples (issue 9; never part of the test suite).

For each refinement level the example runs in its own process (so the peak memory is that run's)
and the script prints, and writes to ``build/benchmarks/<example>_baseline.json``:
DoFs, Newton iterations per step, total wall time and its split into contact search, assembly
(structural + contact, from the builder), of which contact assembly (the pair conditions' local
systems, timed separately once per build and multiplied by the number of builds), linear solve,
output, and the peak resident memory; then the share of search + contact assembly in the total.
A second table (issue 18) gives, per run, the linear solver and the fill-reducing ordering it used,
the share of the linear solve in the total, the CPU seconds of the symbolic analyses (the ordering)
and of the numeric factorisations with their flop count (independent of the machine's load), the
largest factors (nnz of L + U and the solver's peak factor memory), the peak resident memory and the
errors of the contact size (a, or b in 2D) and of p0 against Hertz theory. A third table lists, for
Krylov solvers (``--solver amgcl``), the solves, the Krylov iterations (total, largest, mean per
solve) and the method.

Usage: ``python benchmarks/hertz_baseline.py [--example E] [--steps N] [--ordering O[,O...]]
[--solver S[,S...]] [levels ...]`` with E = hertz_2d (default) or hertz_3d, levels 1 2 3 by
default, ``--steps N``: the full load in N equal steps instead of the example's own time_step,
``--ordering amd,metis``: run every level once per fill-reducing ordering
(linear_solver_settings.ordering; default: the example's own setting, "auto"), ``--solver
umfpack,mumps``: and once per linear solver_type (default: the example's own), ``--linear JSON``:
these keys merged into every run's linear_solver_settings (e.g.
``'{"reform_preconditioner_at_each_step": false}'``). For hertz_3d a
fractional level is an intermediate mesh (``make_mesh.subdivision_factor``): ``--example
hertz_3d 3.8`` has 2.8e5 displacement DoFs. ``--threads 1,2``: and once per OpenMP thread count of
the assembly (OMP_NUM_THREADS; OpenBLAS held at OPENBLAS_NUM_THREADS, 1 unless set, so that only
the assembly changes), with a table of the builder's figures: the assembly and its share of the
total, the scatter (adding local systems into A and b), the RHS-only assemblies (count and
seconds), the LHS + RHS builds, and the 1-minute load average before and after the run.
"""

from __future__ import annotations

import importlib
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


def _measure(
    example: str,
    level: float,
    steps: int | None = None,
    ordering: str | None = None,
    solver: str | None = None,
    linear: dict | None = None,
) -> dict:
    """Run one level of ``example`` in this process and return its figures."""
    folder = ROOT / "examples" / example
    sys.path[:0] = [str(folder), str(folder.parent)]
    import make_mesh  # the example's mesh script

    runner = importlib.import_module(f"run_{example}")  # its evaluation of a and p0

    import contact_app as ca
    from contact_app.contact.search_base_process import SearchBaseProcess

    search_seconds = [0.0]
    original = SearchBaseProcess.ExecuteInitializeSolutionStep
    builder_totals: dict[str, float] = {}
    add_timings = ca.analysis.Reporter.add_builder_timings

    def summed_timings(self, timings):  # every step's builder figures, summed over the run
        for key, value in timings.items():
            builder_totals[key] = builder_totals.get(key, 0.0) + float(value)
        add_timings(self, timings)

    ca.analysis.Reporter.add_builder_timings = summed_timings

    def timed_search(self):  # the search phase of every step
        start = time.perf_counter()
        original(self)
        search_seconds[0] += time.perf_counter() - start

    SearchBaseProcess.ExecuteInitializeSolutionStep = timed_search
    workdir = OUT / f"{example}_level{level}"
    workdir.mkdir(parents=True, exist_ok=True)
    for name in ("ProjectParameters.json", "materials.json"):
        (workdir / name).write_text((folder / name).read_text())
    parameters = json.loads((workdir / "ProjectParameters.json").read_text())
    if steps is not None:  # fewer steps: fewer factorisations on the largest meshes
        span = parameters["problem_data"]["end_time"] - parameters["problem_data"]["start_time"]
        parameters["solver_settings"]["time_stepping"]["time_step"] = span / steps
    if ordering is not None:
        parameters["solver_settings"]["linear_solver_settings"]["ordering"] = ordering
    if solver is not None:
        parameters["solver_settings"]["linear_solver_settings"]["solver_type"] = solver
    parameters["solver_settings"]["linear_solver_settings"].update(linear or {})
    (workdir / "ProjectParameters.json").write_text(json.dumps(parameters, indent=1))
    make_mesh.write_mesh(workdir / f"{example}.msh", level)
    os.chdir(workdir)
    load_before = os.getloadavg()[0]
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
    analysis.system_sizes = []  # what the example's evaluate reads of its recording analysis
    hertz = runner.evaluate(analysis, workdir / "materials.json")
    solver = analysis.reporter.linear_solver or {}
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
        "linear_solver": solver.get("solver", ""),
        "ordering": solver.get("ordering", ""),
        "factorizations": solver.get("factorizations", 0),
        "max_factor_nonzeros": solver.get("max_factor_nonzeros", 0.0),
        "max_factor_memory_mb": solver.get("max_factor_memory", 0.0) / 2.0**20,
        "symbolic_analyses": solver.get("symbolic_analyses", 0),
        "symbolic_cpu_s": solver.get("symbolic_seconds", 0.0),
        "numeric_cpu_s": solver.get("numeric_seconds", 0.0),
        "factor_gflop": solver.get("factor_flops", 0.0) / 1e9,
        # Krylov solvers (solver_type amgcl / gmres): iterations of every solve of the run
        "krylov_iterations": [int(n) for n in solver.get("krylov_iterations", [])],
        "krylov_method": solver.get("krylov_method", ""),
        "preconditioner_s": solver.get("preconditioner_seconds", 0.0),
        "krylov_s": solver.get("krylov_seconds", 0.0),
        "preconditioner_setups": solver.get("preconditioner_setups", 0),
        "cpu_s": sum(resource.getrusage(resource.RUSAGE_SELF)[:2]),
        "size_error": getattr(hertz, "a_error", getattr(hertz, "b_error", float("nan"))),
        "p0_error": hertz.p0_error,
    }
    figures["search_and_contact_share"] = (figures["search_s"] + contact_assembly) / total
    figures["threads"] = os.environ.get("OMP_NUM_THREADS", "")
    figures["lhs_rhs_builds"] = int(builder_totals.get("builds", 0))
    figures["rhs_only_builds"] = int(builder_totals.get("residual_builds", 0))
    figures["rhs_only_s"] = builder_totals.get("residual", 0.0)
    figures["scatter_s"] = builder_totals.get("scatter", 0.0)
    figures["load"] = [load_before, os.getloadavg()[0]]
    return figures


def main(argv: list[str]) -> int:
    """Run the levels in child processes (or, with ``--worker EXAMPLE LEVEL``, measure one)."""
    if argv and argv[0] == "--worker":
        job = json.loads(argv[1])
        figures = _measure(
            job["example"],
            job["level"],
            job["steps"],
            job["ordering"],
            job["solver"],
            job["linear"],
        )
        print(json.dumps(figures))
        return 0
    options: dict[str, str] = {}
    keys = ("--example", "--steps", "--ordering", "--solver", "--threads", "--linear")
    while argv and argv[0] in keys:
        if len(argv) < 2:
            print(f"{argv[0]} expects a value", file=sys.stderr)
            return 2
        options[argv[0][2:]], argv = argv[1], argv[2:]
    example = options.get("example", "hertz_2d")
    if example not in EXAMPLES:
        print(f"--example expects one of {sorted(EXAMPLES)}", file=sys.stderr)
        return 2
    steps = int(options["steps"]) if "steps" in options else None
    orderings = options["ordering"].split(",") if "ordering" in options else [None]
    solvers = options["solver"].split(",") if "solver" in options else [None]
    thread_counts = options["threads"].split(",") if "threads" in options else [None]
    linear = json.loads(options.get("linear", "{}"))
    if any(a in ("-h", "--help") for a in argv):
        print(__doc__)
        return 0
    try:
        levels = [float(a) if "." in a else int(a) for a in argv] or [1, 2, 3]
    except ValueError:
        message = f"levels must be numbers (got {' '.join(argv)}); options: {', '.join(keys)}"
        print(message, file=sys.stderr)
        return 2
    OUT.mkdir(parents=True, exist_ok=True)
    rows = []
    jobs = [
        {"example": example, "level": level, "steps": steps, "linear": linear}
        | {"ordering": o, "solver": s, "threads": t}
        for level in levels
        for s in solvers
        for o in orderings
        for t in thread_counts
    ]
    for job in jobs:
        environment = dict(os.environ)
        if job["threads"] is not None:
            environment["OMP_NUM_THREADS"] = job["threads"]
            environment.setdefault("OPENBLAS_NUM_THREADS", "1")
        done = subprocess.run(
            [sys.executable, __file__, "--worker", json.dumps(job)],
            capture_output=True,
            text=True,
            check=False,
            env=environment,
        )
        if done.returncode != 0:
            print(f"{job} failed:\n{done.stderr[-2000:]}", file=sys.stderr)
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
    size = "a" if example == "hertz_3d" else "b"
    print(
        f"\n{'level':>5} {'DoFs':>7} {'solver':>7} {'ordering':>8} {'total s':>8} "
        f"{'solve s':>8} {'share':>6} "
        f"{'analyses':>8} {'sym CPU':>7} {'num CPU':>7} {'Gflop':>7} {'factors nnz':>11} "
        f"{'factor MB':>9} {'peak MB':>8} {size + ' error':>9} {'p0 error':>9}"
    )
    for r in rows:
        print(
            f"{r['level']:>5} {r['dofs_displacement']:>7} {r['linear_solver'][-30:]:>7} "
            f"{r['ordering']:>8} {r['total_s']:8.2f} "
            f"{r['linear_solve_s']:8.2f} {100 * r['linear_solve_s'] / r['total_s']:5.1f}% "
            f"{r['symbolic_analyses']:>8} {r['symbolic_cpu_s']:7.2f} {r['numeric_cpu_s']:7.2f} "
            f"{r['factor_gflop']:7.1f} {r['max_factor_nonzeros']:11.4g} "
            f"{r['max_factor_memory_mb']:9.0f} {r['peak_rss_mb']:8.0f} "
            f"{100 * r['size_error']:8.4f}% {100 * r['p0_error']:8.4f}%"
        )
    krylov = [r for r in rows if r.get("krylov_iterations")]
    if krylov:
        print(
            f"\n{'level':>5} {'DoFs':>7} {'solves':>6} {'PC set-ups':>10} {'Krylov its':>10} "
            f"{'max':>5} {'mean':>6} {'set-up s':>8} {'its s':>7}  method"
        )
        for r in krylov:
            its = r["krylov_iterations"]
            print(
                f"{r['level']:>5} {r['dofs_displacement']:>7} {len(its):>6} "
                f"{r['preconditioner_setups'] or len(its):>10} {sum(its):>10} "
                f"{max(its):>5} {sum(its) / len(its):6.1f} {r['preconditioner_s']:8.2f} "
                f"{r['krylov_s']:7.2f}  {r['krylov_method']}"
            )
    if thread_counts != [None]:
        print(
            f"\n{'level':>5} {'DoFs':>7} {'threads':>7} {'total s':>8} {'assembly':>8} "
            f"{'share':>6} {'scatter':>7} {'RHS-only':>8} {'(s)':>6} {'LHS+RHS':>7} {'solve s':>8} "
            f"{'load':>10}"
        )
        for r in rows:
            print(
                f"{r['level']:>5} {r['dofs_displacement']:>7} {r['threads']:>7} "
                f"{r['total_s']:8.2f} {r['assembly_s']:8.2f} "
                f"{100 * r['assembly_s'] / r['total_s']:5.1f}% {r['scatter_s']:7.2f} "
                f"{r['rhs_only_builds']:>8} {r['rhs_only_s']:6.2f} {r['lhs_rhs_builds']:>7} "
                f"{r['linear_solve_s']:8.2f} {r['load'][0]:4.1f}/{r['load'][1]:<4.1f}"
            )
    path = OUT / f"{example}_baseline.json"
    path.write_text(json.dumps(rows, indent=1) + "\n")
    print(f"written: {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
