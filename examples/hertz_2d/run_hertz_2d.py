"""Run the 2D Hertz example and compare the contact pressure with the analytic semi-ellipse.

Runs ``ProjectParameters.json`` (from the working directory, else from this folder) on
``hertz_2d.msh`` in the working directory, writing the mesh first when it is missing or when
``--refinement`` is given. Afterwards it reads the contact pressure
p = -AUGMENTED_NORMAL_CONTACT_PRESSURE on the ACTIVE slave (cylinder) nodes and estimates:

* the half-width b from the second moment of the nodal forces f_i = p_i L_i (L_i the lumped
  nodal length of the slave lines in the reference configuration): for the Hertz semi-ellipse
  sum(x^2 f) / sum(f) = b^2 / 4 (x >= 0 on the half model, which does not change the ratio);
* the peak pressure p0 (and a second b) by fitting the semi-ellipse p(x)^2 = p0^2 (1 - x^2/b^2)
  (linear least squares in x^2).

The moment estimate of b is the primary one: it converges monotonically over the refinement
levels, while the fit moves with where the contact edge falls between two nodes. The script
writes ``hertz_2d_pressure.png`` and ``hertz_2d_summary.txt``.
Analytic values (plane strain, line load P' per unit length, benchmarks.md 2.2):
1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, b = sqrt(4 P' R / (pi E*)), p0 = 2 P' / (pi b).
P' is what the LINE_LOAD conditions apply at the end (twice the half model's load).
Exit code 0 when every step converged, 1 otherwise.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

import contact_app as ca

HERE = Path(__file__).resolve().parent
sys.path[:0] = [str(HERE), str(HERE.parent)]
import hertz_common as common  # noqa: E402  (examples/hertz_common.py)

EXAMPLE = common.Example(HERE, "pressure", default_refinement=2)
make_mesh = EXAMPLE.make_mesh


@dataclass(kw_only=True)
class HertzResult(common.HertzRun):
    """What one run measured, next to the analytic values; p0 is the fit's."""

    b_analytic: float
    b: float  # moment estimate
    b_fit: float

    b_error = common.RelativeError("b", "b_analytic")
    b_fit_error = common.RelativeError("b_fit", "b_analytic")


#: (b, p0) of p^2 = p0^2 - (p0/b)^2 x^2 fitted in the least-squares sense.
fit_semi_ellipse = common.SEMI_ELLIPSE.fit
#: Half-width from sum(x^2 f) / sum(f) = b^2 / 4 (second moment of the semi-ellipse).
moment_half_width = common.SEMI_ELLIPSE.moment_width


def evaluate(analysis: ca.analysis.StructuralMechanicsAnalysis, materials: Path) -> HertzResult:
    """Measure b and p0 on a finished analysis and compute the analytic values."""
    main = analysis.model.GetModelPart("Structure")
    half_load = 0.0
    for condition in main.GetSubModelPart("LineLoad2D_top").Conditions:
        nodes = condition.GetNodes()
        length = math.hypot(nodes[1].X0 - nodes[0].X0, nodes[1].Y0 - nodes[0].Y0)
        half_load += np.linalg.norm(np.asarray(condition.GetValue(ca.LINE_LOAD))) * length
    load = 2.0 * half_load  # the model is the half x >= 0
    modulus = common.effective_modulus(materials)
    b_analytic = math.sqrt(4.0 * load * make_mesh.RADIUS / (math.pi * modulus))
    p0_analytic = 2.0 * load / (math.pi * b_analytic)

    slave = main.GetSubModelPart("Contact_Slave")
    nodal_length = common.lumped_line_lengths(slave)
    profile = sorted(
        (node.X0, -node.GetValue(ca.AUGMENTED_NORMAL_CONTACT_PRESSURE), node.Is(ca.ACTIVE))
        for node in slave.Nodes
    )
    active = np.array(
        [
            (node.X0, -node.GetValue(ca.AUGMENTED_NORMAL_CONTACT_PRESSURE), nodal_length[node.Id])
            for node in slave.Nodes
            if node.Is(ca.ACTIVE)
        ]
    )
    if len(active):
        b = moment_half_width(active[:, 0], active[:, 1] * active[:, 2])
        b_fit, p0 = fit_semi_ellipse(active[:, 0], active[:, 1])
    else:
        b = b_fit = p0 = 0.0
    xs = [x for x, _, _ in profile]
    return HertzResult(
        refinement=None,
        spacing=xs[1] - xs[0],
        nodes=main.NumberOfNodes(),
        elements=main.NumberOfElements(),
        load=load,
        effective_modulus=modulus,
        b_analytic=b_analytic,
        p0_analytic=p0_analytic,
        b=b,
        p0=p0,
        b_fit=b_fit,
        active_nodes=len(active),
        wall_time=0.0,
        profile=profile,
        **common.newton_record(analysis),
    )


def run(workdir: Path, refinement: int | None = None, quiet: bool = True) -> HertzResult:
    """Run the example in ``workdir``, meshed as ``hertz_common.run_example`` says."""

    def analyse(parameters: Path) -> ca.analysis.StructuralMechanicsAnalysis:
        # The runner reports every step, NOT CONVERGED ones too (exit 1), so it goes on from them
        # (the default stops at the first one: docs/running.md "Non-convergence").
        return ca.analysis.run(parameters, quiet=quiet, stop_on_non_convergence=False)

    return EXAMPLE.run(workdir, refinement, analyse, evaluate)


def summary(result: HertzResult) -> str:
    """The text summary of a run."""
    level = common.refinement_text(result)
    lines = [
        "hertz_2d: elastic cylinder on an elastic foundation, plane strain, ALM frictionless",
        f"  R = {make_mesh.RADIUS:g} mm, P' = {result.load:.6g} N/mm, "
        f"E* = {result.effective_modulus:.6g} MPa (units: mm, N, MPa)",
        f"  mesh: {result.nodes} nodes, {result.elements} quads{level}, contact spacing "
        f"h = {result.spacing:.4g} (b/h = {result.b_analytic / result.spacing:.1f})",
        f"  half-width b (moment): computed {result.b:.6g}, analytic {result.b_analytic:.6g}, "
        f"error {100 * result.b_error:.2f} % (b/R = {result.b_analytic / make_mesh.RADIUS:.3f})",
        f"  peak pressure p0 (fit): computed {result.p0:.6g}, analytic {result.p0_analytic:.6g}, "
        f"error {100 * result.p0_error:.2f} %",
        f"  fitted half-width b: {result.b_fit:.6g}, error {100 * result.b_fit_error:.2f} %",
        f"  active slave nodes: {result.active_nodes}",
    ]
    return common.hertz_summary(result, lines)


def plot(result: HertzResult, path: Path) -> None:
    """Contact pressure on the slave nodes vs the analytic and the fitted semi-ellipse."""

    def estimates(axis) -> None:
        if result.b_fit > 0.0:
            fit = f"fit: b = {result.b_fit:.4g}, p0 = {result.p0:.4g}"
            common.plot_elliptic_profile(axis, result.p0, result.b_fit, "C0--", fit)
            axis.axvline(result.b, color="C3", linestyle=":", label=f"moment: b = {result.b:.4g}")

    common.plot_pressure(
        path,
        result,
        result.b_analytic,
        estimates,
        "x, distance from the contact centre (mm)",
        f"2D Hertz: b error {100 * result.b_error:.2f} %, p0 error {100 * result.p0_error:.2f} %",
    )


def main(argv: list[str] | None = None) -> int:
    """Run, write the plot and the summary, print the summary; 1 if a step did not converge."""
    return EXAMPLE.main(argv, __doc__, run, summary, plot)


if __name__ == "__main__":
    sys.exit(main())
