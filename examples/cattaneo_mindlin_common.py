"""What the Cattaneo-Mindlin runners share: the run, its steps, the result's frame, the plot.

The inputs with the friction coefficient, the timed analysis recording a ``Step`` after every
step (``Recording``), the stick zone from the deficit mu p - |t|, the result's common fields
(``CattaneoMindlinRun``) and summary lines, and the traction plot. Each runner keeps its geometry
(2D cylinder or 3D sphere), its loads, its analytic law of c/a, its own measures and its summary
text. What both example families share (meshing, width estimates, E*, the command line) is in
``hertz_common``.

The runs press the body with the normal load P (t in [0, 1]), then pull it with Q < mu P along x
(t in [1, 2]); the theory (Johnson, Contact Mechanics, 7.1-7.2) has a stick zone |x| < c (2D) or
r < c (3D) and q = mu p outside it.
"""

from __future__ import annotations

import json
import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, NamedTuple

import hertz_common as common
import meshio
import numpy as np


def frictional_inputs(workdir: Path, example_dir: Path) -> tuple[dict, Path, Path, float]:
    """(parameters tree, its file, materials file, mu) of an example run in ``workdir``.

    The inputs are the working folder's, else the example's own (``example_inputs``); the tree
    names the materials file by its absolute path.
    """
    parameters_path, materials = common.example_inputs(workdir, example_dir)
    parameters = json.loads(parameters_path.read_text(encoding="utf-8"))
    parameters["solver_settings"]["material_import_settings"]["materials_filename"] = str(materials)
    return parameters, parameters_path, materials, common.friction_coefficient(parameters)


def timed_analysis(
    workdir: Path,
    analysis_class: Callable[..., Any],
    parameters: dict,
    parameters_path: Path,
    quiet: bool,
    **options: Any,
) -> tuple[Any, float]:
    """(analysis, wall time) of ``analysis_class`` run on ``parameters`` in ``workdir``.

    ``options`` go to the class (with the model, the parameters, their folder and the reporter).
    """
    import contact_app as ca
    from contact_app.analysis.reporting import Reporter

    with common.working_directory(workdir):
        start = time.perf_counter()
        analysis = analysis_class(
            ca.Model(),
            parameters,
            base_dir=parameters_path.parent,
            reporter=Reporter(quiet=quiet),
            # The runner reports every step, NOT CONVERGED ones too (exit 1), so it goes on
            # from them (the default stops at the first: docs/running.md "Non-convergence").
            stop_on_non_convergence=False,
            **options,
        )
        analysis.Run()
        elapsed = time.perf_counter() - start
    return analysis, elapsed


#: The tangential load's share in a Cattaneo-Mindlin run (a load expression of t): none while
#: the normal load is applied (t <= 1), then all of it at t = 2.
RAMP = "min(max(t - 1.0, 0.0), 1.0)"


def tangential_share(t: float) -> float:
    """``RAMP`` at the time ``t``."""
    return min(max(t - 1.0, 0.0), 1.0)


@dataclass(kw_only=True)
class Step:
    """Newton iterations and the contact sets after one step of a Cattaneo-Mindlin run.

    Each runner's step adds its measure of the stick zone and defines ``stick_text``.
    """

    time: float
    iterations: int
    converged: bool
    ratio: float  # Q/(mu P) applied in the step
    active: int
    slipping: int
    max_shear: float  # max |t| over the active nodes

    @property
    def tangential(self) -> bool:
        """A step of the tangential load (t > 1)."""
        return self.time > 1.0 + 1e-9

    def stick_text(self, a: float) -> str:
        """The stick zone in the line of a tangential step (``a``: the analytic a)."""
        raise NotImplementedError

    def line(self, a: float) -> str:
        """The step's summary line: iterations, active nodes; slip nodes, ``stick_text(a)``."""
        text = f"    t = {self.time:g}: {self.iterations} iterations, {self.active} active"
        if self.tangential:
            text += f", {self.slipping} slip{self.stick_text(a)}"
        return text + ("" if self.converged else ", NOT CONVERGED")


class Recording:
    """Records a ``Step`` after every step of the analysis it is mixed into.

    Listed before the analysis class in the bases. The runner's class defines
    ``slave_profile(main)`` (the slave nodes, with ``active``, ``slip`` and ``shear`` = |t|) and
    ``step_state(fields, profile)`` (its step from the common ``fields`` and the profile).
    """

    def __init__(self, *args: Any, full_ratio: float, mu: float, **kwargs: Any) -> None:
        """The analysis's arguments, the final Q/(mu P) and mu."""
        super().__init__(*args, **kwargs)
        self.full_ratio = full_ratio
        self.mu = mu
        self.states: list[Any] = []

    def FinalizeSolutionStep(self) -> None:  # noqa: N802 - Kratos name
        """The analysis's, then the record of the step."""
        super().FinalizeSolutionStep()
        record = self.reporter.steps[-1]
        profile = self.slave_profile(self.model.GetModelPart("Structure"))
        fields = {
            "time": record.time,
            "iterations": record.iterations,
            "converged": record.converged,
            "ratio": self.full_ratio * tangential_share(record.time),
            "active": sum(node.active for node in profile),
            "slipping": sum(node.active and node.slip for node in profile),
            "max_shear": max((node.shear for node in profile if node.active), default=0.0),
        }
        self.states.append(self.step_state(fields, profile))


def deficit_width(
    c: np.ndarray, p: np.ndarray, shear: np.ndarray, weight: np.ndarray, mu: float, ratio: float
) -> float:
    """The stick zone's width from the deficit mu p - |t| (nan where there is none).

    The deficit is mu p0 (c/a) sqrt(1 - x^2/c^2) in the stick zone, 0 in the slip zone: an
    elliptic profile of width c, whose ``second_moment_width`` (nodal forces: deficit times
    ``weight``, the nodal length or area) does not depend on where c falls between two nodes.
    """
    deficit = np.clip(mu * p - shear, 0.0, None) * weight
    return common.second_moment_width(c, deficit, ratio) if deficit.sum() > 0.0 else math.nan


@dataclass(kw_only=True)
class CattaneoMindlinRun:
    """What a Cattaneo-Mindlin run measured in both dimensions; each runner adds its own.

    A runner's result defines ``c_over_a_analytic`` (its law of c/a in Q/(mu P)) and ``c`` (its
    estimate of the stick zone from the stick set).
    """

    refinement: float | None = None  # None: an existing mesh of unknown level was reused
    spacing: float  # slave node spacing at the contact centre
    nodes: int
    elements: int
    mu: float
    load: float  # the normal load on the whole body: P' (2D), P (3D)
    tangential_load: float  # Q' (2D), Q (3D)
    effective_modulus: float
    a_analytic: float
    p0_analytic: float
    a: float  # moment estimate
    c_deficit: float  # second moment of the deficit mu p - |q|
    base_reaction_x: float
    coulomb_slip_deviation: float  # max | |q| / (mu p) - 1 | over the slip nodes
    stick_max_ratio: float  # max |q| / (mu p) over the stick nodes
    max_slip_angle: float  # max angle between t and +WEIGHTED_SLIP over the slip nodes
    steps: list[Any]
    wall_time: float = 0.0
    profile: list[Any] = field(default_factory=list)

    @property
    def ratio(self) -> float:
        """Q/(mu P) applied."""
        return self.tangential_load / (self.mu * self.load)

    @property
    def c_over_a_analytic(self) -> float:
        """Analytic c/a (defined by each runner's result)."""
        raise NotImplementedError

    @property
    def c(self) -> float:
        """Stick half-width or radius from the stick set (defined by each runner's result)."""
        raise NotImplementedError

    @property
    def contact_friction(self) -> float:
        """The contact's friction force along Q (defined by each runner's result)."""
        raise NotImplementedError

    @property
    def tangential_force_error(self) -> float:
        """Relative difference between the contact's friction force and Q."""
        return common.relative_error(self.contact_friction, self.tangential_load)

    @property
    def c_analytic(self) -> float:
        """Analytic stick half-width (2D) or radius (3D)."""
        return self.c_over_a_analytic * self.a_analytic

    @property
    def c_error(self) -> float:
        """Relative error of c (and of c/a: the same a_analytic divides both)."""
        return common.relative_error(self.c, self.c_analytic)

    @property
    def c_deficit_error(self) -> float:
        """Relative error of the deficit estimate of c."""
        return common.relative_error(self.c_deficit, self.c_analytic)

    @property
    def a_error(self) -> float:
        """Relative error of the contact half-width or radius (moment estimate)."""
        return common.relative_error(self.a, self.a_analytic)

    @property
    def normal_phase_shear(self) -> float:
        """Max shear traction after the last normal step (t = 1), where the theory has none."""
        pressed = [step for step in self.steps if not step.tangential]
        return pressed[-1].max_shear if pressed else math.nan

    @property
    def iterations(self) -> list[int]:
        """Newton iterations per step."""
        return [step.iterations for step in self.steps]

    @property
    def converged(self) -> bool:
        """Every step converged."""
        return bool(self.steps) and all(step.converged for step in self.steps)

    @property
    def active(self) -> list[Any]:
        """The ACTIVE slave nodes."""
        return [node for node in self.profile if node.active]

    def coulomb_line(self, t: str) -> str:
        """The summary's line on the Coulomb law; ``t`` names the shear traction (q or t)."""
        return (
            f"  Coulomb: slip nodes max | |{t}|/(mu p) - 1 | = {self.coulomb_slip_deviation:.2e}, "
            f"stick nodes max |{t}|/(mu p) = {self.stick_max_ratio:.4f}"
        )

    def normal_phase_line(self, t: str) -> str:
        """The summary's line on ``normal_phase_shear``; ``t`` names the shear traction."""
        share = 100 * self.normal_phase_shear / (self.mu * self.p0_analytic)
        return (
            f"  shear left by the normal steps (t = 1; none in the theory): max |{t}| = "
            f"{self.normal_phase_shear:.4g} = {share:.1f} % of mu p0"
        )

    def analytic_traction(self, c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(p, q) of Hertz and Cattaneo-Mindlin at ``c`` (x in 2D, the radius r in 3D)."""
        a, stick_width, p0 = self.a_analytic, self.c_analytic, self.p0_analytic
        p = common.elliptic_profile(p0, a, c)
        stick = common.elliptic_profile(self.mu * p0 * (stick_width / a), stick_width, c)
        return p, self.mu * p - stick


def analysis_fields(analysis: Any) -> dict[str, Any]:
    """The ``CattaneoMindlinRun`` fields a finished ``Recording`` analysis gives.

    The mesh's nodes and elements, mu and the recorded steps.
    """
    main = analysis.model.GetModelPart("Structure")
    return {
        "nodes": main.NumberOfNodes(),
        "elements": main.NumberOfElements(),
        "mu": analysis.mu,
        "steps": analysis.states,
    }


class MeshedExample(NamedTuple):
    """An example's folder, the name of its mesh, the mesh's default level and writer."""

    folder: Path
    mesh: str
    default_refinement: float
    write_mesh: Callable[[Path, Any], object]


def run(
    workdir: Path,
    refinement: float | None,
    ratio: float,
    quiet: bool,
    example: MeshedExample,
    analysis_class: Callable[..., Any],
    load_values: Callable[[Callable[[], meshio.Mesh], float, float], list[Any]],
    evaluate: Callable[[Any, Path], Any],
) -> Any:
    """Run a Cattaneo-Mindlin example in ``workdir`` with Q/(mu P) = ``ratio``; evaluate it.

    The mesh of ``example`` is written there as ``mesh_level`` says. The loads of the parameters
    file become ``load_values(mesh, ratio, mu)``, ``mesh()`` giving the mesh (the one written,
    else read: meshio prints a blank line); ``analysis_class`` (a
    ``Recording``) runs them and ``evaluate(analysis, materials)`` makes the result,
    which gets its level and wall time.
    """
    workdir = Path(workdir).resolve()
    path = workdir / example.mesh
    refinement, written = common.mesh_level(
        path, refinement, example.default_refinement, example.write_mesh
    )

    def mesh() -> meshio.Mesh:
        return meshio.read(str(path)) if written is None else written

    parameters, parameters_path, materials, mu = frictional_inputs(workdir, example.folder)
    load_process = parameters["processes"]["loads_process_list"][0]["Parameters"]
    load_process["value"] = load_values(mesh, ratio, mu)
    analysis, elapsed = timed_analysis(
        workdir, analysis_class, parameters, parameters_path, quiet, full_ratio=ratio, mu=mu
    )
    result = evaluate(analysis, materials)
    result.refinement = refinement
    result.wall_time = elapsed
    return result


def plot_tractions(
    path: Path,
    result: CattaneoMindlinRun,
    position: Callable[[Any], float],
    curve: np.ndarray,
    xlim: tuple[float, float],
    names: tuple[str, str],
    draw_stick_zone: Callable[[Any], None],
    xlabel: str,
    title: str,
    **legend: Any,
) -> None:
    """Normal and shear traction of the slave nodes against Hertz and Cattaneo-Mindlin.

    The analytic p, mu p and q over ``curve``, then the nodes within ``xlim`` at their
    ``position`` (x or r): p of the active ones, q of the stick and the slip ones, the inactive
    ones; then ``draw_stick_zone(axis)``. ``names`` = (the analytic q's name, the nodes' q's);
    ``legend`` goes to the legend.
    """
    analytic, measured = names
    p, q = result.analytic_traction(curve)
    fig, axis = common.new_figure((8.0, 5.0))
    axis.plot(curve, p, "k-", label="Hertz p (analytic)")
    axis.plot(curve, result.mu * p, "k:", label="μ p (analytic)")
    axis.plot(curve, q, "C0-", label=f"{analytic} (analytic)")
    low, high = xlim
    shown = [n for n in result.profile if low <= position(n) <= high]
    active = [n for n in shown if n.active]
    axis.plot(
        [position(n) for n in active], [n.p for n in active], "ko", mfc="none", label="p, active"
    )
    stick = [n for n in active if not n.slip]
    slip = [n for n in active if n.slip]
    axis.plot(
        [position(n) for n in stick], [n.q for n in stick], "C2s", label=f"{measured}, stick nodes"
    )
    axis.plot(
        [position(n) for n in slip], [n.q for n in slip], "C3^", label=f"{measured}, slip nodes"
    )
    inactive = [n for n in shown if not n.active]
    axis.plot(
        [position(n) for n in inactive], [0.0] * len(inactive), "x", color="grey", label="inactive"
    )
    draw_stick_zone(axis)
    labels = (xlabel, "traction (MPa)", title)
    common.save_figure(
        fig, path, labels, xlim, (0.0, 1.3 * result.p0_analytic), fontsize=8, **legend
    )
