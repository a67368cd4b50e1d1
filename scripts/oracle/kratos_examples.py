r"""Kratos oracle: the example collection's models (../shared/kratos_examples) as JSON fixtures.

Runs the reference (PyPI KratosMultiphysics 10.4.x, in its own virtual environment, never a
dependency of contact_app) on each model with the model's own settings, one thread
(``OMP_NUM_THREADS=1``), no output processes, and at most ``--cap`` seconds of wall time in the
solution loop (120 s, the issue's "about two minutes"; the loop stops before the next step once the
cap is passed). Only ``mesh_id`` is removed from the parameters (10.4 refuses it; the same helper
as generate_kratos_fixtures.py). Each model runs in its own process, so that a crash of the
reference is a result and not the end of the script.

Writes ``tests/python/examples/data/kratos_examples/<model>.json``: Kratos version, SHA-256 of the
mdpa, end time asked and reached, whether the cap stopped it, the reference's own failure (message,
TIME), the import/initialize wall time, per step TIME, Newton iterations, wall time, converged,
active slave nodes and largest |pressure|, and full snapshots (named nodes' displacement, reaction
sums per support, active nodes, max/median |pressure|, contact force) at a few steps: the first,
the fifth, and the quarters of the steps reached. What is recorded and how is
tests/python/examples/kratos_examples_common.py, shared with the tests and the benchmark.

Usage::

    /tmp/kratos_venv/bin/python scripts/oracle/kratos_examples.py [--model NAME ...] [--cap 120]
"""

from __future__ import annotations

import argparse
import importlib.metadata
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

os.environ["OMP_NUM_THREADS"] = "1"  # before the reference is loaded

import KratosMultiphysics as KM  # the oracle, only in its own environment  # noqa: E402
import KratosMultiphysics.ConstitutiveLawsApplication  # noqa: E402, F401  (hyperelastic laws)
import KratosMultiphysics.ContactStructuralMechanicsApplication as CSMA  # noqa: E402
import KratosMultiphysics.LinearSolversApplication  # noqa: E402, F401
import KratosMultiphysics.StructuralMechanicsApplication  # noqa: E402, F401
from KratosMultiphysics.StructuralMechanicsApplication.structural_mechanics_analysis import (  # noqa: E402
    StructuralMechanicsAnalysis,
)

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests" / "python" / "examples"))
sys.path.insert(0, str(Path(__file__).resolve().parent))
import kratos_examples_common as common  # noqa: E402  (tests/python/examples/)
from generate_kratos_fixtures import strip_mesh_id  # noqa: E402  (drops mesh_id)

OUT = ROOT / "tests" / "python" / "examples" / "data" / "kratos_examples"


class _Variables:
    """The core's names, then the contact application's (AUGMENTED_NORMAL_CONTACT_PRESSURE)."""

    def __getattr__(self, name: str):
        return getattr(KM, name) if hasattr(KM, name) else getattr(CSMA, name)


def _kept_steps(count: int) -> set[int]:
    """Indices of the steps whose snapshot is kept: first, fifth, quarters, last."""
    if count == 0:
        return set()
    kept = {0, min(4, count - 1), count - 1}
    kept.update(round(k * (count - 1) / 4) for k in range(1, 4))
    return kept


def run(name: str, cap: float) -> dict:
    """Run one model in a scratch folder; return its fixture."""
    KM.ParallelUtilities.SetNumThreads(1)
    raw = strip_mesh_id(common.prepared_parameters(name))
    analysis_class = common.recording_analysis(StructuralMechanicsAnalysis, _Variables())
    failure = None
    previous = Path.cwd()
    with tempfile.TemporaryDirectory() as scratch:
        os.chdir(scratch)
        start = time.perf_counter()
        try:
            analysis = analysis_class(
                KM.Model(), KM.Parameters(json.dumps(raw)), name, wall_cap=cap
            )
            try:
                analysis.Run()
            except RuntimeError as error:  # the reference's own failure is a result too
                info = analysis.model.GetModelPart("Structure").ProcessInfo
                failure = {
                    "step": int(info[KM.STEP]),
                    "time": float(info[KM.TIME]),
                    "message": [line for line in str(error).splitlines() if line.strip()][:3],
                }
        finally:
            os.chdir(previous)
        total = time.perf_counter() - start
    kept = _kept_steps(len(analysis.snapshots))
    history = analysis.history
    return {
        "model": name,
        "case": str(Path(*common.MODELS[name])),
        "kratos": importlib.metadata.version("KratosMultiphysics"),
        "kratos_contact": importlib.metadata.version("KratosContactStructuralMechanicsApplication"),
        "threads": 1,
        "mdpa": common.mdpa_path(name).name,
        "mdpa_sha256": common.mdpa_sha256(name),
        "end_time": raw["problem_data"]["end_time"],
        "reached_time": history[-1]["time"] if history else 0.0,
        "steps": len(history),
        "newton_iterations": sum(step["iterations"] for step in history),
        "non_converged_steps": sum(step["converged"] is False for step in history),
        "capped": analysis.capped,
        "wall_cap": cap,
        "failure": failure,
        "initialize_time": analysis.initialize_time,
        "loop_time": sum(step["wall"] for step in history),
        "loop_cpu_time": sum(step["cpu"] for step in history),
        "total_time": total,
        "load_average": os.getloadavg()[0],
        "nodes": analysis.nodes,
        "history": history,
        "snapshots": [record for k, record in enumerate(analysis.snapshots) if k in kept],
    }


def main() -> int:
    """Run the models, each in its own process (or, with --in-process, here)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", action="append", choices=sorted(common.MODELS))
    parser.add_argument("--cap", type=float, default=common.REFERENCE_CAP)
    parser.add_argument("--in-process", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()
    names = args.model or list(common.MODELS)
    if args.in_process:
        for name in names:
            fixture = run(name, args.cap)
            OUT.mkdir(parents=True, exist_ok=True)
            (OUT / f"{name}.json").write_text(json.dumps(fixture, indent=1) + "\n")
            print(
                f"{name}: {fixture['steps']} steps to t = {fixture['reached_time']:.6g} of "
                f"{fixture['end_time']}, {fixture['newton_iterations']} iterations, "
                f"{fixture['loop_time']:.1f} s, CPU {fixture['loop_cpu_time']:.1f} s "
                f"(capped: {fixture['capped']}, "
                f"failure: {fixture['failure']})",
                flush=True,
            )
        return 0
    status = 0
    for name in names:
        command = [
            sys.executable,
            __file__,
            "--in-process",
            "--model",
            name,
            "--cap",
            str(args.cap),
        ]
        log = Path(tempfile.gettempdir()) / f"kratos_examples_{name}.log"
        with log.open("w") as stream:  # the reference's own console output
            result = subprocess.run(command, check=False, stdout=stream, stderr=subprocess.STDOUT)
        print(log.read_text().rstrip().splitlines()[-1], flush=True)
        if result.returncode != 0:
            print(f"{name}: the reference process ended with code {result.returncode}")
            status = 1
    return status


if __name__ == "__main__":
    sys.exit(main())
