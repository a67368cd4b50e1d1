"""Run the 2D Cattaneo-Mindlin example and compare the contact tractions with the analytic ones.

A cylinder pressed by P' (steps 1-4, t in [0, 1]) and then pulled sideways by Q' < mu P' with P'
kept (steps 5-8, t in [1, 2]); plane strain, identical materials, so the normal and the tangential
problems uncouple (Johnson, Contact Mechanics, 7.1):

* normal: a = sqrt(4 P' R / (pi E*)), p(x) = p0 sqrt(1 - x^2/a^2), p0 = 2 P' / (pi a);
* tangential: a central stick zone |x| < c, c/a = sqrt(1 - Q'/(mu P')), where
  q(x) = mu p0 sqrt(1 - x^2/a^2) - mu p0 (c/a) sqrt(1 - x^2/c^2), and slip zones c < |x| < a
  where q = mu p.

The loads are LINE_LOAD components on the cylinder's flat top (y = R), written by
``load_values`` from Q'/(mu P') (``--ratio``, default 0.5) and mu (the contact process's
``friction_coefficients``): a uniform -P'/(2R) in y; a uniform Q'/(2R) in x; and a couple
+-Q'/R in y on the right and left halves of the top. The couple cancels the moment Q' R of the
tangential load about the contact point, which the contact (width 2a = 0.023 R) cannot carry:
without it the cylinder tips over. It is piecewise constant so that the conditions, whose value
is evaluated at their centre, apply exactly Q' R (sum of |x_c| L = R^2 on any mesh with a node at
x = 0). The analysis is geometrically linear (move_mesh_flag false), as the analytic solution.

Measured on the active slave (cylinder) nodes: p = -AUGMENTED_NORMAL_CONTACT_PRESSURE, the shear
traction q = |t| (t = AUGMENTED_TANGENT_CONTACT_PRESSURE, the foundation's traction on the
cylinder, against Q'; q is its magnitude with the sign of -t_x), STICK = ACTIVE and not SLIP.

* a from the second moment of the nodal normal forces, p0 from the semi-ellipse fit (as
  hertz_2d);
* c as the half-width of the stick set: on each side the midpoint between the outermost stick
  node and the next slave node (a slip node), c = (c_right - c_left) / 2; with the stick set
  right, that is within h/2 of the exact c (h the node spacing, uniform over the contact);
* c a second way, between the nodes: the deficit mu p - q is mu p0 (c/a) sqrt(1 - x^2/c^2) in
  the stick zone and 0 in the slip zones, a semi-ellipse of half-width c, so c^2 = 4
  sum(x^2 d L) / sum(d L) (d L the nodal deficit forces, L the lumped nodal length);
* the tangential force sum(q L) against Q', and the base's x reaction.

Writes ``cattaneo_mindlin_2d_traction.png`` and ``cattaneo_mindlin_2d_summary.txt``; exit code 0
when every step converged, 1 otherwise.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

import contact_app as ca
from contact_app.analysis import StructuralMechanicsAnalysis

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
import cattaneo_mindlin_common as partial_slip  # noqa: E402  (examples/cattaneo_mindlin_common.py)
import hertz_common as common  # noqa: E402  (examples/hertz_common.py)

make_mesh = common.mesh_script(HERE)

MESH, PLOT, SUMMARY = common.output_names(HERE, "traction")
DEFAULT_REFINEMENT = 2
EXAMPLE = partial_slip.MeshedExample(HERE, MESH, DEFAULT_REFINEMENT, make_mesh.write_mesh)
DEFAULT_RATIO = 0.5  # Q'/(mu P'): c/a = sqrt(0.5) = 0.707
LINE_PRESSURE = 6.25  # N/mm^2 on the top of length 2R: P' = 125 N/mm, as hertz_2d
TOP_LENGTH = 2.0 * make_mesh.RADIUS
OPTIONS = {"ratio": ("Q'/(mu P')", DEFAULT_RATIO)}  # of the command line


def c_over_a(ratio: float) -> float:
    """Cattaneo's stick zone: c/a = sqrt(1 - Q'/(mu P'))."""
    return math.sqrt(1.0 - ratio)


def load_values(ratio: float, mu: float) -> list[str | float]:
    """The LINE_LOAD value [x, y, z] of the top conditions for Q'/(mu P') = ``ratio``."""
    if not 0.0 < ratio < 1.0:
        raise ValueError(f"Q'/(mu P') must be in (0, 1) for partial slip, got {ratio}")
    tangential = ratio * mu * LINE_PRESSURE * TOP_LENGTH
    shear = tangential / TOP_LENGTH
    couple = tangential / make_mesh.RADIUS
    return [
        f"{shear:.12g}*{partial_slip.RAMP}",
        f"-{LINE_PRESSURE:.12g}*min(t, 1.0) + {couple:.12g}*x/abs(x)*{partial_slip.RAMP}",
        0.0,
    ]


@dataclass
class SlaveNode:
    """The contact state of one cylinder surface node."""

    x: float
    p: float  # normal pressure, > 0 in compression
    q: float  # shear traction magnitude, signed as -t_x (> 0 against Q')
    active: bool
    slip: bool
    length: float  # lumped nodal length (reference configuration)
    slip_angle: float  # degrees between t and +WEIGHTED_SLIP (slip nodes; 0 otherwise)
    slide: float  # u_x of the node minus u_x of the foundation's surface at the same x

    @property
    def shear(self) -> float:
        """|t|."""
        return abs(self.q)

    @property
    def stick(self) -> bool:
        """ACTIVE and not SLIP."""
        return self.active and not self.slip


@dataclass(kw_only=True)
class StepState(partial_slip.Step):
    """Newton iterations and the stick zone after one step (ratio: Q'/(mu P'))."""

    stick_half_width: float  # midpoint estimate, nan when no node slips

    def stick_text(self, a: float) -> str:
        """The midpoint c/a against the theory's."""
        analytic = c_over_a(self.ratio)
        if math.isnan(self.stick_half_width):
            return f", c/a analytic {analytic:.3f}"
        return f", c/a {self.stick_half_width / a:.3f} (analytic {analytic:.3f})"


@dataclass(kw_only=True)
class CattaneoMindlinResult(partial_slip.CattaneoMindlinRun):
    """What one run measured, next to the analytic values."""

    applied_moment: float  # of the top loads about the contact point (0 up to round-off)
    p0: float  # semi-ellipse fit
    c_right: float  # midpoint between the outermost stick node and the next node, x > 0
    c_left: float  # same for x < 0 (negative)
    contact_tangential_force: float  # sum(q L) over the active nodes
    contact_normal_force: float  # sum(p L)
    stick_contiguous: bool  # no slip node between two stick nodes

    @property
    def c_over_a_analytic(self) -> float:
        """sqrt(1 - Q'/(mu P'))."""
        return c_over_a(self.ratio)

    @property
    def c(self) -> float:
        """Stick half-width, midpoint estimate."""
        return 0.5 * (self.c_right - self.c_left)

    @property
    def stick_offset(self) -> float:
        """Centre of the stick set (0 by symmetry)."""
        return 0.5 * (self.c_right + self.c_left)

    @property
    def p0_error(self) -> float:
        """Relative error of the peak pressure."""
        return common.relative_error(self.p0, self.p0_analytic)

    @property
    def contact_friction(self) -> float:
        """sum(q L)."""
        return self.contact_tangential_force


def stick_half_width(nodes: list[SlaveNode]) -> tuple[float, float]:
    """(c_right, c_left): midpoints between the outermost stick nodes and their outer neighbours.

    ``nodes`` sorted by x. nan when no node sticks or a stick node is the last slave node.
    """
    stick = [i for i, node in enumerate(nodes) if node.stick]
    if not stick or stick[0] == 0 or stick[-1] == len(nodes) - 1:
        return math.nan, math.nan
    right = 0.5 * (nodes[stick[-1]].x + nodes[stick[-1] + 1].x)
    left = 0.5 * (nodes[stick[0]].x + nodes[stick[0] - 1].x)
    return right, left


def slave_profile(main: ca.ModelPart) -> list[SlaveNode]:
    """The contact state of every slave node, sorted by x."""
    slave = main.GetSubModelPart("Contact_Slave")
    master = sorted(main.GetSubModelPart("Contact_Master").Nodes, key=lambda node: node.X0)
    master_x = np.array([node.X0 for node in master])
    master_u = np.array([node.GetSolutionStepValue(ca.DISPLACEMENT_X) for node in master])
    lengths = common.lumped_line_lengths(slave)
    profile = []
    for node in slave.Nodes:
        traction = np.asarray(node.GetValue(ca.AUGMENTED_TANGENT_CONTACT_PRESSURE))[:2]
        magnitude = float(np.linalg.norm(traction))
        slip = np.asarray(node.GetSolutionStepValue(ca.WEIGHTED_SLIP))[:2]
        angle = 0.0
        if node.Is(ca.ACTIVE) and node.Is(ca.SLIP) and magnitude > 0.0:
            cosine = traction @ slip / (magnitude * max(float(np.linalg.norm(slip)), 1e-300))
            angle = math.degrees(math.acos(max(-1.0, min(1.0, float(cosine)))))
        profile.append(
            SlaveNode(
                x=node.X0,
                p=-node.GetValue(ca.AUGMENTED_NORMAL_CONTACT_PRESSURE),
                q=math.copysign(magnitude, -traction[0]),
                active=node.Is(ca.ACTIVE),
                slip=node.Is(ca.SLIP),
                length=lengths[node.Id],
                slip_angle=angle,
                slide=node.GetSolutionStepValue(ca.DISPLACEMENT_X)
                - float(np.interp(node.X0, master_x, master_u)),
            )
        )
    return sorted(profile, key=lambda node: node.x)


class _RecordingAnalysis(partial_slip.Recording, StructuralMechanicsAnalysis):
    """The analysis, recording the stick zone after every step."""

    slave_profile = staticmethod(slave_profile)

    def step_state(self, fields: dict[str, Any], profile: list[SlaveNode]) -> StepState:
        """The step with the midpoint stick half-width (nan when no node slips)."""
        right, left = stick_half_width(profile) if fields["slipping"] else (math.nan, math.nan)
        return StepState(**fields, stick_half_width=0.5 * (right - left))


def _applied_loads(main: ca.ModelPart) -> tuple[float, float, float]:
    """(P', Q', moment about the contact point) of the top's LINE_LOAD conditions."""
    fx = fy = moment = 0.0
    for condition in main.GetSubModelPart("LineLoad2D_top").Conditions:
        nodes = condition.GetNodes()
        length = math.hypot(nodes[1].X0 - nodes[0].X0, nodes[1].Y0 - nodes[0].Y0)
        force = np.asarray(condition.GetValue(ca.LINE_LOAD)) * length
        xc = 0.5 * (nodes[0].X0 + nodes[1].X0)
        yc = 0.5 * (nodes[0].Y0 + nodes[1].Y0)
        fx += force[0]
        fy += force[1]
        moment += xc * force[1] - yc * force[0]
    return -fy, fx, moment


def evaluate(analysis: _RecordingAnalysis, materials: Path) -> CattaneoMindlinResult:
    """Measure a, p0, c and the forces on a finished analysis."""
    mu = analysis.mu
    main = analysis.model.GetModelPart("Structure")
    load, tangential, moment = _applied_loads(main)
    modulus = common.effective_modulus(materials)
    a_analytic = math.sqrt(4.0 * load * make_mesh.RADIUS / (math.pi * modulus))
    profile = slave_profile(main)
    active = [node for node in profile if node.active]
    x = np.array([node.x for node in active])
    p = np.array([node.p for node in active])
    q = np.array([node.q for node in active])
    length = np.array([node.length for node in active])
    if len(active) >= 2:
        a = common.second_moment_width(x, p * length, 4.0)
        _, p0 = common.fit_elliptic_profile(x, p, "semi-ellipse")
        c_deficit = partial_slip.deficit_width(x, p, np.abs(q), length, mu, 4.0)
    else:
        a = p0 = c_deficit = math.nan
    right, left = stick_half_width(profile)
    slipping = [node for node in active if node.slip]
    sticking = [node for node in active if not node.slip]
    stick_x = [node.x for node in sticking]
    inside = [node for node in active if stick_x and min(stick_x) <= node.x <= max(stick_x)]
    base = main.GetSubModelPart("DISPLACEMENT_fixed_base")
    xs = np.array([node.x for node in profile])
    centre = int(np.argmin(np.abs(xs)))
    return CattaneoMindlinResult(
        **partial_slip.analysis_fields(analysis),
        spacing=float(xs[centre + 1] - xs[centre]),
        load=load,
        tangential_load=tangential,
        applied_moment=moment,
        effective_modulus=modulus,
        a_analytic=a_analytic,
        p0_analytic=2.0 * load / (math.pi * a_analytic),
        a=a,
        p0=p0,
        c_right=right,
        c_left=left,
        c_deficit=c_deficit,
        contact_tangential_force=float(np.sum(q * length)),
        contact_normal_force=float(np.sum(p * length)),
        base_reaction_x=sum(node.GetSolutionStepValue(ca.REACTION_X) for node in base.Nodes),
        coulomb_slip_deviation=max(
            (abs(abs(n.q) / (mu * n.p) - 1.0) for n in slipping), default=0.0
        ),
        stick_max_ratio=max((abs(n.q) / (mu * n.p) for n in sticking), default=0.0),
        max_slip_angle=max((n.slip_angle for n in slipping), default=0.0),
        stick_contiguous=all(not node.slip for node in inside),
        profile=profile,
    )


def run(
    workdir: Path,
    refinement: int | None = None,
    ratio: float = DEFAULT_RATIO,
    quiet: bool = True,
) -> CattaneoMindlinResult:
    """Run the example in ``workdir`` with Q'/(mu P') = ``ratio``.

    The mesh is written and chosen as ``hertz_common.mesh_level`` says (default level
    DEFAULT_REFINEMENT). The loads of the parameters file are replaced by
    ``load_values(ratio, mu)``.
    """

    def loads(_mesh: object, ratio: float, mu: float) -> list[str | float]:
        return load_values(ratio, mu)

    return partial_slip.run(
        workdir, refinement, ratio, quiet, EXAMPLE, _RecordingAnalysis, loads, evaluate
    )


def summary(result: CattaneoMindlinResult) -> str:
    """The text summary of a run."""
    r = result
    level = common.refinement_text(r)
    stick = [n.x for n in r.active if not n.slip]
    slips = sum(n.slip for n in r.active)
    lines = [
        "cattaneo_mindlin_2d: Cattaneo-Mindlin partial slip, cylinder on an elastic foundation,",
        f"  plane strain, ALM frictional mortar, mu = {r.mu:g} (units: mm, N, MPa)",
        f"  R = {make_mesh.RADIUS:g}, P' = {r.load:.6g}, Q' = {r.tangential_load:.6g} "
        f"(Q'/(mu P') = {r.ratio:.4g}), E* = {r.effective_modulus:.6g}",
        f"  mesh: {r.nodes} nodes, {r.elements} quads{level}, contact spacing h = {r.spacing:.4g} "
        f"(a/h = {r.a_analytic / r.spacing:.1f}, c/h = {r.c_analytic / r.spacing:.1f})",
        f"  half-width a (moment): computed {r.a:.6g}, analytic {r.a_analytic:.6g}, "
        f"error {100 * r.a_error:.2f} %",
        f"  peak pressure p0 (fit): computed {r.p0:.6g}, analytic {r.p0_analytic:.6g}, "
        f"error {100 * r.p0_error:.2f} %",
        "  stick half-width c (midpoint between the outermost stick node and the next, a slip "
        "node, on each side):",
        f"    c = {r.c:.6g}, c/a = {r.c / r.a_analytic:.4f}, analytic sqrt(1 - Q'/(mu P')) = "
        f"{r.c_over_a_analytic:.4f}, error {100 * r.c_error:.2f} % (h/(2c) = "
        f"{100 * r.spacing / (2.0 * r.c_analytic):.2f} %)",
        f"    {len(stick)} stick nodes, x in [{min(stick, default=math.nan):.5g}, "
        f"{max(stick, default=math.nan):.5g}], {slips} slip nodes, stick centre "
        f"{r.stick_offset:.3g}, contiguous: {r.stick_contiguous}",
        f"  stick half-width c (second moment of mu p - |q|): {r.c_deficit:.6g}, "
        f"c/a = {r.c_deficit / r.a_analytic:.4f}, error {100 * r.c_deficit_error:.2f} %",
        f"  tangential force: sum(q L) = {r.contact_tangential_force:.7g} vs Q' = "
        f"{r.tangential_load:.7g} ({r.contact_tangential_force / r.tangential_load - 1.0:+.2e}), "
        f"base reaction {r.base_reaction_x:.7g}",
        f"  normal force: sum(p L) = {r.contact_normal_force:.7g} vs P' = {r.load:.7g} "
        f"({r.contact_normal_force / r.load - 1.0:+.2e})",
        r.coulomb_line("q"),
        f"  slip nodes: max angle between t and +WEIGHTED_SLIP {r.max_slip_angle:.2e} deg",
        r.normal_phase_line("q"),
        f"  active slave nodes: {len(r.active)}",
    ]
    return common.hertz_summary(r, lines, (step.line(r.a_analytic) for step in r.steps))


def write_outputs(result: CattaneoMindlinResult, workdir: Path) -> str:
    """Write the summary and the plot into ``workdir``; return the summary."""
    return common.write_outputs(result, workdir, summary, plot, SUMMARY, PLOT)


def plot(result: CattaneoMindlinResult, path: Path) -> None:
    """Normal and shear traction of the slave nodes vs Hertz and Cattaneo-Mindlin."""
    r = result

    def stick_zone(axis: Any) -> None:
        for sign in (-1.0, 1.0):
            axis.axvline(sign * r.c_analytic, color="C0", linestyle="--", linewidth=0.8)
        axis.axvline(r.c_right, color="C2", linestyle=":", linewidth=1.0)
        axis.axvline(
            r.c_left, color="C2", linestyle=":", linewidth=1.0, label="c measured (midpoint)"
        )

    x_max = 1.5 * r.a_analytic
    partial_slip.plot_tractions(
        path,
        r,
        lambda node: node.x,
        np.linspace(-r.a_analytic, r.a_analytic, 801),
        (-x_max, x_max),
        ("Cattaneo–Mindlin q", "q"),
        stick_zone,
        "x, distance from the contact centre (mm)",
        f"Cattaneo–Mindlin, Q'/(μP') = {r.ratio:.3g}: c/a = {r.c / r.a_analytic:.3f} "
        f"(analytic {r.c_over_a_analytic:.3f}, error {100 * r.c_error:.1f} %)",
        loc="upper center",
        ncol=3,
    )


def main(argv: list[str] | None = None) -> int:
    """Run, write the plot and the summary, print the summary; 1 if a step did not converge."""
    return common.example_main(argv, __doc__, run, summary, plot, SUMMARY, PLOT, **OPTIONS)


if __name__ == "__main__":
    sys.exit(main())
