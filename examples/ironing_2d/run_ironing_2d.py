"""Run the 2D ironing example and compare the die's reaction history with the Kratos oracle.

The die (E = 10) is pressed 0.2 into the slab (E = 1, both compressible Neo-Hookean, plane strain,
total Lagrangian) over t in [0, 0.5] and then slid 2.0 along it over t in [0.5, 4.5], Coulomb
mu = 0.3 (README.md). Recorded after every step: the die's reaction, summed REACTION over the die's
top, as the drag Fx (its x component: the force that pulls the die along the slide) and the
pressing force Fy (minus its y component); the slab base's reaction (equilibrium: it must balance
the die's); Newton iterations; ACTIVE and SLIP slave nodes; on the slipping nodes the Coulomb law
|q| = mu p (p = -AUGMENTED_NORMAL_CONTACT_PRESSURE, q = |AUGMENTED_TANGENT_CONTACT_PRESSURE|).

Compared with the oracle fixtures written by scripts/oracle/ironing_2d.py
(tests/python/examples/data/ironing_2d_<variant>.json) on the steps both have: the relative
difference |F - F_oracle| / max |Fy_oracle| of Fx and Fy (scaled by the pressing force, the size of
the problem's forces). Steady sliding is the second half of the slide (t >= 2.5): there Fx/Fy is
compared with mu.

``--variant`` (``alm``, default; ``penalty``; ``alm_frictionless``; ``penalty_frictionless``)
changes the mortar type, the contact process and the contact type only, as the oracle driver does;
``--end-time`` shortens the history. Writes
``ironing_2d_reactions.png`` and ``ironing_2d_summary.txt``; exit code 0 when every step converged.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import math
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

import contact_app as ca
from contact_app.analysis import StructuralMechanicsAnalysis
from contact_app.analysis.reporting import Reporter

HERE = Path(__file__).resolve().parent
ORACLE = HERE.parents[1] / "tests" / "python" / "examples" / "data"
sys.path.insert(0, str(HERE.parent))
from hertz_common import (  # noqa: E402  (examples/hertz_common.py)
    example_inputs,
    load_script,
    working_directory,
)

make_mesh = load_script("ironing_2d_make_mesh", HERE / "make_mesh.py")

MESH = "ironing_2d.mdpa"
PLOT = "ironing_2d_reactions.png"
SUMMARY = "ironing_2d_summary.txt"
PRESS_END = 0.5  # end of the pressing phase
STEADY_START = 2.5  # second half of the slide
#: Variant -> the settings it changes (the oracle driver changes the same three).
VARIANTS = {
    "alm": {"mortar": "ALMContactFrictional", "process": "alm", "contact": "Frictional"},
    "penalty": {
        "mortar": "PenaltyContactFrictional",
        "process": "penalty",
        "contact": "Frictional",
    },
    "alm_frictionless": {
        "mortar": "ALMContactFrictionless",
        "process": "alm",
        "contact": "Frictionless",
    },
    "penalty_frictionless": {
        "mortar": "PenaltyContactFrictionless",
        "process": "penalty",
        "contact": "Frictionless",
    },
}


@dataclass
class Step:
    """The state after one step."""

    time: float
    iterations: int
    converged: bool
    fx: float  # drag on the die (sum of REACTION_X over its top)
    fy: float  # pressing force (minus the sum of REACTION_Y over its top)
    base_fx: float  # sum of REACTION_X over the slab's base
    base_fy: float
    active: int
    slip: int
    coulomb: float  # max | |q|/(mu p) - 1 | over the slipping nodes (nan if none)
    #: Slave nodes whose ACTIVE flag disagrees with their weighted gap G (ACTIVE with G >= 0, or
    #: inactive with G < 0 while a pair covers them): 0 in a converged penalty state (the ALM
    #: decides with k lambda + eps G and ends at G = 0 up to round-off).
    set_mismatches: int = 0


@dataclass
class IroningResult:
    """A run's history and the oracle's."""

    variant: str
    mu: float
    refinement: int | None
    nodes: int
    elements: int
    steps: list[Step]
    oracle: dict | None
    wall_time: float = math.nan
    notes: list[str] = field(default_factory=list)

    @property
    def converged(self) -> bool:
        """Every step converged."""
        return bool(self.steps) and all(s.converged for s in self.steps)

    def series(self, name: str) -> np.ndarray:
        """One recorded quantity over the steps."""
        return np.array([getattr(s, name) for s in self.steps], dtype=float)

    @property
    def steady(self) -> list[Step]:
        """The steps of steady sliding (t >= STEADY_START)."""
        return [s for s in self.steps if s.time >= STEADY_START - 1e-9]

    @property
    def steady_ratio(self) -> tuple[float, float, float]:
        """(mean, min, max) of Fx/Fy over steady sliding."""
        ratio = np.array([s.fx / s.fy for s in self.steady])
        return float(ratio.mean()), float(ratio.min()), float(ratio.max())

    def oracle_difference(self) -> tuple[int, float, float]:
        """(steps compared, max |dFx|, max |dFy|) / max |Fy_oracle| on the common steps."""
        if not self.oracle or not self.oracle["history"]:
            return 0, math.nan, math.nan
        ours = {round(s.time, 9): s for s in self.steps}
        pairs = [(ours.get(round(o["time"], 9)), o) for o in self.oracle["history"]]
        pairs = [(s, o) for s, o in pairs if s is not None]
        scale = max(abs(o["die_reaction_y"]) for _, o in pairs)
        dfx = max(abs(s.fx - o["die_reaction_x"]) for s, o in pairs) / scale
        dfy = max(abs(s.fy + o["die_reaction_y"]) for s, o in pairs) / scale
        return len(pairs), dfx, dfy


def variant_parameters(parameters: dict, variant: str) -> dict:
    """Set ``parameters`` (a ProjectParameters tree) to ``variant`` in place; return it."""
    settings = VARIANTS[variant]
    parameters["solver_settings"]["contact_settings"]["mortar_type"] = settings["mortar"]
    process = parameters["processes"]["contact_process_list"][0]
    process["python_module"] = f"{settings['process']}_contact_process"
    process["Parameters"]["contact_type"] = settings["contact"]
    return parameters


def _sum(part: ca.ModelPart, variable) -> float:
    return float(sum(node.GetSolutionStepValue(variable) for node in part.Nodes))


def coulomb_deviation(main: ca.ModelPart, mu: float) -> float:
    """Max | |q|/(mu p) - 1 | over the ACTIVE and SLIP slave nodes (nan if none slips)."""
    deviation = math.nan
    for node in main.GetSubModelPart("Contact_Slave").Nodes:
        if not (node.Is(ca.ACTIVE) and node.Is(ca.SLIP)):
            continue
        p = -node.GetValue(ca.AUGMENTED_NORMAL_CONTACT_PRESSURE)
        q = float(np.linalg.norm(np.asarray(node.GetValue(ca.AUGMENTED_TANGENT_CONTACT_PRESSURE))))
        value = abs(q / (mu * p) - 1.0) if p > 0.0 else math.inf
        deviation = value if math.isnan(deviation) else max(deviation, value)
    return deviation


def set_mismatches(main: ca.ModelPart) -> int:
    """Slave nodes ACTIVE with G >= 0, or inactive, covered and G < 0 (G = WEIGHTED_GAP)."""
    count = 0
    for node in main.GetSubModelPart("Contact_Slave").Nodes:
        gap = node.GetSolutionStepValue(ca.WEIGHTED_GAP)
        covered = node.GetValue(ca.NODAL_AREA) > 0.0
        if node.Is(ca.ACTIVE) != (gap < 0.0 and covered):
            count += 1
    return count


def record_step(main: ca.ModelPart, record, mu: float) -> Step:
    """The state of ``main`` after the step ``record`` (a reporter's StepRecord)."""
    top = main.GetSubModelPart("DISPLACEMENT_die_top")
    base = main.GetSubModelPart("DISPLACEMENT_slab_base")
    slave = main.GetSubModelPart("Contact_Slave").Nodes
    return Step(
        time=record.time,
        iterations=record.iterations,
        converged=record.converged,
        fx=_sum(top, ca.REACTION_X),
        fy=-_sum(top, ca.REACTION_Y),
        base_fx=_sum(base, ca.REACTION_X),
        base_fy=_sum(base, ca.REACTION_Y),
        active=sum(n.Is(ca.ACTIVE) for n in slave),
        slip=sum(n.Is(ca.ACTIVE) and n.Is(ca.SLIP) for n in slave),
        coulomb=coulomb_deviation(main, mu) if mu > 0.0 else math.nan,
        set_mismatches=set_mismatches(main),
    )


class _RecordingAnalysis(StructuralMechanicsAnalysis):
    """The analysis, appending ``record_step`` to ``history`` after every step."""

    mu = 0.0  # 0: frictionless, no Coulomb check
    history: list[Step]

    def FinalizeSolutionStep(self) -> None:  # noqa: N802 - Kratos name
        super().FinalizeSolutionStep()
        main = self.model.GetModelPart("Structure")
        self.history.append(record_step(main, self.reporter.steps[-1], self.mu))


def load_oracle(variant: str) -> dict | None:
    """The oracle fixture of ``variant`` (None if there is none)."""
    path = ORACLE / f"ironing_2d_{variant}.json"
    return json.loads(path.read_text(encoding="utf-8")) if path.exists() else None


def run(
    workdir: Path,
    refinement: int | None = None,
    variant: str = "alm",
    end_time: float | None = None,
    quiet: bool = True,
) -> IroningResult:
    """Mesh (level ``refinement``; the folder's or the example's mesh if None), run, record.

    ``end_time`` shortens the history (the fast test).
    """
    workdir = Path(workdir).resolve()
    mesh = workdir / MESH
    if refinement is not None:
        make_mesh.write_mesh(mesh, refinement)
    elif not mesh.exists():
        mesh.write_bytes((HERE / MESH).read_bytes())
    parameters_path, materials = example_inputs(workdir, HERE)
    parameters = json.loads(parameters_path.read_text(encoding="utf-8"))
    parameters["solver_settings"]["material_import_settings"]["materials_filename"] = str(materials)
    parameters["solver_settings"]["model_import_settings"]["input_filename"] = str(
        mesh.with_suffix("")
    )
    variant_parameters(parameters, variant)
    if end_time is not None:
        parameters["problem_data"]["end_time"] = end_time
    contact = parameters["processes"]["contact_process_list"][0]["Parameters"]
    mu = float(contact["friction_coefficients"]["0"])
    frictional = VARIANTS[variant]["contact"] == "Frictional"
    # The runner reports every step, NOT CONVERGED ones too (exit 1), so it goes on from them
    # (the default stops at the first one: docs/running.md "Non-convergence").
    options = {
        "base_dir": parameters_path.parent,
        "reporter": Reporter(quiet=quiet),
        "stop_on_non_convergence": False,
    }
    with working_directory(workdir):
        analysis = _RecordingAnalysis(ca.Model(), parameters, **options)
        analysis.mu, analysis.history = (mu if frictional else 0.0), []
        start = time.perf_counter()
        analysis.Run()
        elapsed = time.perf_counter() - start
    main = analysis.model.GetModelPart("Structure")
    oracle = load_oracle(variant)
    if oracle and oracle["mdpa_sha256"] != hashlib.sha256(mesh.read_bytes()).hexdigest():
        oracle = None  # the oracle ran another mesh
    return IroningResult(
        variant=variant,
        mu=mu,
        refinement=refinement,
        nodes=main.NumberOfNodes(),
        elements=main.NumberOfElements(),
        steps=analysis.history,
        oracle=oracle,
        wall_time=elapsed,
    )


def summary(result: IroningResult) -> str:
    """The text summary of a run."""
    r = result
    status = "all steps converged" if r.converged else "NOT CONVERGED"
    iterations = r.series("iterations").astype(int)
    press = [s for s in r.steps if s.time <= PRESS_END + 1e-9]
    lines = [
        f"ironing_2d ({r.variant}): die pressed 0.2 into a slab, then slid 2.0; mu = {r.mu:g}",
        f"  mesh: {r.nodes} nodes, {r.elements} quads"
        + ("" if r.refinement is None else f", refinement {r.refinement}"),
        f"  Newton iterations: {iterations.sum()} in {len(r.steps)} steps "
        f"(pressing {sum(s.iterations for s in press)} in {len(press)}, per step "
        f"{iterations.min()}-{iterations.max()}, mean {iterations.mean():.2f}), {status}",
    ]
    if press:
        end = press[-1]
        lines.append(f"  end of pressing (t = {end.time:g}): Fx = {end.fx:.6g}, Fy = {end.fy:.6g}")
    if r.steady:
        mean, low, high = r.steady_ratio
        last = r.steps[-1]
        lines += [
            f"  steady sliding (t >= {STEADY_START:g}, {len(r.steady)} steps): Fx/Fy mean "
            f"{mean:.4f} (min {low:.4f}, max {high:.4f}) vs mu = {r.mu:g}",
            f"  last step (t = {last.time:g}): Fx = {last.fx:.6g}, Fy = {last.fy:.6g}, "
            f"{last.active} active, {last.slip} slip",
        ]
        coulomb = [s.coulomb for s in r.steady if not math.isnan(s.coulomb)]
        if coulomb:
            lines.append(f"  slip nodes: max | |q|/(mu p) - 1 | = {max(coulomb):.2e}")
    balance = max(
        max(abs(s.fx + s.base_fx), abs(s.fy - s.base_fy)) / max(abs(s.fy), 1e-300) for s in r.steps
    )
    lines.append(f"  equilibrium: max |die + base reaction| / Fy = {balance:.2e}")
    compared, dfx, dfy = r.oracle_difference()
    if r.oracle is None:
        lines.append("  oracle: no fixture for this variant and mesh")
    else:
        failure = r.oracle.get("failure")
        lines.append(
            f"  oracle (Kratos {r.oracle['kratos']}): {len(r.oracle['history'])} steps"
            + (
                f", stopped at step {failure['step']} (t = {failure['time']:.3g})"
                if failure
                else ""
            )
        )
        if compared:
            lines.append(
                f"    on {compared} common steps: max |dFx| = {dfx:.2e}, max |dFy| = {dfy:.2e} "
                "(relative to max |Fy_oracle|)"
            )
    lines.append(f"  wall time: {r.wall_time:.1f} s")
    return "\n".join(lines)


def plot(result: IroningResult, path: Path) -> None:
    """Fx, Fy and mu Fy against time, ours and the oracle's."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    r = result
    t = r.series("time")
    fig, axis = plt.subplots(figsize=(8.0, 5.0))
    axis.plot(t, r.series("fy"), "C0-", label="Fy (pressing force), contact_app")
    axis.plot(t, r.series("fx"), "C3-", label="Fx (drag), contact_app")
    axis.plot(t, r.mu * r.series("fy"), "k:", label=f"μ Fy (μ = {r.mu:g}), contact_app")
    if r.oracle and r.oracle["history"]:
        history = r.oracle["history"]
        ot = [h["time"] for h in history]
        kratos = f"Kratos {r.oracle['kratos']}"
        axis.plot(
            ot, [-h["die_reaction_y"] for h in history], "C0o", mfc="none", label=f"Fy, {kratos}"
        )
        axis.plot(
            ot, [h["die_reaction_x"] for h in history], "C3s", mfc="none", label=f"Fx, {kratos}"
        )
        failure = r.oracle.get("failure")
        if failure:
            axis.axvline(failure["time"], color="grey", linestyle="--", label=f"{kratos} stops")
    axis.axvline(PRESS_END, color="grey", linewidth=0.6)
    axis.set_xlabel("time (pressing 0-0.5, sliding 0.5-4.5)")
    axis.set_ylabel("die reaction")
    axis.set_title(f"2D ironing, {r.variant}: die reaction history")
    axis.grid(True, alpha=0.3)
    axis.legend(fontsize=8, loc="center right")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def write_outputs(result: IroningResult, workdir: Path) -> str:
    """Write the summary and the plot into ``workdir``; return the summary."""
    text = summary(result)
    (Path(workdir) / SUMMARY).write_text(text + "\n", encoding="utf-8")
    plot(result, Path(workdir) / PLOT)
    return text


def main(argv: list[str] | None = None) -> int:
    """Run, write the plot and the summary, print the summary; 1 if a step did not converge."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--refinement", type=int, help="write the mesh at this level (1 = coarsest)"
    )
    parser.add_argument("--variant", default="alm", choices=sorted(VARIANTS))
    parser.add_argument("--quiet", action="store_true", help="no step table")
    parser.add_argument(
        "--end-time", type=float, help="stop at this time (default: the whole history, 4.5)"
    )
    args = parser.parse_args(argv)
    workdir = Path.cwd()
    result = run(workdir, args.refinement, args.variant, args.end_time, quiet=args.quiet)
    print(write_outputs(result, workdir))
    print(f"outputs: {workdir / PLOT}, {workdir / SUMMARY}")
    return 0 if result.converged else 1


if __name__ == "__main__":
    sys.exit(main())
