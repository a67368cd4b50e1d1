"""Run the 3D Hertz example and compare the contact pressure with the analytic half-ellipsoid.

Runs ``ProjectParameters.json`` (from the working directory, else from this folder) on
``hertz_3d.msh`` in the working directory, writing the mesh first when it is missing or when
``--refinement`` is given. Afterwards it reads the contact pressure
p = -AUGMENTED_NORMAL_CONTACT_PRESSURE on the ACTIVE slave (sphere) nodes and estimates the
contact radius a and the peak pressure p0 in two ways:

* moment: with the nodal forces f_i = p_i A_i (A_i the lumped nodal area of the slave faces in the
  reference configuration), sum(r^2 f) / sum(f) = (2/5) a^2 for the Hertz profile, and
  p0 = 3F / (2 pi a^2);
* fit: p(r)^2 = p0^2 (1 - r^2/a^2) fitted to the active nodes (linear least squares in r^2).

Analytic values (point contact under the force F, benchmarks.md 2.1):
1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, a = (3 F R / (4 E*))^(1/3), p0 = 3 F / (2 pi a^2).
F is what the SURFACE_LOAD conditions apply at the end (four times the quarter model's load).
Writes ``hertz_3d_pressure.png``, ``hertz_3d_summary.txt`` and ``vtk_output/``.
Exit code 0 when every step converged, 1 otherwise.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

import contact_app as ca
from contact_app.analysis.reporting import Reporter
from contact_app.parameters import Parameters

HERE = Path(__file__).resolve().parent
sys.path[:0] = [str(HERE), str(HERE.parent)]
import hertz_common as common  # noqa: E402  (examples/hertz_common.py)

EXAMPLE = common.Example(HERE, "pressure", default_refinement=2)
make_mesh = EXAMPLE.make_mesh


@dataclass(kw_only=True)
class HertzResult(common.HertzRun):
    """What one run measured, next to the analytic values; p0 = 3F / (2 pi a^2), moment a."""

    dofs: int  # equations of the last step: displacements and the paired slave multipliers
    a_analytic: float
    a: float  # moment estimate
    a_fit: float
    p0_fit: float
    contact_force: float  # 4 sum(f) over the active slave nodes

    a_error = common.RelativeError("a", "a_analytic")
    a_fit_error = common.RelativeError("a_fit", "a_analytic")
    p0_fit_error = common.RelativeError("p0_fit", "p0_analytic")


#: (a, p0) of p^2 = p0^2 - (p0/a)^2 r^2 fitted in the least-squares sense.
fit_half_ellipsoid = common.HALF_ELLIPSOID.fit
#: Contact radius from sum(r^2 f) / sum(f) = (2/5) a^2, the Hertz pressure's second moment.
moment_radius = common.HALF_ELLIPSOID.moment_width


def _reference(node) -> np.ndarray:
    return np.array([node.X0, node.Y0, node.Z0])


class RecordingAnalysis(ca.analysis.StructuralMechanicsAnalysis):
    """The driver's analysis, also recording the equation system size of every step."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.system_sizes: list[int] = []

    def FinalizeSolutionStep(self) -> None:  # noqa: N802  (Kratos name)
        """Record the size of the system just solved, then finalize the step."""
        builder = self._GetSolver().GetBuilderAndSolver()
        self.system_sizes.append(builder.GetEquationSystemSize())
        super().FinalizeSolutionStep()


def evaluate(analysis: RecordingAnalysis, materials: Path) -> HertzResult:
    """Measure a and p0 on a finished analysis and compute the analytic values."""
    main = analysis.model.GetModelPart("Structure")
    quarter_load = 0.0
    for condition in main.GetSubModelPart("SurfaceLoad3D_top").Conditions:
        corners = np.array([_reference(node) for node in condition.GetNodes()])
        area = common.quad_nodal_areas(corners).sum()
        quarter_load += np.linalg.norm(np.asarray(condition.GetValue(ca.SURFACE_LOAD))) * area
    load = 4.0 * quarter_load  # the model is the quarter x, y >= 0
    modulus = common.effective_modulus(materials)
    a_analytic = (3.0 * load * make_mesh.RADIUS / (4.0 * modulus)) ** (1.0 / 3.0)
    p0_analytic = 3.0 * load / (2.0 * math.pi * a_analytic**2)

    slave = main.GetSubModelPart("Contact_Slave")
    nodal_area: dict[int, float] = {}
    for condition in slave.Conditions:
        nodes = condition.GetNodes()
        areas = common.quad_nodal_areas(np.array([_reference(node) for node in nodes]))
        for node, area in zip(nodes, areas, strict=True):
            nodal_area[node.Id] = nodal_area.get(node.Id, 0.0) + area
    rows = sorted(
        (
            math.hypot(node.X0, node.Y0),
            -node.GetValue(ca.AUGMENTED_NORMAL_CONTACT_PRESSURE),
            node.Is(ca.ACTIVE),
            nodal_area.get(node.Id, 0.0),
        )
        for node in slave.Nodes
    )
    active = np.array([(r, p, area) for r, p, is_active, area in rows if is_active])
    if len(active):
        force = active[:, 1] * active[:, 2]
        a = moment_radius(active[:, 0], force)
        a_fit, p0_fit = fit_half_ellipsoid(active[:, 0], active[:, 1])
        contact_force = 4.0 * float(force.sum())
    else:
        a = a_fit = p0_fit = contact_force = 0.0
    return HertzResult(
        refinement=None,
        spacing=sorted({round(r, 12) for r, *_ in rows})[1],
        nodes=main.NumberOfNodes(),
        elements=main.NumberOfElements(),
        dofs=analysis.system_sizes[-1] if analysis.system_sizes else 0,
        load=load,
        effective_modulus=modulus,
        a_analytic=a_analytic,
        p0_analytic=p0_analytic,
        a=a,
        p0=3.0 * load / (2.0 * math.pi * a**2) if a > 0.0 else 0.0,
        a_fit=a_fit,
        p0_fit=p0_fit,
        contact_force=contact_force,
        active_nodes=len(active),
        wall_time=0.0,
        profile=[(r, p, is_active) for r, p, is_active, _ in rows],
        **common.newton_record(analysis),
    )


def run(workdir: Path, refinement: int | None = None, quiet: bool = True) -> HertzResult:
    """Run the example in ``workdir``, meshed as ``hertz_common.run_example`` says."""

    def analyse(parameters: Path) -> RecordingAnalysis:
        analysis = RecordingAnalysis(
            ca.Model(),
            Parameters.from_file(parameters),
            base_dir=parameters.parent,
            reporter=Reporter(quiet=quiet),
            # The runner reports every step, NOT CONVERGED ones too (exit 1), so it goes on
            # from them (the default stops at the first: docs/running.md "Non-convergence").
            stop_on_non_convergence=False,
        )
        analysis.Run()
        return analysis

    return EXAMPLE.run(workdir, refinement, analyse, evaluate)


def summary(result: HertzResult) -> str:
    """The text summary of a run."""
    level = common.refinement_text(result)
    lines = [
        "hertz_3d: elastic sphere on an elastic block, quarter model, ALM frictionless",
        f"  R = {make_mesh.RADIUS:g} mm, F = {result.load:.6g} N, "
        f"E* = {result.effective_modulus:.6g} MPa (units: mm, N, MPa)",
        f"  mesh: {result.nodes} nodes, {result.elements} hexahedra{level}, {result.dofs} DoFs, "
        f"contact spacing h = {result.spacing:.4g} "
        f"(a/h = {result.a_analytic / result.spacing:.1f})",
        f"  contact radius a (moment): computed {result.a:.6g}, analytic "
        f"{result.a_analytic:.6g}, error {100 * result.a_error:.2f} % "
        f"(a/R = {result.a_analytic / make_mesh.RADIUS:.3f})",
        f"  peak pressure p0 = 3F/(2 pi a^2): computed {result.p0:.6g}, analytic "
        f"{result.p0_analytic:.6g}, error {100 * result.p0_error:.2f} %",
        f"  fit p^2 = p0^2 (1 - r^2/a^2): a = {result.a_fit:.6g} "
        f"(error {100 * result.a_fit_error:.2f} %), p0 = {result.p0_fit:.6g} "
        f"(error {100 * result.p0_fit_error:.2f} %)",
        f"  active slave nodes: {result.active_nodes}, their force 4 sum(p A) = "
        f"{result.contact_force:.6g} N "
        f"({100 * (result.contact_force / result.load - 1):+.2f} % of F)",
    ]
    return common.hertz_summary(result, lines)


def plot(result: HertzResult, path: Path) -> None:
    """Contact pressure on the slave nodes vs r, with the analytic and the fitted profiles."""

    def estimates(axis) -> None:
        if result.a > 0.0:
            moment = f"moment: a = {result.a:.4g}, p0 = 3F/(2πa²) = {result.p0:.4g}"
            common.plot_elliptic_profile(axis, result.p0, result.a, "C3:", moment)
            fit = f"fit: a = {result.a_fit:.4g}, p0 = {result.p0_fit:.4g}"
            common.plot_elliptic_profile(axis, result.p0_fit, result.a_fit, "C0--", fit)

    common.plot_pressure(
        path,
        result,
        result.a_analytic,
        estimates,
        "r, distance from the contact axis (mm)",
        f"3D Hertz: a error {100 * result.a_error:.2f} %, p0 error {100 * result.p0_error:.2f} %",
        fontsize="small",
    )


def main(argv: list[str] | None = None) -> int:
    """Run, write the plot and the summary, print the summary; 1 if a step did not converge."""
    return EXAMPLE.main(argv, __doc__, run, summary, plot)


if __name__ == "__main__":
    sys.exit(main())
