"""Ours against the reference on the models of its example collection (issue 17 item 5).

The models are read from ``../shared/kratos_examples`` at run time. The reference numbers are
``data/kratos_examples/<model>.json``, written by ``scripts/oracle/kratos_examples.py`` (Kratos
10.4.4 from PyPI, one thread, at most 120 s of wall time per model): the named nodes'
displacement, the reaction sums per support, the active slave nodes and the contact pressure at
the first step, the fifth and the quarters of the steps the reference finished. What is recorded
and how is ``kratos_examples_common.py``, the same code for both systems.

Each model is run here to a time the reference reached (``CASES``) and compared at every fixture
snapshot up to it. How far each system gets, and the tolerances:

| model | reference (120 s cap) | compared here | largest difference |
|---|---|---|---|
| press fit 2D | t = 0.641, then an inverted element | t <= 0.005 | 7.5e-7 |
| press fit 3D | step 1; 2-13 unconverged; singular | step 1 (y); to 1.4 (slow) | 2.5 % (ref) |
| cylinders vertical | t = 0.29 | t <= 0.29 (slow) | 6.2e-4 reactions |
| cylinders horizontal 1 | t = 0.1275 | t <= 0.1275 (slow) | 8.5e-4 displacement |
| cylinders horizontal 2 | t = 0.1475 | t <= 0.1475 (slow) | 1.6e-2 reactions (ref) |
| horizontal 2 frictional | t = 0.32; 1, 2, 7, 8 unconverged | t <= 0.24 (slow) | 0.11 pressure |
| hyperelastic tubes | step 1; step 2 unconverged | step 1 | 7.1 % reaction (ref) |
| double arch | t = 0.0025; 6-8 unconverged | t <= 0.0025 | 1.5e-3 pressure |
| double arch frictional | stops in step 1 (CONTACT LOST) | ours: step 1; 40 steps (slow) | |

Sizes: displacement over the largest displacement component of the named nodes, reactions over
the largest reaction of the reference's converged snapshots, pressures relative, active nodes
as a count. Each tolerance is about twice the measured difference where the two agree; where
they differ more, the test next to the case says which is right and why (reference steps that
did not converge, reactions that do not balance, a symmetric problem solved asymmetrically,
Coulomb's law not obeyed), and the reference's own defect is asserted on the fixture.
Contact pressure: compared where neither system has a spike (the largest pressure agrees to
0.6 % on the cylinders up to the times above; the spikes of the issue come later, from t = 0.2 on
horizontal 1, and are being fixed separately), at 1e-2 for the largest and the median.
"""

from __future__ import annotations

import functools
import json
import math
from pathlib import Path

import kratos_examples_common as common
import pytest

DATA = Path(__file__).parent / "data" / "kratos_examples"

pytestmark = pytest.mark.skipif(
    not common.EXAMPLES.is_dir(), reason="../shared/kratos_examples is missing"
)


def _fixture(name: str) -> dict:
    return json.loads((DATA / f"{name}.json").read_text())


@pytest.mark.parametrize("name", list(common.MODELS))
def test_fixture_is_of_this_mesh_and_reference(name: str) -> None:
    fixture = _fixture(name)
    assert fixture["mdpa_sha256"] == common.mdpa_sha256(name)
    assert fixture["kratos"] == "10.4.4"
    assert fixture["threads"] == 1
    assert fixture["snapshots"] or fixture["failure"], "the reference finished no step"


@functools.cache
def _ours(name: str, end_time: float) -> tuple[list[dict], list[dict], str | None]:
    """Our run of ``name`` to ``end_time``: history, snapshots at the fixture's times, failure."""
    times = [record["time"] for record in _fixture(name)["snapshots"]]

    def wanted(time: float) -> bool:
        return any(abs(time - t) <= 1.0e-9 * max(1.0, abs(t)) for t in times)

    analysis, failure = common.run_ours(name, end_time, keep_snapshots=wanted)
    return analysis.history, analysis.snapshots, failure


def _scale(values) -> float:
    return max((abs(v) for vector in values for v in vector), default=0.0)


def reaction_scale(fixture: dict) -> float:
    """The largest reaction component of the reference over its converged snapshots."""
    return max(
        _scale(record["reactions"].values())
        for record in fixture["snapshots"]
        if _converged_in_reference(fixture, record["time"])
    )


def differences(ours: dict, reference: dict, reactions: float) -> dict[str, float]:
    """The sizes of the differences of two snapshots, each relative to its natural scale.

    displacement: the largest component difference over the named nodes, over the largest
    displacement component of the named nodes; reactions: the largest component difference over
    the supports, over ``reactions`` (the model's reaction scale: before contact the reactions
    are round-off); active: the difference in the count of active slave nodes (absolute);
    pressure_median and pressure_max: relative to the reference's value (0 when both are 0).
    """
    u_ref = reference["displacement"]
    du = max(
        abs(a - b)
        for key in u_ref
        for a, b in zip(ours["displacement"][key], u_ref[key], strict=True)
    )
    r_ref = reference["reactions"]
    dr = max(
        abs(a - b) for key in r_ref for a, b in zip(ours["reactions"][key], r_ref[key], strict=True)
    )

    def relative(key: str) -> float:
        if reference[key] == 0.0:
            return 0.0 if ours[key] == 0.0 else math.inf
        return abs(ours[key] - reference[key]) / abs(reference[key])

    return {
        "displacement": du / max(_scale(u_ref.values()), 1e-300),
        "reactions": dr / reactions,
        "active": float(abs(ours["active"] - reference["active"])),
        "pressure_median": relative("pressure_median"),
        "pressure_max": relative("pressure_max"),
    }


def _converged_in_reference(fixture: dict, when: float) -> bool:
    step = common.at_time(fixture["history"], when)
    return step is not None and step["converged"] is not False


def _imbalance(record: dict) -> list[float]:
    """The sum of the reactions over all supports (the models have no other load)."""
    return [sum(vector[i] for vector in record["reactions"].values()) for i in range(3)]


def compare(name: str, until: float, tolerances: dict[str, float]) -> dict[str, float]:
    """Run ours to ``until``; compare at every fixture snapshot up to it; the largest differences.

    Snapshots where the reference did not converge are left out (checked separately). Before the
    first contact (no active node in the reference) only the displacements are compared and our
    reactions must vanish (see test_reference_reactions_do_not_balance_before_contact).
    """
    fixture = _fixture(name)
    history, snapshots, failure = _ours(name, until)
    assert failure is None, failure
    assert all(step["converged"] is not False for step in history)
    assert history[-1]["time"] == pytest.approx(until, rel=1e-9)
    scale = reaction_scale(fixture)
    largest: dict[str, float] = {}
    compared = 0
    for reference in fixture["snapshots"]:
        late = reference["time"] > until + 1e-9
        if late or not _converged_in_reference(fixture, reference["time"]):
            continue
        ours = common.at_time(snapshots, reference["time"])
        assert ours is not None, f"no snapshot of ours at t = {reference['time']}"
        sizes = differences(ours, reference, scale)
        if name.startswith(("cylinders", "hyperelastic")):  # disjoint supports, no load: balance
            # measured: 3e-6 (cylinders), 3.4e-5 (tubes); the reference: up to 6.4e-2
            assert max(abs(value) for value in _imbalance(ours)) <= 1e-4 * scale
        if reference["active"] == 0:
            assert ours["active"] == 0
            assert _scale(ours["reactions"].values()) <= 1e-5 * scale
            sizes = {"displacement": sizes["displacement"]}
        for key, size in sizes.items():
            largest[key] = max(largest.get(key, 0.0), size)
        compared += 1
    assert compared > 0
    for key, size in largest.items():
        assert size <= tolerances[key], f"t <= {until}: {key} differs by {size:.3g}"
    return largest


def _tolerances(
    displacement: float,
    reactions: float = 0.0,
    active: float = 0.0,
    pressure_median: float = 0.0,
    pressure_max: float = 0.0,
) -> dict[str, float]:
    return {
        "displacement": displacement,
        "reactions": reactions,
        "active": active,
        "pressure_median": pressure_median,
        "pressure_max": pressure_max,
    }


#: model -> [(compare up to this TIME, slow, tolerances)]. The TIMEs are fixture snapshot times.
CASES: dict[str, list[tuple[float, bool, dict[str, float]]]] = {
    # Pressing phase (steps 1-5): measured 7.5e-7, 9.5e-10, 0, 4.5e-8, 2.0e-6.
    "press_fit_2d": [(0.005, False, _tolerances(1e-5, 1e-5, 0, 1e-5, 1e-5))],
    # Before contact (t < 0.12): displacement only, 3.3e-5. To t = 0.29 (16 active nodes):
    # 2.3e-4, 6.2e-4, 0, 2.9e-3, 5.8e-3.
    "cylinders_vertical": [
        (0.025, False, _tolerances(1e-4)),
        (0.29, True, _tolerances(5e-4, 1.5e-3, 0, 1e-2, 1e-2)),
    ],
    # Before contact: 8.5e-4 (the reference's unbalanced force deforms the upper cylinder). To
    # t = 0.1275 (11 active nodes): 8.5e-4, 4.1e-4, 0, 1.3e-3, 1.8e-3.
    "cylinders_horizontal_1": [
        (0.0125, False, _tolerances(2e-3)),
        (0.1275, True, _tolerances(2e-3, 1e-3, 0, 1e-2, 1e-2)),
    ],
    # As horizontal 1; the reactions differ by the reference's own imbalance (2.2e5, 1.6e-2 of the
    # scale; ours 20): measured 8.6e-4, 1.6e-2, 0, 3.4e-3, 4.2e-3 to t = 0.1475 (15 active).
    "cylinders_horizontal_2": [
        (0.0125, False, _tolerances(2e-3)),
        (0.1475, True, _tolerances(2e-3, 2.5e-2, 0, 1e-2, 1e-2)),
    ],
    # Step 1 only (the reference's step 2 stops unconverged at 20 iterations). One active node.
    # The reference converged step 1 in one iteration with its two supports out of balance by
    # 6.4 % (1.896e-4 against 1.775e-4; ours balance to 4e-5 at 1.762e-4, 0.7 % from the
    # reference's second support): reactions 7.1e-2, pressure 6.8 % (the same ratio: the
    # reference's contact force equals its unbalanced first reaction); displacement 7.3e-3.
    "hyperelastic_tubes": [(0.05, False, _tolerances(1.5e-2, 0.1, 0, 0.1, 0.1))],
    # Steps 1-5 (the reference's steps 6-8 stop unconverged at 20 iterations): 1.1e-4, 1.1e-3 or
    # 1.13e-2, 0, 1.5e-3, 1.7e-4; 24 active nodes. The reactions are converged only to the model's
    # residual ratio 1e-4 of a first residual that holds the penalty forces: the two mirror
    # supports DISPLACEMENT_Auto1/Auto2 carry y 4645.83 / -4854.89 in the reference at t = 0.0025,
    # and 4645.93 / -4645.93 in ours converged to 1e-9 (either ordering). With the model's own
    # tolerances ours lands on -4857.19 (AMD ordering) or -4645.93 (METIS): 1.2e-3 or 1.13e-2 of
    # the scale from the reference, whose second support is the unconverged one.
    "double_arch": [(0.0025, False, _tolerances(3e-4, 1.5e-2, 0, 5e-3, 1e-3))],
}


def _params():
    for name, cases in CASES.items():
        for until, slow, tolerances in cases:
            marks = [pytest.mark.slow] if slow else []
            yield pytest.param(name, until, tolerances, marks=marks, id=f"{name}-t{until:g}")


@pytest.mark.parametrize(("name", "until", "tolerances"), list(_params()))
def test_agrees_with_reference(name: str, until: float, tolerances: dict[str, float]) -> None:
    sizes = compare(name, until, tolerances)
    print(name, until, {key: f"{size:.3g}" for key, size in sizes.items()})


def test_press_fit_3d_first_step_is_symmetric_where_the_reference_is_not() -> None:
    """The 3D press fit: the reference converges step 1 only; ours converges all 13 of its steps.

    The mesh is a structured extrusion (hexahedra, 0 <= z <= 0.25) with the channel fixed in z
    and the block free, so the problem, and its discrete solution, are mirror-symmetric about
    z = 0.125, where the named nodes lie: their z displacement and the z reactions must vanish.
    Ours: 1e-12 of the displacement. The reference, at its only converged step, moves the block's
    contact face in z by 0.2 of its largest displacement and carries a z force of 11834 from the
    block into the channel (a tangential contact force that breaks the symmetry); then its steps
    2-13 stop at max_iteration unconverged with the block's reactions out of balance by 1e8 and it
    gives up at step 14 on a singular matrix. So only the symmetric part of step 1 is compared:
    the y components agree within 3.5 % (measured: 2.5 % displacement, 1.9 % reaction).
    """
    fixture = _fixture("press_fit_3d")
    converged = [step["converged"] for step in fixture["history"]]
    assert converged == [True] + [False] * 12
    history, snapshots, failure = _ours("press_fit_3d", fixture["reached_time"])
    assert failure is None and len(history) == 13
    assert all(step["converged"] for step in history)
    reference = fixture["snapshots"][0]
    ours = common.at_time(snapshots, reference["time"])
    size = _scale(ours["displacement"].values())
    assert max(abs(u[2]) for u in ours["displacement"].values()) <= 1e-9 * size
    assert max(abs(u[2]) for u in reference["displacement"].values()) >= 0.1 * size
    forces = _scale(ours["reactions"].values())
    assert max(abs(r[2]) for r in ours["reactions"].values()) <= 1e-8 * forces
    assert max(abs(r[2]) for r in reference["reactions"].values()) >= 0.03 * forces
    for key, u in reference["displacement"].items():
        assert ours["displacement"][key][1] == pytest.approx(u[1], abs=0.035 * size)
    for key, r in reference["reactions"].items():
        assert ours["reactions"][key][1] == pytest.approx(r[1], abs=0.035 * forces)
    assert ours["active"] == reference["active"]


def _coulomb_ratio(record: dict) -> float:
    """Press fit 2D: the force pushing the block along x over the force pressing it down."""
    push = record["reactions"]["DISPLACEMENT_Displacement_Auto3"][0]
    press = record["reactions"]["DISPLACEMENT_Displacement_Auto1"][1]
    return abs(push / press)


def test_press_fit_2d_slides_with_coulomb_friction_where_the_reference_does_not() -> None:
    """The 2D press fit after the pressing phase: the block slides along the straight channel.

    At t = 0.231 (the fixture's third snapshot, before the channel narrows) every contact node
    slides, the contact normals are along y, and Coulomb's law with the process's
    friction_coefficients (mu = 0.1) makes the pushing force mu times the pressing force. Ours:
    0.1000 (and the contact force sum(area * p) equals the pressing reaction to 1e-3: equilibrium
    of contact forces against reactions). The reference: 0.0038, as if mu were 0.004; its
    pressing forces are also 9 % lower. So from the start of sliding the two differ by the
    reference's friction (displacements 7e-4 at t = 0.231, reactions 0.3 after, pressure up to
    1.2x), and ours is the one that obeys Coulomb's law: the comparison with the reference stops
    at the end of the pressing phase (test_agrees_with_reference, t <= 0.005).
    """
    fixture = _fixture("press_fit_2d")
    reference = fixture["snapshots"][2]
    assert reference["time"] == pytest.approx(0.231)
    history, snapshots, failure = _ours("press_fit_2d", reference["time"])
    assert failure is None and all(step["converged"] for step in history)
    ours = common.at_time(snapshots, reference["time"])
    assert _coulomb_ratio(ours) == pytest.approx(0.1, rel=1e-3)
    assert _coulomb_ratio(reference) < 0.01
    press = ours["reactions"]["DISPLACEMENT_Displacement_Auto1"][1]
    assert abs(ours["contact_force"]) == pytest.approx(abs(press), rel=1e-3)


@pytest.mark.slow
def test_press_fit_2d_runs_to_its_end_where_the_reference_gives_up() -> None:
    """The whole history, where the reference stops at t = 0.6415 (element 57 inverted).

    Ours runs the model to its end_time 1.3 (360 steps of 1e-3, then 1880 of 5e-4) without
    cutting a step, 4-9 Newton iterations per step (12,464 in all, 24 s on the quiet machine).
    """
    fixture = _fixture("press_fit_2d")
    assert fixture["failure"] is not None and "INVERTED" in " ".join(fixture["failure"]["message"])
    end_time = common.raw_parameters("press_fit_2d")["problem_data"]["end_time"]
    history, _, failure = _ours("press_fit_2d", end_time)
    assert failure is None and all(step["converged"] for step in history)
    assert history[-1]["time"] == pytest.approx(end_time)
    assert len(history) == 360 + 1880  # the model's own steps: none was cut
    assert max(step["iterations"] for step in history) <= 10


@pytest.mark.slow
def test_press_fit_3d_runs_to_its_end_where_the_reference_gives_up() -> None:
    """The whole 3D history, where the reference gives up at step 14 (singular matrix).

    Ours stopped at t = 0.525 (step 105: fixed contact sets, the residual ratio stuck at 0.2)
    while the mortar cells fanned from the overlap's first vertex, whose D and M jump when the
    overlap gains a vertex (docs/theory/mortar.md section 1). With the cells around the area
    centroid it runs to end_time 1.4: 280 model steps, one (t = 0.595) cut into 10 on an inverted
    element, 6-9 Newton iterations each (model max_iteration 10), about a minute.
    """
    end_time = common.raw_parameters("press_fit_3d")["problem_data"]["end_time"]
    history, _, failure = _ours("press_fit_3d", end_time)
    assert failure is None, failure
    assert all(step["converged"] for step in history)
    assert history[-1]["time"] == pytest.approx(end_time)
    assert 280 <= len(history) <= 300
    assert max(step["iterations"] for step in history) <= 10


@pytest.mark.parametrize(
    "name", ["cylinders_vertical", "cylinders_horizontal_1", "cylinders_horizontal_2"]
)
def test_reference_reactions_do_not_balance_before_contact(name: str) -> None:
    """Why the reactions before contact are not compared: the reference's are not in balance.

    Before the first contact the upper cylinder moves freely under its imposed displacement and
    nothing else loads either body, so every reaction must vanish (ours: at most 22, 3e-6 of the
    model's reaction scale, checked in ``compare``). The reference holds a constant force on the
    imposed support that nothing balances: 5.0e3 (vertical), 2.2e5 (horizontal 1 and 2), 2e-4 to
    3e-2 of the scale; on horizontal 2 it stays in the contact phase (the 1.6e-2 tolerance).
    """
    fixture = _fixture(name)
    first = fixture["snapshots"][0]
    assert first["active"] == 0
    assert max(abs(value) for value in _imbalance(first)) > 1e-4 * reaction_scale(fixture)


@pytest.mark.slow
def test_cylinders_horizontal_2_frictional_agrees_where_the_reference_converges() -> None:
    """Horizontal 2, frictional (mu = 1), dynamic (Bossak), time step 0.04, to t = 0.24.

    The reference does not converge its steps 1 and 2 (20 iterations each, multiplier norms
    1e23-1e26) and converges steps 3-6 (t = 0.12 ... 0.24, 4-5 iterations, 11-18 active nodes);
    its steps 7 and 8 stop unconverged again. Ours converges steps 1-6 (3, 17, 13, 12, 11, 12
    iterations; 12 s). Before the contact strategy stopped extrapolating with the Bossak
    predictor, our step 2 inverted tetrahedra next to the driven face and the run gave up at
    t = 0.0775. The two histories part at the reference's unconverged steps 1-2 (its state at
    t = 0.08 is the end of 20 failed iterations), so the differences grow with time: measured at
    t = 0.12 / 0.24: displacement 4.3e-3 / 8.0e-3, reactions 5.2e-3 / 2.2e-2 of the scale,
    the same active nodes, contact pressure median 1.2e-2 / 1.1e-1, largest 1.1e-1 / 2.5e-2.
    The tolerances are about those doubled, as for the other models; ours balances its
    reactions to 1e-4 of the scale at every compared step (checked in ``compare``).
    """
    compare("cylinders_horizontal_2_frictional", 0.24, _tolerances(1.6e-2, 4.5e-2, 0, 0.25, 0.25))


@pytest.mark.slow
def test_cylinders_horizontal_2_frictional_converges_step_7() -> None:
    """Steps 7 and 8 of the frictional horizontal 2 (t = 0.28, 0.32): all 20-23 active nodes slip.

    The reference stops unconverged at step 7. So did ours (20 iterations, displacement ratio
    3.9e-4, LM ratio 0.83, 19 of 20 slip directions still turning) until a slipping node whose
    direction turns beyond the slip law's linearisation raises its own trial constant
    (docs/theory/mortar.md section 8): steps 1-8 now converge in 3, 9, 11, 9, 9, 11, 11, 10
    iterations.
    """
    history, _, failure = _ours("cylinders_horizontal_2_frictional", 0.32)
    assert failure is None, failure
    assert len(history) == 8 and all(step["converged"] for step in history)
    assert max(step["iterations"] for step in history) <= 14


def test_double_arch_frictional_converges_the_step_where_the_reference_stops() -> None:
    """The frictional double arch: the reference stops in step 1 ("CONTACT LOST", ensure_contact).

    Nothing of the reference to compare with. Ours converges step 1 with the arches in contact.
    """
    fixture = _fixture("double_arch_frictional")
    assert fixture["steps"] == 0 and "CONTACT LOST" in fixture["failure"]["message"][0]
    history, _, failure = _ours("double_arch_frictional", 0.0005)
    assert failure is None and len(history) == 1
    assert history[0]["converged"] and history[0]["active"] > 0


@pytest.mark.slow
def test_double_arch_frictional_runs_forty_steps_at_three_iterations() -> None:
    """The frictional double arch over 40 steps (t = 0.02; the model's end is 0.175).

    Step 2 (24 active nodes, 16 slipping) stopped at 20 iterations until slipping nodes whose
    direction turns beyond the slip law's linearisation raise their own trial constant
    (docs/theory/mortar.md section 8). Step 19 (t = 0.0095, all 56 active nodes sticking) then
    alternated between two states until it stopped at 20 iterations: Gauss points were dropped
    at random by projections that stalled on the round-off of the absolute coordinates (section
    2). Since: 3 iterations per step, a few 4-7.
    """
    history, _, failure = _ours("double_arch_frictional", 0.02)
    assert failure is None, failure
    assert len(history) == 40 and all(step["converged"] for step in history)
    iterations = [step["iterations"] for step in history]
    assert max(iterations) <= 8, iterations
    assert sum(iterations) <= 150, iterations


@pytest.mark.slow
def test_cylinders_horizontal_2_frictional_slides_at_a_smaller_step() -> None:
    """Horizontal 2, frictional, at time step 0.004 to t = 0.06: every step converges.

    Contact starts at t = 0.04. With the slip law's trial constant c_t = kappa eps (kappa = 0.025
    here) step 11 stopped at 20 iterations, the most loaded node's traction turning 6.7 -> 89
    degrees off its slip; with c_t = max(kappa, 1) eps (docs/theory/mortar.md section 8) steps
    10-15 converge in 6-12 iterations.
    """
    import contact_app as ca
    from contact_app.analysis import StructuralMechanicsAnalysis
    from contact_app.analysis.reporting import Reporter

    raw = common.prepared_parameters("cylinders_horizontal_2_frictional", end_time=0.06)
    raw["solver_settings"]["time_stepping"] = {"time_step": 0.004}
    analysis = StructuralMechanicsAnalysis(ca.Model(), raw, reporter=Reporter(quiet=True))
    analysis.Run()
    steps = analysis.reporter.steps
    assert len(steps) == 15
    assert all(step.converged for step in steps)
    assert max(step.iterations for step in steps) <= 15
