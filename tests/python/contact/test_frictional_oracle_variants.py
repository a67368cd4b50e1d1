"""The reference suite's 2D frictional patch variants, run as Kratos 10.4.4 ran them.

Each folder under data/kratos_oracle/cases holds the parameters (+ materials) of one variant of the
hyper-simple frictional patch (two quadrilaterals, one contact segment; slip, stick ramp, threshold
slip, no friction, perfect stick; ALM and penalty), reconstructed by
scripts/oracle/generate_friction_fixtures.py, with the mesh read from ../shared/kratos_cases. The
fixture next to it records what Kratos computed. We compare the final state of the four contact
nodes (displacements, stick/slip flags) and, for slipping nodes, the dissipation sign.

Where the two disagree the difference is recorded with its cause in DIFFERENT: the reference's
slip traction is frozen along its first direction and converges pointing along the slip (its
k lambda_t . WEIGHTED_SLIP < 0), while ours follows the trial traction and dissipates
(docs/theory/mortar.md section 8).

The suite's static-evolution and dynamic evolution-load variants (catalog rows 57 and 47) come
without meshes; their folders run our own block-on-base model
(cases/frictional_evolution_load_2d.mdpa, scripts/oracle/make_evolution_load_mesh.py), whose
fixtures keep the slave state after every step (``history``). Static: the block is pressed
(t = 1), dragged by its top centre node into partial slip (t = 1.5, 2) and gross slip (t >= 2.15)
under a growing press. Dynamic (Bossak): pressed over two steps, then pushed by a tangential line
load through partial slip (t = 3) into gross slip (Q > mu N from t = 3.57) and released (Q < mu N
from t = 4.23): the block slides on by its momentum until t = 4.7 and sticks again. They are
checked step by step against Kratos until the first slip and, at every step, against Coulomb's law
and the dissipation sign.
"""

from __future__ import annotations

import functools
import importlib.util
import json
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pytest

import contact_app as ca
from contact_app.analysis import StructuralMechanicsAnalysis
from contact_app.analysis.reporting import Reporter
from contact_app.parameters import Parameters

ORACLE_DIR = Path(__file__).parent / "data" / "kratos_oracle"
CASES = sorted(p.name for p in (ORACLE_DIR / "cases").iterdir() if p.is_dir())
SHARED = Path(__file__).resolve().parents[3].parent / "shared" / "kratos_cases"
RELATIVE_TOLERANCE = 1.0e-4

#: Variants we do not match, with the difference measured on 2026-11-25 (strict xfails). The others
#: agree to 2e-7 of the largest displacement (no friction 7.9e-10 / 5.0e-14, perfect stick 7.3e-12,
#: ALM threshold slip 2.1e-7).
B2 = (
    "the reference spreads its penalty friction with D - D_old (B2 in docs/architecture.md), which "
    "vanishes for small sliding; ours with D and M"
)
DIFFERENT: dict[str, str] = {
    "alm_frictional_2d_slip": "3.75e-2 of the largest displacement: the reference's converged slip "
    "traction points along the slip (k lambda_t . WEIGHTED_SLIP < 0 at both slipping nodes), ours "
    "against it",
    "penalty_frictional_2d_slip": f"1.85e-2 of the largest displacement: {B2}",
    "penalty_frictional_2d_stick_ramp": f"1.35 of the largest displacement (the reference's slave "
    f"lags its master by 4e-2 while flagged stick): {B2}",
    "penalty_frictional_2d_threshold_slip": f"8.1e-2 of the largest displacement: {B2}",
    "alm_frictional_2d_static_evolution_load": "7.0e-4 of the largest displacement (up to 2.0e-3 "
    "of a step's largest slave displacement from the first partial-slip step t = 2): the "
    "reference's gross-slip friction depends on its time step. The drag force at t = 2.6 is "
    "0.9993 / 0.872 / 0.425 mu N with the slip-phase steps 0.05 / 0.025 / 0.0125 (nodes flagged "
    "stick while the block slides), ours 1.0000 mu N with displacements changing by 5e-6 and 3e-6 "
    "of the largest",
    "alm_frictional_2d_evolution_load": "1.0 of the largest displacement: the reference's slip "
    "traction turns along the slip from t = 3.90 (one node, all eleven by t = 4.45; "
    "k lambda_t . WEIGHTED_SLIP < 0), its block accelerates while the push falls below mu N, and "
    "its last step does not converge (30 iterations, |p_n| up to 9.7e4 against 2.5e2); ours "
    "decelerates and sticks again at t = 4.75",
}

pytestmark = pytest.mark.skipif(not SHARED.is_dir(), reason="../shared/kratos_cases missing")


def _run(case: str) -> StructuralMechanicsAnalysis:
    folder = ORACLE_DIR / "cases" / case
    parameters = Parameters.from_file(folder / "parameters.json")
    # As the reference runs them: on past a step that does not converge (penalty stick ramp, step
    # 14; the tests check convergence themselves). contact_app's default would stop there.
    analysis = StructuralMechanicsAnalysis(
        ca.Model(),
        parameters,
        base_dir=folder,
        reporter=Reporter(quiet=True),
        stop_on_non_convergence=False,
    )
    analysis.Run()
    return analysis


def _param(case: str) -> object:
    marks = [pytest.mark.xfail(strict=True, reason=DIFFERENT[case])] if case in DIFFERENT else []
    return pytest.param(case, marks=marks, id=case)


@pytest.mark.kratos_reference
@pytest.mark.parametrize("case", [_param(c) for c in CASES])
def test_frictional_variant_matches_the_current_kratos(case: str) -> None:
    fixture = json.loads((ORACLE_DIR / f"{case}.json").read_text())
    analysis = _run(case)
    main = analysis.model.GetModelPart("Structure")
    worst = 0.0
    for key, values in fixture["values"].items():
        node = main.GetNode(int(key.removeprefix("NODE_")))
        for name in ("DISPLACEMENT_X", "DISPLACEMENT_Y"):
            ours, theirs = node.GetSolutionStepValue(ca.get_variable(name)), values[name]
            scale = max(abs(v[name]) for v in fixture["values"].values())
            worst = max(worst, abs(ours - theirs) / scale)
    print(f"\n{case}: worst displacement difference {worst:.2e} of the largest")
    for key, flags in fixture["flags"].items():
        node = main.GetNode(int(key.removeprefix("NODE_")))
        assert node.Is(ca.ACTIVE) == flags["ACTIVE"], key
        assert node.Is(ca.SLIP) == flags["SLIP"], key
    assert worst < RELATIVE_TOLERANCE
    assert all(step.converged for step in analysis.reporter.steps)


@pytest.mark.kratos_reference
@pytest.mark.parametrize("case", CASES)
def test_frictional_variant_slips_dissipatively(case: str) -> None:
    analysis = _run(case)
    for node in analysis.model.GetModelPart("Structure").Nodes:
        if not (node.Is(ca.SLAVE) and node.Is(ca.ACTIVE) and node.Is(ca.SLIP)):
            continue
        traction = np.array(node.GetValue(ca.AUGMENTED_TANGENT_CONTACT_PRESSURE))
        slip = np.array(node.GetSolutionStepValue(ca.WEIGHTED_SLIP))
        if np.linalg.norm(traction) == 0.0:  # frictionless
            continue
        assert traction @ slip >= 0.0, f"node {node.Id}: traction along the slip"


# -- Evolution-load variants, step by step --

EVOLUTION = ("alm_frictional_2d_static_evolution_load", "alm_frictional_2d_evolution_load")
MU = 0.3  # FRICTION_COEFFICIENT of both bodies in their materials.json
#: TIME of the first step with a slipping node in both codes; the steps before it agree (from it
#: on: up to 2.0e-3 of a step's largest slave displacement in the static case, see DIFFERENT).
FIRST_SLIP = {EVOLUTION[0]: 2.0, EVOLUTION[1]: 3.0}
COULOMB_TOLERANCE = 1.0e-6  # relative, on |t_t| = mu |p_n| at the slipping nodes


@dataclass
class EvolutionStep:
    """Our state after one step of an evolution-load case (slave arrays in the fixture's order)."""

    time: float
    converged: bool
    displacement: np.ndarray  # (slave nodes, 2)
    normal_pressure: np.ndarray  # AUGMENTED_NORMAL_CONTACT_PRESSURE
    tangent_pressure: np.ndarray  # (slave nodes, 2) AUGMENTED_TANGENT_CONTACT_PRESSURE
    weighted_slip: np.ndarray  # (slave nodes, 2)
    active: np.ndarray
    slip: np.ndarray
    max_normal_x: float  # over the active slave nodes: how far the interface tilts
    reaction: dict[str, np.ndarray] = field(default_factory=dict)  # summed by constrained part
    load: dict[str, np.ndarray] = field(default_factory=dict)  # LINE_LOAD x current length


class _EvolutionAnalysis(StructuralMechanicsAnalysis):
    """The analysis, keeping the slave nodes, reactions and applied loads after every step."""

    def __init__(self, *args, nodes: list[int], **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.nodes = nodes
        self.steps: list[EvolutionStep] = []

    def FinalizeSolutionStep(self) -> None:  # noqa: N802 - Kratos name
        super().FinalizeSolutionStep()
        main = self.model.GetModelPart("Structure")
        slave = [main.GetNode(i) for i in self.nodes]

        def nodal(variable: ca.Variable, historical: bool) -> np.ndarray:
            if historical:
                return np.array([n.GetSolutionStepValue(variable) for n in slave])
            return np.array([n.GetValue(variable) for n in slave])

        def current(node: ca.Node) -> np.ndarray:
            u = node.GetSolutionStepValue(ca.DISPLACEMENT)
            return np.array([node.X0 + u[0], node.Y0 + u[1]])

        def applied(part: str) -> np.ndarray:
            return sum(
                np.array(c.GetValue(ca.LINE_LOAD))[:2]
                * np.linalg.norm(np.subtract(*(current(n) for n in c.GetNodes())))
                for c in main.GetSubModelPart(part).Conditions
            )

        def reaction(part: str) -> np.ndarray:
            return sum(
                np.array(n.GetSolutionStepValue(ca.REACTION))[:2]
                for n in main.GetSubModelPart(part).Nodes
            )

        active = np.array([n.Is(ca.ACTIVE) for n in slave])
        self.steps.append(
            EvolutionStep(
                time=main.ProcessInfo[ca.TIME],
                converged=self.reporter.steps[-1].converged,
                displacement=nodal(ca.DISPLACEMENT, True)[:, :2],
                normal_pressure=nodal(ca.AUGMENTED_NORMAL_CONTACT_PRESSURE, False),
                tangent_pressure=nodal(ca.AUGMENTED_TANGENT_CONTACT_PRESSURE, False)[:, :2],
                weighted_slip=nodal(ca.WEIGHTED_SLIP, True)[:, :2],
                active=active,
                slip=np.array([n.Is(ca.SLIP) for n in slave]) & active,
                max_normal_x=float(np.max(np.abs(nodal(ca.NORMAL_X, True)[active]))),
                reaction={p: reaction(p) for p in ("DISPLACEMENT_Base", "DISPLACEMENT_Pull")},
                load={p: applied(p) for p in ("Load_Normal", "Load_Tangent")},
            )
        )


def _run_evolution(case: str, folder: Path | None = None) -> list[EvolutionStep]:
    """Our steps of an evolution-load case (``folder``: a modified copy of its case folder)."""
    fixture = json.loads((ORACLE_DIR / f"{case}.json").read_text())
    folder = folder or ORACLE_DIR / "cases" / case
    analysis = _EvolutionAnalysis(
        ca.Model(),
        Parameters.from_file(folder / "parameters.json"),
        base_dir=folder,
        reporter=Reporter(quiet=True),
        nodes=fixture["history"][0]["nodes"],
    )
    analysis.Run()
    return analysis.steps


@functools.cache
def _evolution(case: str) -> tuple[EvolutionStep, ...]:
    return tuple(_run_evolution(case))


@pytest.mark.kratos_reference
@pytest.mark.parametrize("case", EVOLUTION)
def test_evolution_load_matches_kratos_before_the_first_slip(case: str) -> None:
    history = json.loads((ORACLE_DIR / f"{case}.json").read_text())["history"]
    ours = _evolution(case)
    assert [round(s.time, 9) for s in ours] == [round(h["time"], 9) for h in history]
    compared = 0
    for step, theirs in zip(ours, history, strict=True):
        if step.time > FIRST_SLIP[case] - 1.0e-9:
            break
        kratos = np.column_stack([theirs["DISPLACEMENT_X"], theirs["DISPLACEMENT_Y"]])
        worst = np.max(np.abs(step.displacement - kratos)) / np.max(np.abs(kratos))
        print(f"{case} t = {step.time:.3f}: {worst:.2e} of the step's largest slave displacement")
        assert worst < RELATIVE_TOLERANCE, step.time
        assert step.active.tolist() == theirs["ACTIVE"], step.time
        assert step.slip.tolist() == theirs["SLIP"], step.time
        compared += 1
    assert compared >= 2


@pytest.mark.kratos_reference
@pytest.mark.parametrize("case", EVOLUTION)
def test_evolution_load_obeys_coulomb_and_dissipates_at_every_step(case: str) -> None:
    ours = _evolution(case)
    kinds = set()
    for step in ours:
        assert step.converged, step.time
        assert step.active.all(), step.time  # the block stays pressed all along
        ratio = np.linalg.norm(step.tangent_pressure, axis=1) / np.abs(step.normal_pressure)
        assert np.all(ratio <= MU * (1.0 + COULOMB_TOLERANCE)), (step.time, ratio.max())
        slipping = step.slip
        np.testing.assert_allclose(ratio[slipping], MU, rtol=COULOMB_TOLERANCE, err_msg=step.time)
        power = np.einsum("ij,ij->i", step.tangent_pressure, step.weighted_slip)
        assert np.all(power[slipping] >= 0.0), f"t = {step.time}: traction along the slip"
        kinds.add("slip" if slipping.all() else "partial slip" if slipping.any() else "stick")
    assert kinds == {"stick", "partial slip", "slip"}


@pytest.mark.kratos_reference
def test_static_evolution_load_balances_and_slides_at_mu_n() -> None:
    ours = _evolution(EVOLUTION[0])
    for step in ours:
        base, pull = step.reaction["DISPLACEMENT_Base"], step.reaction["DISPLACEMENT_Pull"]
        press = -step.load["Load_Normal"][1]
        assert abs(base[0] + pull[0]) <= 1.0e-9 * press, step.time
        assert abs(base[1] - press) <= 1.0e-9 * press, step.time
        if step.slip.all():
            # Gross slip: the drag force is mu N up to the tilt of the interface (the bound of
            # test_frictional_stick_slip.py), here max|NORMAL_X| <= 2e-3.
            bound = 1.01 * (1.0 + MU**2) / MU * step.max_normal_x
            assert abs(pull[0] / (MU * press) - 1.0) <= bound, step.time
    assert sum(step.slip.all() for step in ours) >= 10


@pytest.mark.kratos_reference
def test_static_evolution_load_does_not_depend_on_the_time_step(tmp_path: Path) -> None:
    case = EVOLUTION[0]
    raw = json.loads((ORACLE_DIR / "cases" / case / "parameters.json").read_text())
    intervals = raw["solver_settings"]["time_stepping"]["time_step_intervals"]
    for interval in ("partial_slip", "slip"):
        intervals[interval]["time_step"] /= 2.0
    raw["solver_settings"]["model_import_settings"]["input_filename"] = str(
        ORACLE_DIR / "cases" / "frictional_evolution_load_2d"
    )
    raw["solver_settings"]["material_import_settings"]["materials_filename"] = str(
        ORACLE_DIR / "cases" / case / "materials.json"
    )
    raw["problem_data"]["end_time"] = 2.599  # the same last TIME, 2.6, in half steps
    (tmp_path / "parameters.json").write_text(json.dumps(raw))
    fine = _run_evolution(case, tmp_path)[-1]
    coarse = _evolution(case)[-1]
    assert fine.time == pytest.approx(coarse.time)
    change = np.max(np.abs(fine.displacement - coarse.displacement))
    assert change <= 1.0e-5 * np.max(np.abs(coarse.displacement))


@pytest.mark.kratos_reference
def test_dynamic_evolution_load_slides_on_by_its_momentum() -> None:
    ours = _evolution(EVOLUTION[1])
    coasting = [
        step.time
        for step in ours
        if step.slip.all() and step.load["Load_Tangent"][0] < MU * -step.load["Load_Normal"][1]
    ]
    # Quasi-statically the block would stick as soon as the push drops below mu N (t = 4.23).
    print(f"gross slip under a push below mu N at t = {coasting}")
    assert len(coasting) >= 5
    assert ours[-1].slip.sum() == 0  # and it sticks again


def test_evolution_load_mesh_is_what_its_script_writes(tmp_path: Path) -> None:
    script = Path(__file__).resolve().parents[3] / "scripts/oracle/make_evolution_load_mesh.py"
    spec = importlib.util.spec_from_file_location("make_evolution_load_mesh", script)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    module.build().write(tmp_path / "mesh.mdpa")
    stored = ORACLE_DIR / "cases" / "frictional_evolution_load_2d.mdpa"
    assert (tmp_path / "mesh.mdpa").read_text() == stored.read_text()


def test_kratos_dynamic_evolution_load_slides_along_its_traction() -> None:
    """The dynamic xfail's reason, measured on the fixture; fails once the reference is fixed."""
    history = json.loads((ORACLE_DIR / f"{EVOLUTION[1]}.json").read_text())["history"]
    along = []
    for step in history:
        traction = np.column_stack(
            [
                step["AUGMENTED_TANGENT_CONTACT_PRESSURE_X"],
                step["AUGMENTED_TANGENT_CONTACT_PRESSURE_Y"],
            ]
        )
        slip = np.column_stack([step["WEIGHTED_SLIP_X"], step["WEIGHTED_SLIP_Y"]])
        power = np.einsum("ij,ij->i", traction, slip)
        along.append(int(np.sum((power < 0.0) & np.array(step["SLIP"]))))
    assert max(along) >= 10
    assert history[-1]["iterations"] == 30
