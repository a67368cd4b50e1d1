"""Run the 3D Cattaneo-Mindlin example and compare the contact tractions with the analytic ones.

Mindlin's partial slip: the hertz_3d ball is pressed by P (steps 1-4, t in [0, 1]) and then
pulled along x by Q < mu P with P kept (steps 5-8, t in [1, 2]). Identical materials, so the
normal and the tangential problems uncouple (Johnson, Contact Mechanics, 7.2):

* normal: a = (3 P R / (4 E*))^(1/3), p(r) = p0 sqrt(1 - r^2/a^2), p0 = 3 P / (2 pi a^2);
* tangential, along x: a central stick disc r < c, c/a = (1 - Q/(mu P))^(1/3), where
  q(r) = mu p0 sqrt(1 - r^2/a^2) - mu p0 (c/a) sqrt(1 - r^2/c^2), and a slip annulus c < r < a
  where q = mu p.

The model is the half y >= 0 (u_y = 0 on y = 0; the x = 0 plane is not a symmetry plane under a
load along x). The loads are SURFACE_LOAD components on the ball's flat top z = R, written by
``load_values`` from Q/(mu P) (``--ratio``, default 0.5), mu (the contact process's
``friction_coefficients``) and the mesh: a uniform -PRESSURE in z; a uniform ratio mu PRESSURE in
x; and +-s in z on the halves x > 0 and x < 0 of the top, with s chosen so that this couple
cancels the moment Q R of the tangential load about the contact point (exactly, from the top's
quads). A contact of radius a = 0.06 R cannot carry Q R: without the couple the ball tips. No
displacement constraint acts on the ball besides the symmetry plane: its rotation about y is
held by the stick zone, about z and x by the symmetry plane. Geometrically linear (move_mesh_flag
false), as the theory.

Measured on the active slave (sphere) nodes: p = -AUGMENTED_NORMAL_CONTACT_PRESSURE, the shear
traction t = AUGMENTED_TANGENT_CONTACT_PRESSURE (the block's traction on the ball, against Q;
q = -t_x), STICK = ACTIVE and not SLIP, nodal areas A = integral of N_i over the slave faces.

* a from the second moment of the nodal normal forces, p0 = 3P/(2 pi a^2) (as hertz_3d);
* c from the stick set: c_in = largest radius of a stick node, c_out = smallest radius of a slip
  node; if every stick node lies inside every slip node (reported), c is in [c_in, c_out] and the
  estimate is the midpoint, within (c_out - c_in)/2;
* c a second way, between the nodes: the deficit mu p - |t| is mu p0 (c/a) sqrt(1 - r^2/c^2) in
  the stick disc and 0 in the slip annulus, a half-ellipsoid of radius c, so c^2 = (5/2)
  sum(r^2 d A) / sum(d A);
* the friction force 2 sum(q A) against Q (the factor 2: half model), and the base reaction.

Writes ``cattaneo_mindlin_3d_traction.png``, ``cattaneo_mindlin_3d_summary.txt`` and
``vtk_output/``; exit code 0 when every step converged, 1 otherwise.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import meshio
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
DEFAULT_RATIO = 0.5  # Q/(mu P): c/a = 0.5^(1/3) = 0.794
PRESSURE = 10.0  # MPa on the flat top, as hertz_3d: P = 10 MPa x (meshed disc area) = 3129 N
OPTIONS = {"refinement_type": float, "ratio": ("Q/(mu P)", DEFAULT_RATIO)}  # of the command line


def c_over_a(ratio: float) -> float:
    """Mindlin's stick disc: c/a = (1 - Q/(mu P))^(1/3)."""
    return (1.0 - ratio) ** (1.0 / 3.0)


def top_integrals(points: np.ndarray, quads: np.ndarray) -> tuple[float, float]:
    """(area, integral of |x|) over the top's quads, as the load conditions integrate them."""
    area = moment = 0.0
    for quad in quads:
        corners = points[quad]
        weights = common.quad_nodal_areas(corners)
        area += weights.sum()
        moment += abs(weights @ corners[:, 0])
    return area, moment


def load_values(ratio: float, mu: float, area: float, moment: float) -> list[str | float]:
    """The SURFACE_LOAD value [x, y, z] of the top conditions for Q/(mu P) = ``ratio``.

    ``area`` and ``moment`` are the top's area and integral of |x|: the couple s sign(x) in z
    has the moment s * moment about y, which must cancel Q R = ratio mu PRESSURE area R.
    """
    if not 0.0 < ratio < 1.0:
        raise ValueError(f"Q/(mu P) must be in (0, 1) for partial slip, got {ratio}")
    shear = ratio * mu * PRESSURE
    couple = shear * area * make_mesh.RADIUS / moment
    return [
        f"{shear:.15g}*{partial_slip.RAMP}",
        0.0,
        f"-{PRESSURE:.15g}*min(t, 1.0) + {couple:.15g}*x/abs(x)*{partial_slip.RAMP}",
    ]


def _angle(a: np.ndarray, b: np.ndarray) -> float:
    norm = float(np.linalg.norm(a) * np.linalg.norm(b))
    if norm == 0.0:
        return 180.0
    return math.degrees(math.acos(max(-1.0, min(1.0, float(a @ b) / norm))))


@dataclass
class SlaveNode:
    """The contact state of one sphere surface node."""

    x: float
    y: float
    p: float  # normal pressure, > 0 in compression
    traction: np.ndarray  # AUGMENTED_TANGENT_CONTACT_PRESSURE (the block's traction on the ball)
    slip_vector: np.ndarray  # WEIGHTED_SLIP
    active: bool
    slip: bool
    area: float  # lumped nodal area (reference configuration)

    @property
    def r(self) -> float:
        """Distance from the contact axis."""
        return math.hypot(self.x, self.y)

    @property
    def q(self) -> float:
        """Shear traction along the load direction, against Q (> 0): -t_x."""
        return -float(self.traction[0])

    @property
    def shear(self) -> float:
        """|t|."""
        return float(np.linalg.norm(self.traction))

    @property
    def stick(self) -> bool:
        """ACTIVE and not SLIP."""
        return self.active and not self.slip

    @property
    def slip_angle(self) -> float:
        """Degrees between t and +WEIGHTED_SLIP."""
        return _angle(self.traction, self.slip_vector)

    @property
    def power(self) -> float:
        """The power t . WEIGHTED_SLIP: > 0 when the friction dissipates."""
        return float(self.traction @ self.slip_vector)


@dataclass
class StickZone:
    """The stick set's radial extent."""

    inner: float  # largest radius of a stick node
    outer: float  # smallest radius of a slip node
    separated: bool  # inner < outer: the stick set is {r < c} for any c in between

    @property
    def c(self) -> float:
        """Midpoint estimate."""
        return 0.5 * (self.inner + self.outer)

    @property
    def bound(self) -> float:
        """Half the gap: |c - c_exact| <= bound when separated."""
        return 0.5 * abs(self.outer - self.inner)


def stick_zone(nodes: list[SlaveNode]) -> StickZone:
    """The radii of the outermost stick node and the innermost slip node (nan if either is none)."""
    stick = [node.r for node in nodes if node.stick]
    slip = [node.r for node in nodes if node.active and node.slip]
    if not stick or not slip:
        return StickZone(math.nan, math.nan, False)
    inner, outer = max(stick), min(slip)
    return StickZone(inner, outer, inner < outer)


@dataclass(kw_only=True)
class StepState(partial_slip.Step):
    """Newton iterations, the stick zone and the slip law after one step (ratio: Q/(mu P))."""

    zone: StickZone
    max_slip_angle: float  # over the slip nodes
    min_power: float  # min t . WEIGHTED_SLIP / (|t| |s|) over the slip nodes
    coulomb_deviation: float  # max | |t| / (mu p) - 1 | over the slip nodes

    def stick_text(self, a: float) -> str:
        """The theory's c/a, the stick set's radii and the slip nodes' worst angle."""
        text = f", c/a analytic {c_over_a(self.ratio):.3f}"
        if not math.isnan(self.zone.c):
            text += (
                f", stick set in r <= {self.zone.inner / a:.3f} a, slip from "
                f"{self.zone.outer / a:.3f} a"
            )
        if self.slipping:
            text += f", max angle(t, slip) {self.max_slip_angle:.1e} deg"
        return text


@dataclass(kw_only=True)
class CattaneoMindlin3DResult(partial_slip.CattaneoMindlinRun):
    """What one run measured, next to the analytic values (load: P on the whole ball)."""

    applied_moment: np.ndarray  # of the top loads about the contact point, half model
    zone: StickZone
    friction_force: np.ndarray  # 2 sum(-t A) over the active nodes (x, y, z); y: half model
    normal_force: float  # 2 sum(p A)
    min_power: float

    @property
    def c_over_a_analytic(self) -> float:
        """(1 - Q/(mu P))^(1/3)."""
        return c_over_a(self.ratio)

    @property
    def c(self) -> float:
        """Stick radius from the stick set (midpoint)."""
        return self.zone.c

    @property
    def contact_friction(self) -> float:
        """2 sum(q A) = 2 sum(-t_x A)."""
        return float(self.friction_force[0])


def slave_profile(main: ca.ModelPart) -> list[SlaveNode]:
    """The contact state of every slave node, sorted by radius."""
    slave = main.GetSubModelPart("Contact_Slave")
    areas: dict[int, float] = {}
    for condition in slave.Conditions:
        nodes = condition.GetNodes()
        corners = np.array([[node.X0, node.Y0, node.Z0] for node in nodes])
        for node, area in zip(nodes, common.quad_nodal_areas(corners), strict=True):
            areas[node.Id] = areas.get(node.Id, 0.0) + area
    profile = [
        SlaveNode(
            x=node.X0,
            y=node.Y0,
            p=-node.GetValue(ca.AUGMENTED_NORMAL_CONTACT_PRESSURE),
            traction=np.array(node.GetValue(ca.AUGMENTED_TANGENT_CONTACT_PRESSURE), dtype=float),
            slip_vector=np.array(node.GetSolutionStepValue(ca.WEIGHTED_SLIP), dtype=float),
            active=node.Is(ca.ACTIVE),
            slip=node.Is(ca.SLIP),
            area=areas.get(node.Id, 0.0),
        )
        for node in slave.Nodes
    ]
    return sorted(profile, key=lambda node: node.r)


def _slip_checks(nodes: list[SlaveNode], mu: float) -> tuple[float, float, float]:
    """(max traction-slip angle, min cosine, max | |t|/(mu p) - 1 |) over the slip nodes."""
    slipping = [node for node in nodes if node.active and node.slip]
    angle = max((node.slip_angle for node in slipping), default=0.0)
    cosine = min(
        (
            node.power / max(node.shear * float(np.linalg.norm(node.slip_vector)), 1e-300)
            for node in slipping
        ),
        default=1.0,
    )
    coulomb = max((abs(node.shear / (mu * node.p) - 1.0) for node in slipping), default=0.0)
    return angle, cosine, coulomb


class _RecordingAnalysis(partial_slip.Recording, StructuralMechanicsAnalysis):
    """The analysis, recording the stick zone and the slip law after every step."""

    slave_profile = staticmethod(slave_profile)

    def step_state(self, fields: dict[str, Any], profile: list[SlaveNode]) -> StepState:
        """The step with its stick zone and the slip law of its slip nodes."""
        angle, cosine, coulomb = _slip_checks(profile, self.mu)
        return StepState(
            **fields,
            zone=stick_zone(profile),
            max_slip_angle=angle,
            min_power=cosine,
            coulomb_deviation=coulomb,
        )


def _applied_loads(main: ca.ModelPart) -> tuple[np.ndarray, np.ndarray]:
    """(force, moment about the origin) of the top's SURFACE_LOAD conditions, half model."""
    force = np.zeros(3)
    moment = np.zeros(3)
    for condition in main.GetSubModelPart("SurfaceLoad3D_top").Conditions:
        corners = np.array([[node.X0, node.Y0, node.Z0] for node in condition.GetNodes()])
        load = np.asarray(condition.GetValue(ca.SURFACE_LOAD), dtype=float)
        for position, weight in zip(corners, common.quad_nodal_areas(corners), strict=True):
            force += weight * load
            moment += np.cross(position, weight * load)
    return force, moment


def evaluate(analysis: _RecordingAnalysis, materials: Path) -> CattaneoMindlin3DResult:
    """Measure a, c, the slip law and the forces on a finished analysis."""
    mu = analysis.mu
    main = analysis.model.GetModelPart("Structure")
    force, moment = _applied_loads(main)
    load, tangential = -2.0 * force[2], 2.0 * force[0]
    modulus = common.effective_modulus(materials)
    a_analytic = (3.0 * load * make_mesh.RADIUS / (4.0 * modulus)) ** (1.0 / 3.0)
    profile = slave_profile(main)
    active = [node for node in profile if node.active]
    r = np.array([node.r for node in active])
    p = np.array([node.p for node in active])
    area = np.array([node.area for node in active])
    shear = np.array([node.shear for node in active])
    a = common.second_moment_width(r, p * area, 2.5)
    c_deficit = partial_slip.deficit_width(r, p, shear, area, mu, 2.5)
    traction = np.array([node.traction for node in active])
    angle, cosine, coulomb = _slip_checks(profile, mu)
    sticking = [node for node in active if not node.slip]
    base = main.GetSubModelPart("DISPLACEMENT_fixed_base")
    radii = sorted({round(node.r, 12) for node in profile})
    return CattaneoMindlin3DResult(
        **partial_slip.analysis_fields(analysis),
        spacing=radii[1],
        load=load,
        tangential_load=tangential,
        applied_moment=moment,
        effective_modulus=modulus,
        a_analytic=a_analytic,
        p0_analytic=3.0 * load / (2.0 * math.pi * a_analytic**2),
        a=a,
        zone=stick_zone(profile),
        c_deficit=c_deficit,
        friction_force=-2.0 * (traction * area[:, None]).sum(axis=0),
        normal_force=2.0 * float(np.sum(p * area)),
        base_reaction_x=2.0 * sum(node.GetSolutionStepValue(ca.REACTION_X) for node in base.Nodes),
        coulomb_slip_deviation=coulomb,
        stick_max_ratio=max((node.shear / (mu * node.p) for node in sticking), default=0.0),
        max_slip_angle=angle,
        min_power=cosine,
        profile=profile,
    )


def _top_loads(mesh: Callable[[], meshio.Mesh], ratio: float, mu: float) -> list[str | float]:
    """``load_values`` for the top of the run's mesh, ``mesh()``."""
    meshed = mesh()
    top = np.vstack([block.data for block in meshed.cells if block.type == "quad"])
    return load_values(ratio, mu, *top_integrals(meshed.points, top))


def run(
    workdir: Path,
    refinement: float | None = None,
    ratio: float = DEFAULT_RATIO,
    quiet: bool = True,
) -> CattaneoMindlin3DResult:
    """Run the example in ``workdir`` with Q/(mu P) = ``ratio``.

    The mesh is written and chosen as ``hertz_common.mesh_level`` says (default level
    DEFAULT_REFINEMENT). The loads of the parameters file are replaced by ``load_values`` for
    this ratio and mesh.
    """
    return partial_slip.run(
        workdir, refinement, ratio, quiet, EXAMPLE, _RecordingAnalysis, _top_loads, evaluate
    )


def summary(result: CattaneoMindlin3DResult) -> str:
    """The text summary of a run."""
    r = result
    level = "" if r.refinement is None else f", refinement {r.refinement:g}"
    slips = sum(n.slip for n in r.active)
    p0 = 3.0 * r.load / (2.0 * math.pi * r.a**2)
    lines = [
        "cattaneo_mindlin_3d: Mindlin partial slip, sphere on an elastic block, half model y >= 0,",
        f"  ALM frictional mortar, mu = {r.mu:g} (units: mm, N, MPa)",
        f"  R = {make_mesh.RADIUS:g}, P = {r.load:.6g}, Q = {r.tangential_load:.6g} "
        f"(Q/(mu P) = {r.ratio:.4g}), E* = {r.effective_modulus:.6g}; moment of the top loads "
        f"about the contact point (half model) [{', '.join(f'{m:.2g}' for m in r.applied_moment)}]",
        f"  mesh: {r.nodes} nodes, {r.elements} hexahedra{level}, slave spacing at the pole "
        f"h = {r.spacing:.4g} (a/h = {r.a_analytic / r.spacing:.1f}, "
        f"c/h = {r.c_analytic / r.spacing:.1f})",
        f"  contact radius a (moment): computed {r.a:.6g}, analytic {r.a_analytic:.6g}, "
        f"error {100 * r.a_error:.2f} %",
        f"  peak pressure p0 = 3P/(2 pi a^2): computed {p0:.6g}, analytic {r.p0_analytic:.6g}, "
        f"error {100 * abs(p0 / r.p0_analytic - 1.0):.2f} %",
        "  stick radius c from the stick set (midpoint of the outermost stick node's radius and "
        "the innermost slip node's):",
        f"    stick nodes r <= {r.zone.inner:.5g}, slip nodes r >= {r.zone.outer:.5g} "
        f"(separated: {r.zone.separated}), c = {r.zone.c:.5g} +- {r.zone.bound:.3g}",
        f"    c/a = {r.zone.c / r.a_analytic:.4f}, analytic (1 - Q/(mu P))^(1/3) = "
        f"{r.c_over_a_analytic:.4f}, error {100 * r.c_error:.2f} % (half gap "
        f"{100 * r.zone.bound / r.c_analytic:.2f} % of c)",
        f"  stick radius c (second moment of mu p - |t|): {r.c_deficit:.5g}, "
        f"c/a = {r.c_deficit / r.a_analytic:.4f}, error {100 * r.c_deficit_error:.2f} %",
        f"  friction force 2 sum(-t A) = [{', '.join(f'{f:.6g}' for f in r.friction_force)}] "
        f"vs Q = {r.tangential_load:.6g} along x "
        f"({r.friction_force[0] / r.tangential_load - 1:+.2e}), "
        f"base reaction 2 R_x = {r.base_reaction_x:.6g}",
        f"  normal force 2 sum(p A) = {r.normal_force:.6g} vs P = {r.load:.6g} "
        f"({r.normal_force / r.load - 1.0:+.2e}; reference-configuration areas)",
        r.coulomb_line("t"),
        f"  slip nodes: max angle between t and WEIGHTED_SLIP {r.max_slip_angle:.2e} deg, "
        f"min cos {r.min_power:.9f} (dissipative: > 0)",
        r.normal_phase_line("t"),
        f"  active slave nodes: {len(r.active)}, of which {slips} slip",
    ]
    return common.hertz_summary(r, lines, (step.line(r.a_analytic) for step in r.steps))


def plot(result: CattaneoMindlin3DResult, path: Path) -> None:
    """Normal and shear traction of the slave nodes against radius, with Hertz and Mindlin."""
    r = result

    def stick_zone(axis: Any) -> None:
        axis.axvline(r.c_analytic, color="C0", linestyle="--", linewidth=0.8, label="c analytic")
        axis.axvspan(r.zone.inner, r.zone.outer, color="C2", alpha=0.15, label="c measured (range)")

    partial_slip.plot_tractions(
        path,
        r,
        lambda node: node.r,
        np.linspace(0.0, r.a_analytic, 400),
        (0.0, 1.6 * r.a_analytic),
        ("Mindlin q", "q = −t_x"),
        stick_zone,
        "r, distance from the contact axis (mm)",
        f"Mindlin 3D, Q/(μP) = {r.ratio:.3g}: c/a = {r.zone.c / r.a_analytic:.3f} "
        f"(analytic {r.c_over_a_analytic:.3f}, error {100 * r.c_error:.1f} %)",
        loc="upper right",
        ncol=2,
    )


def write_outputs(result: CattaneoMindlin3DResult, workdir: Path) -> str:
    """Write the summary and the plot into ``workdir``; return the summary."""
    return common.write_outputs(result, workdir, summary, plot, SUMMARY, PLOT)


def main(argv: list[str] | None = None) -> int:
    """Run, write the plot and the summary, print the summary; 1 if a step did not converge."""
    return common.example_main(argv, __doc__, run, summary, plot, SUMMARY, PLOT, **OPTIONS)


if __name__ == "__main__":
    sys.exit(main())
