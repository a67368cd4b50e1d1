"""The ironing_2d example: die reaction histories against the Kratos oracle and Coulomb's law.

Oracle fixtures: tests/python/examples/data/ironing_2d_<variant>.json (scripts/oracle/ironing_2d.py,
Kratos 10.4.4). Kratos' frictional ALM stops at the first sliding step (NaN after 7 iterations) and
its frictional penalty at step 2, so the frictional comparison covers the pressing phase; the
frictionless ALM oracle covers the whole history. Differences are relative to the largest pressing
force of the oracle (examples/ironing_2d/README.md has the measurements behind every tolerance).
"""

from __future__ import annotations

import hashlib
import json
import shutil
import sys
from pathlib import Path

import numpy as np
import pytest

EXAMPLE = Path(__file__).parents[3] / "examples" / "ironing_2d"
sys.path.insert(0, str(EXAMPLE.parent))
from hertz_common import load_script  # noqa: E402  (examples/hertz_common.py)

DATA = Path(__file__).parent / "data"
#: Measured: pressing phase vs Kratos, frictional ALM: dFx 9.4e-4, dFy 7.6e-4; frictionless over
#: the whole history: dFy 1.1e-3 (the same size: it is not friction). Twice the largest.
PRESSING_TOLERANCE = 2.2e-3


def _example_module():
    return load_script("run_ironing_2d", EXAMPLE / "run_ironing_2d.py")


def _copy_inputs(directory: Path) -> None:
    """The example's three input files, as they are, into ``directory``."""
    for path in EXAMPLE.iterdir():
        if path.suffix in (".json", ".mdpa"):
            shutil.copy(path, directory / path.name)


def test_committed_mesh_is_level_1_and_the_one_the_oracle_ran(tmp_path: Path) -> None:
    module = _example_module()
    written = tmp_path / "ironing_2d.mdpa"
    mesh = module.make_mesh.write_mesh(written, 1)
    assert written.read_bytes() == (EXAMPLE / "ironing_2d.mdpa").read_bytes()
    digest = hashlib.sha256(written.read_bytes()).hexdigest()
    for variant in ("alm", "alm_frictionless", "penalty"):
        fixture = json.loads((DATA / f"ironing_2d_{variant}.json").read_text())
        assert fixture["mdpa_sha256"] == digest
        assert fixture["kratos"] == "10.4.4"
    assert (mesh.number_of_nodes, mesh.number_of_quads) == (896, 792)


def test_mesh_geometry_and_node_sets() -> None:
    module = _example_module()
    make_mesh = module.make_mesh
    mesh = make_mesh.build(2)
    coordinates = {**mesh.slab.coordinates, **mesh.die.coordinates}
    groups = mesh.groups
    # Slave: the slab's top, 121 nodes at level 2; master: the die's arc, 49 nodes on the circle.
    slave = np.array([coordinates[n] for n in groups["Contact_Slave"]])
    master = np.array([coordinates[n] for n in groups["Contact_Master"]])
    assert len(slave) == 121 and np.allclose(slave[:, 1], make_mesh.SLAB_HEIGHT)
    centre = np.array([make_mesh.DIE_START, make_mesh.SLAB_HEIGHT + make_mesh.RADIUS])
    assert len(master) == 49
    assert np.allclose(np.linalg.norm(master - centre, axis=1), make_mesh.RADIUS)
    assert master[:, 1].min() == pytest.approx(make_mesh.SLAB_HEIGHT)  # touching, no gap
    # The first contact point is not a node of both surfaces (a quarter interval off).
    assert np.min(np.abs(slave[:, 0] - make_mesh.DIE_START)) == pytest.approx(0.025)
    # Every quad counter-clockwise (positive area), areas summing to the slab plus the die.
    for block in (mesh.slab, mesh.die):
        xy = np.array([[block.coordinates[n] for n in quad] for quad in block.quads])
        x, y = xy[..., 0], xy[..., 1]
        area = 0.5 * np.sum(x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y, axis=1)
        assert area.min() > 0.0
    # R = 1, DIE_HEIGHT = 1: the die is the region between the arc and the line y = H + 1.
    die_area = 0.8 * 0.6 + make_mesh.THETA
    xy = np.array([[mesh.die.coordinates[n] for n in q] for q in mesh.die.quads])
    area = 0.5 * np.sum(
        xy[..., 0] * np.roll(xy[..., 1], -1, axis=1) - np.roll(xy[..., 0], -1, axis=1) * xy[..., 1]
    )
    assert area == pytest.approx(die_area, rel=1e-3)  # chords under the arc: O(h^2)
    assert make_mesh.contact_spacing(2) == pytest.approx((0.05, 0.0386), rel=1e-3)


def test_parameters_file_is_the_alm_variant() -> None:
    module = _example_module()
    parameters = json.loads((EXAMPLE / "ProjectParameters.json").read_text())
    reference = json.loads(json.dumps(parameters))
    assert module.variant_parameters(parameters, "alm") == reference
    contact = parameters["processes"]["contact_process_list"][0]["Parameters"]
    assert contact["friction_coefficients"]["0"] == 0.3


def test_pressing_and_first_slide_steps_match_the_oracle(tmp_path: Path) -> None:
    _copy_inputs(tmp_path)
    module = _example_module()
    result = module.run(tmp_path, end_time=0.6)
    text = module.write_outputs(result, tmp_path)
    assert (tmp_path / module.PLOT).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "all steps converged" in text
    assert len(result.steps) == 12 and result.converged
    # Measured: 4 Newton iterations per pressing step, 5 in the first sliding steps.
    assert max(s.iterations for s in result.steps) <= 6
    # The oracle's 10 pressing steps (it stops at the 11th).
    assert result.oracle is not None and result.oracle["failure"]["step"] == 11
    compared, dfx, dfy = result.oracle_difference()
    assert compared == 10
    assert dfx < PRESSING_TOLERANCE and dfy < PRESSING_TOLERANCE
    # Equilibrium: the slab's base carries the die's reaction (measured 1.7e-8 of Fy).
    for step in result.steps:
        assert abs(step.fx + step.base_fx) < 1e-6 * step.fy
        assert abs(step.fy - step.base_fy) < 1e-6 * step.fy
    # Once sliding starts the slip nodes obey |q| = mu p (measured to 4e-16).
    assert result.steps[-1].slip > 0
    assert result.steps[-1].coulomb < 1e-9


@pytest.mark.slow
def test_whole_history_steady_sliding_obeys_coulomb(tmp_path: Path) -> None:
    _copy_inputs(tmp_path)
    module = _example_module()
    result = module.run(tmp_path)
    print(module.summary(result))
    assert result.converged and len(result.steps) == 90
    # Measured 3-6 iterations per step, 435 in all.
    assert max(s.iterations for s in result.steps) <= 8
    compared, dfx, dfy = result.oracle_difference()
    assert compared == 10 and max(dfx, dfy) < PRESSING_TOLERANCE
    # Steady sliding: every active node slips, |q| = mu p on each, and Fx/Fy = mu plus the
    # horizontal part of the normal pressure on the dented, tilted interface (measured 0.3069,
    # steady to +-2e-4; the frictionless drag alone is 0.0035 Fy).
    for step in result.steady:
        assert step.slip == step.active > 0
        assert step.coulomb < 1e-9
    mean, low, high = result.steady_ratio
    assert mean == pytest.approx(result.mu, abs=0.01)
    assert mean > result.mu  # the normal pressure adds to the drag; it cannot cancel friction
    assert high - low < 1e-3


@pytest.mark.slow
def test_frictionless_history_against_the_oracle(tmp_path: Path) -> None:
    _copy_inputs(tmp_path)
    module = _example_module()
    result = module.run(tmp_path, variant="alm_frictionless")
    assert result.converged
    compared, dfx, dfy = result.oracle_difference()
    assert compared == 90
    assert dfy < PRESSING_TOLERANCE  # measured 1.1e-3
    # The drag disagrees: without friction an elastic die sliding steadily on a long slab does no
    # net work, so its mean drag should vanish. Measured in steady sliding: ours 0.35 % of Fy at
    # level 1 and 0.33 % at level 2 (not a slab-mesh effect; unexplained, README.md), Kratos
    # 1.7 % at level 1; dFx = 1.5e-2. This pins the measured values, not a verdict.
    mean, _, _ = result.steady_ratio
    oracle_steady = [
        h["die_reaction_x"] / -h["die_reaction_y"]
        for h in result.oracle["history"]
        if h["time"] >= module.STEADY_START - 1e-9
    ]
    assert abs(mean) < 0.005
    assert abs(mean) < 0.5 * abs(float(np.mean(oracle_steady)))
    assert dfx < 0.02


def _assert_penalty_history(result, iterations: int, total: int) -> None:
    """The whole history, no step cut, every converged set consistent with its gaps.

    ``iterations`` bounds every step, ``total`` the whole history (a tangent that lost a term
    converges linearly again: 840 frictional, 551 frictionless iterations with eta held).
    """
    # A cut step would add its sub-steps to the history (measured before the penalty's release
    # rule, docs/theory/active_set.md section 2: 77 of 80 sliding steps cut, 2385 rows).
    assert result.converged and len(result.steps) == 90
    times = np.array([s.time for s in result.steps])
    assert np.allclose(times, 0.05 * np.arange(1, 91))
    pressing = [step for step in result.steps if step.time <= 0.5 + 1e-9]
    assert max(step.iterations for step in pressing) <= 6
    assert max(s.iterations for s in result.steps) <= iterations
    assert sum(s.iterations for s in result.steps) <= total
    for step in result.steps:
        # A converged penalty set: G < 0 on every active node, G >= 0 on every inactive one.
        assert step.set_mismatches == 0
        assert abs(step.fx + step.base_fx) < 1e-6 * step.fy
        assert abs(step.fy - step.base_fy) < 1e-6 * step.fy


@pytest.mark.slow
def test_penalty_frictional_presses_like_the_alm_and_slides(tmp_path: Path) -> None:
    """The penalty variant over the whole history (4.5 s of model time, about 12 s).

    Before the nodal penalty (docs/theory/mortar.md section 7) the pairs of a node on the curved,
    non-matching die pushed and pulled it with their own partial gaps and pressing steps 1, 2,
    3 and 6 stopped at 30 iterations. Now every pressing step converges in 4-5 iterations and the
    pressing forces are those of the ALM oracle (Kratos 10.4.4; the reference's own penalty
    gives an Fy 10 % lower at t = 0.05 and stops at t = 0.1): measured 1.1e-3 (Fy) and 1.3e-3
    (Fx) of the largest pressing force, the penetration of the penalty (1.1e-4 of the 0.2
    pressing) included. Before the release rule of docs/theory/active_set.md section 2 the
    penalty set released nodes that a Newton iterate opened by 1e-6, the freed slab sprang into
    the die and 77 of the 80 sliding steps were cut (2385 sub-steps, 17623 iterations, 300 s);
    now none is. With eta = sum a_c^2 / A^2 held by the tangent the sliding steps converged
    linearly (840 iterations, 3-14 per step); with its derivative (docs/theory/mortar.md section
    7): measured 687 iterations, 4-6 per pressing and 3-12 per sliding step, steady Fx/Fy =
    0.3067 (ALM 0.3069).
    """
    _copy_inputs(tmp_path)
    module = _example_module()
    result = module.run(tmp_path, variant="penalty")
    print(module.summary(result))
    _assert_penalty_history(result, iterations=14, total=750)
    oracle = module.load_oracle("alm")
    reference = {round(h["time"], 9): h for h in oracle["history"]}
    scale = max(abs(h["die_reaction_y"]) for h in oracle["history"])
    for step in result.steps:
        if step.time > 0.5 + 1e-9:
            break
        alm = reference[round(step.time, 9)]
        assert abs(step.fy + alm["die_reaction_y"]) < PRESSING_TOLERANCE * scale
        assert abs(step.fx - alm["die_reaction_x"]) < PRESSING_TOLERANCE * scale
    for step in result.steady:
        assert step.slip == step.active > 0
        assert step.coulomb < 1e-9
    # The ALM's steady ratio (test above) is 0.3069; the penalty's 0.3067.
    mean, low, high = result.steady_ratio
    assert mean == pytest.approx(0.3069, abs=1e-3)
    assert high - low < 1e-3


@pytest.mark.slow
def test_penalty_frictionless_history_against_the_oracle(tmp_path: Path) -> None:
    """The frictionless penalty over the whole history against the frictionless ALM oracle.

    Measured: 90 steps, none cut, 505 iterations (4-8 per step; 551 with eta held by the
    tangent); max |dFy| = 1.5e-3 of the largest oracle force (ours, ALM: 1.1e-3; the penalty's
    penetration adds the rest).
    """
    _copy_inputs(tmp_path)
    module = _example_module()
    result = module.run(tmp_path, variant="penalty_frictionless")
    print(module.summary(result))
    _assert_penalty_history(result, iterations=10, total=550)
    assert all(step.slip == 0 for step in result.steps)
    result.oracle = module.load_oracle("alm_frictionless")
    compared, _, dfy = result.oracle_difference()
    assert compared == 90 and dfy < 3e-3
