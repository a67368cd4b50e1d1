r"""Speed against the reference on the example collection's models (issue 17 item 6).

For each model of ``../shared/kratos_examples`` runs contact_app with the model's own settings
(one thread: ``OMP_NUM_THREADS`` and ``OPENBLAS_NUM_THREADS`` are 1), to the time the reference
reached in its fixture (``tests/python/examples/data/kratos_examples/<model>.json``, written by
``scripts/oracle/kratos_examples.py`` with Kratos 10.4.4, one thread, on this machine) or until
``--cap`` seconds of wall time have passed (when the reference finished no step: as far as ours
gets in the cap), and prints per model: how far each got, the Newton
iterations and the wall and CPU time of the solution loop of both systems over the span both
covered (steps up to the smaller of the two times reached), and the ratios reference / ours (above
1: ours is faster). Wall time is what a user waits; CPU time (of the process, one thread) is
less disturbed by other load on the machine, so both are shown, with the load average of both
runs. Import and initialize are not in the loop times (the ``init`` column is ours).

Usage::

    python benchmarks/examples_vs_reference.py [--model NAME ...] [--cap 120]
"""

from __future__ import annotations

import os

os.environ["OMP_NUM_THREADS"] = "1"  # before contact_app (and OpenBLAS) are loaded
os.environ["OPENBLAS_NUM_THREADS"] = "1"

import argparse  # noqa: E402
import json  # noqa: E402
import sys  # noqa: E402
from pathlib import Path  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "python" / "examples"))
import kratos_examples_common as common  # noqa: E402  (tests/python/examples/)

DATA = ROOT / "tests" / "python" / "examples" / "data" / "kratos_examples"


def _span(history: list[dict], until: float) -> dict:
    """Steps, iterations, wall and CPU time of the steps of ``history`` up to TIME ``until``."""
    steps = [step for step in history if step["time"] <= until + 1.0e-9 * max(1.0, until)]
    return {
        "steps": len(steps),
        "iterations": sum(step["iterations"] for step in steps),
        "wall": sum(step["wall"] for step in steps),
        "cpu": sum(step["cpu"] for step in steps),
    }


def measure(name: str, cap: float) -> dict:
    """Run ours on ``name`` and set it against the reference's fixture."""
    reference = json.loads((DATA / f"{name}.json").read_text())
    # To where the reference got; when it finished no step, as far as ours gets in the cap.
    end_time = reference["reached_time"] if reference["steps"] else None
    analysis, failure = common.run_ours(
        name, end_time=end_time, wall_cap=cap, keep_snapshots=lambda t: False
    )
    ours_history = analysis.history
    ours_reached = ours_history[-1]["time"] if ours_history else 0.0
    common_time = min(ours_reached, reference["reached_time"])
    ours = _span(ours_history, common_time)
    ref = _span(reference["history"], common_time)
    return {
        "model": name,
        "common_time": common_time,
        "ours_reached": ours_reached,
        "ours_failure": failure,
        "ours_capped": analysis.capped,
        "ours_init": analysis.initialize_time,
        "reference_reached": reference["reached_time"],
        "reference_end": reference["end_time"],
        "reference_stopped": (
            "cap" if reference["capped"] else "error" if reference["failure"] else "end"
        ),
        "ours": ours,
        "reference": ref,
        "wall_ratio": ref["wall"] / ours["wall"] if ours["wall"] > 0 else float("nan"),
        "cpu_ratio": ref["cpu"] / ours["cpu"] if ours["cpu"] > 0 else float("nan"),
        "load": (os.getloadavg()[0], reference["load_average"]),
    }


HEADER = (
    f"{'model':<34} {'t common':>8} {'steps':>11} {'Newton it':>11} "
    f"{'wall s ours/ref':>15} {'ratio':>5} {'CPU s ours/ref':>15} {'ratio':>5} "
    f"{'ours reached':>12} {'ref reached':>16} {'init':>5} {'load':>9}"
)


def row(result: dict) -> str:
    """One line of the table."""
    ours, ref = result["ours"], result["reference"]
    ref_reached = f"{result['reference_reached']:.4g} ({result['reference_stopped']})"
    ours_state = "cap" if result["ours_capped"] else "stop" if result["ours_failure"] else "ok"
    return (
        f"{result['model']:<34} {result['common_time']:>8.4g} "
        f"{ours['steps']:>5}/{ref['steps']:<5} {ours['iterations']:>5}/{ref['iterations']:<5} "
        f"{ours['wall']:>7.1f}/{ref['wall']:<7.1f} {result['wall_ratio']:>5.2f} "
        f"{ours['cpu']:>7.1f}/{ref['cpu']:<7.1f} {result['cpu_ratio']:>5.2f} "
        f"{result['ours_reached']:>6.4g} ({ours_state:>4}) {ref_reached:>16} "
        f"{result['ours_init']:>5.1f} {result['load'][0]:>4.1f}/{result['load'][1]:<4.1f}"
    )


def main() -> int:
    """Measure the models and print the table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", action="append", choices=sorted(common.MODELS))
    parser.add_argument(
        "--cap", type=float, default=common.REFERENCE_CAP, help="wall seconds per model for ours"
    )
    parser.add_argument("--json", type=Path, help="also write the results to this file")
    args = parser.parse_args()
    names = args.model or list(common.MODELS)
    print(HEADER, flush=True)
    results = []
    for name in names:
        result = measure(name, args.cap)
        results.append(result)
        print(row(result), flush=True)
    print(
        "steps, Newton it, wall, CPU: ours/reference over [0, t common]; ratio = reference / ours "
        "(> 1: ours faster); reached: how far each got (cap: wall cap, error/stop: failed, ok/end: "
        "to the end asked); load: 1-min load average during ours / the reference"
    )
    if args.json:
        args.json.write_text(json.dumps(results, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
