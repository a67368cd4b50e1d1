"""The MPC contact solvers: settings validation and the two-block patch (closing, pulling apart)."""

from __future__ import annotations

import logging
from pathlib import Path

import pytest

import contact_app as ca
from contact_app.analysis import StructuralMechanicsAnalysis
from contact_app.analysis.reporting import Reporter
from contact_app.contact.mpc_auxiliary_methods_solvers import MPC_FORCED_SOLVER_SETTINGS
from contact_app.parameters import Parameters

CASES_DIR = Path(__file__).resolve().parents[3].parent / "shared" / "kratos_cases"
CASE = "mpc_contact_tests/2D_contact_simplest_patch_matching_test"
GAP = 0.001  # initial distance between the slave (y = 1) and the master (y = 1.001) faces

pytestmark = pytest.mark.skipif(not CASES_DIR.is_dir(), reason="../shared/kratos_cases missing")


def _parameters(mpc: dict | None = None, top: str = "-2.0e-1*t") -> Parameters:
    parameters = Parameters.from_file(CASES_DIR / f"{CASE}_parameters.json")
    parameters.AddValue("output_processes", {})
    parameters["processes"].AddValue("json_check_process", [])
    parameters["processes"]["constraints_process_list"][1]["Parameters"].AddValue(
        "value", [0.0, top, 0.0]
    )
    for key, value in (mpc or {}).items():
        parameters["solver_settings"]["mpc_contact_settings"].AddValue(key, value)
    return parameters


def _analysis(parameters: Parameters) -> StructuralMechanicsAnalysis:
    """A quiet analysis of ``parameters`` on the files of the Kratos MPC contact cases."""
    return StructuralMechanicsAnalysis(
        ca.Model(),
        parameters,
        base_dir=CASES_DIR / "mpc_contact_tests",
        reporter=Reporter(quiet=True),
    )


def _run(parameters: Parameters) -> StructuralMechanicsAnalysis:
    analysis = _analysis(parameters)
    analysis.Run()
    return analysis


def _disp(part: ca.ModelPart, node: int) -> list[float]:
    return list(part.GetNode(node).GetSolutionStepValue(ca.DISPLACEMENT))


@pytest.mark.parametrize(
    ("simplified", "update_each"), [(False, False), (True, False), (False, True)]
)
def test_mpc_patch_closes_the_gap_and_transmits_the_load(
    simplified: bool, update_each: bool
) -> None:
    analysis = _run(
        _parameters(
            {"simplified_semi_smooth_newton": simplified, "update_each_nl_iteration": update_each}
        )
    )
    part = analysis.model.GetModelPart("Structure")
    # Slave (3, 4) and master (6, 5) nodes face each other: the constraint closes the gap exactly.
    for slave, master in ((3, 6), (4, 5)):
        assert _disp(part, slave)[1] - _disp(part, master)[1] == pytest.approx(GAP, abs=1e-12)
        node = part.GetNode(slave)
        assert node.Is(ca.ACTIVE)
        assert node.GetValue(ca.NORMAL_CONTACT_STRESS) < 0.0
        assert node.GetSolutionStepValue(ca.WEIGHTED_GAP) == pytest.approx(0.0, abs=1e-12)
    # Force balance: the slave contact forces carry the load the top nodes receive.
    top = sum(part.GetNode(n).GetSolutionStepValue(ca.REACTION)[1] for n in (7, 8))
    contact = sum(part.GetNode(n).GetSolutionStepValue(ca.REACTION)[1] for n in (3, 4))
    bottom = sum(part.GetNode(n).GetSolutionStepValue(ca.REACTION)[1] for n in (1, 2))
    assert top < 0.0
    assert contact == pytest.approx(top, rel=1e-9)
    assert bottom == pytest.approx(-top, rel=1e-9)
    # The symmetric problem stays symmetric.
    assert _disp(part, 5)[0] == pytest.approx(-_disp(part, 6)[0], rel=1e-9)


def test_mpc_patch_pulled_apart_releases_the_contact() -> None:
    analysis = _run(_parameters(top="2.0e-1*t"))
    part = analysis.model.GetModelPart("Structure")
    for slave in (3, 4):
        assert not part.GetNode(slave).Is(ca.ACTIVE)
        assert _disp(part, slave) == pytest.approx([0.0, 0.0, 0.0], abs=1e-12)
    # The upper block is free: a rigid translation, no reaction at its top.
    for node in (5, 6, 7, 8):
        assert _disp(part, node)[:2] == pytest.approx([0.0, 0.2], abs=1e-12)
        assert part.GetNode(node).GetSolutionStepValue(ca.REACTION)[1] == pytest.approx(
            0.0, abs=1e-3
        )
    assert all(not c.Is(ca.ACTIVE) for c in part.MasterSlaveConstraints)


def test_mpc_solver_modules_follow_the_solver_type() -> None:
    from contact_app.analysis.paths import PathResolver
    from contact_app.analysis.solvers.solver_wrapper import CreateSolverByParameters
    from contact_app.contact.mpc_contact_structural_mechanics_implicit_dynamic_solver import (
        MPCContactImplicitMechanicalSolver,
    )
    from contact_app.contact.mpc_contact_structural_mechanics_static_solver import (
        MPCContactStaticMechanicalSolver,
    )

    for solver_type, expected in (
        ("Static", MPCContactStaticMechanicalSolver),
        ("Dynamic", MPCContactImplicitMechanicalSolver),
    ):
        settings = _parameters()["solver_settings"]
        settings["solver_type"].SetString(solver_type)
        solver = CreateSolverByParameters(ca.Model(), settings, paths=PathResolver(CASES_DIR))
        assert type(solver) is expected
        # Forced settings of the MPC route.
        for key in ("compute_reactions", "reform_dofs_at_each_step", "clear_storage"):
            assert settings[key].GetBool()


@pytest.mark.parametrize(
    ("given", "named"),
    [
        ({}, []),
        (dict.fromkeys(MPC_FORCED_SOLVER_SETTINGS, True), []),
        ({"compute_reactions": False}, ["compute_reactions"]),
        (
            {"reform_dofs_at_each_step": False, "clear_storage": False, "compute_reactions": True},
            ["reform_dofs_at_each_step", "clear_storage"],
        ),
    ],
    ids=["not_given", "all_true", "reactions_false", "dofs_false"],
)
def test_mpc_forced_settings_are_silent_unless_the_user_said_false(
    given: dict[str, bool], named: list[str], caplog: pytest.LogCaptureFixture
) -> None:
    from contact_app.analysis.paths import PathResolver
    from contact_app.analysis.solvers.solver_wrapper import CreateSolverByParameters

    settings = _parameters()["solver_settings"]
    for key in MPC_FORCED_SOLVER_SETTINGS:
        if settings.Has(key):
            settings.RemoveValue(key)
    for key, value in given.items():
        settings.AddValue(key, value)
    with caplog.at_level(logging.DEBUG, logger="contact_app"):
        CreateSolverByParameters(ca.Model(), settings, paths=PathResolver(CASES_DIR))
    for key in MPC_FORCED_SOLVER_SETTINGS:
        assert settings[key].GetBool()
    records = [
        r for r in caplog.records if any(k in r.getMessage() for k in MPC_FORCED_SOLVER_SETTINGS)
    ]
    if not named:
        assert records == []  # not even an info line
        return
    assert len(records) == 1 and records[0].levelno == logging.WARNING
    message = records[0].getMessage()
    assert "solver_settings" in message and "MPC criterion reads the contact forces" in message
    for key in MPC_FORCED_SOLVER_SETTINGS:
        assert (key in message) == (key in named)


def test_mpc_settings_unknown_key_is_an_input_error() -> None:
    with pytest.raises(ca.InputError, match="inner_loop_iteration"):
        _run(_parameters({"inner_loop_iteration": 3}))


def test_mpc_settings_bad_contact_type_is_an_input_error() -> None:
    with pytest.raises(ca.InputError, match="Frictional"):
        _run(_parameters({"contact_type": "Frictionnal"}))


def _frictional_run(mu: float) -> ca.ModelPart:
    parameters = _parameters({"contact_type": "Frictional"})
    process = parameters["processes"]["contact_process_list"][0]["Parameters"]
    process.AddValue("contact_type", "Frictional")
    parameters["solver_settings"].AddValue("buffer_size", 3)
    analysis = _analysis(parameters)
    analysis.Initialize()
    for node in analysis.model.GetModelPart("Structure.Contact").Nodes:
        node.SetValue(ca.FRICTION_COEFFICIENT, mu)
    analysis.RunSolutionLoop()
    analysis.Finalize()
    return analysis.model.GetModelPart("Structure")


def test_mpc_frictional_patch_sticks_slips_and_degenerates_to_frictionless() -> None:
    frictionless = _run(_parameters()).model.GetModelPart("Structure")
    # μ = 0: every active node slips and the result is the frictionless one.
    free = _frictional_run(0.0)
    for node in (3, 4, 5, 6):
        assert _disp(free, node) == pytest.approx(_disp(frictionless, node), rel=1e-9)
    assert all(free.GetNode(n).Is(ca.SLIP) for n in (3, 4))
    # Large μ: stick, the facing nodes move together tangentially.
    stuck = _frictional_run(0.3)
    for slave, master in ((3, 6), (4, 5)):
        assert not stuck.GetNode(slave).Is(ca.SLIP)
        assert _disp(stuck, slave)[0] == pytest.approx(_disp(stuck, master)[0], rel=1e-12)
        traction = stuck.GetNode(slave).GetValue(ca.TANGENTIAL_CONTACT_STRESS)
        assert 0.0 < traction <= -0.3 * stuck.GetNode(slave).GetValue(ca.NORMAL_CONTACT_STRESS)
    # Small μ: slip with a friction force that holds the slave back from its frictionless motion.
    slipping = _frictional_run(1.0e-5)
    for slave in (3, 4):
        assert slipping.GetNode(slave).Is(ca.SLIP)
        x_free, x_stuck = _disp(free, slave)[0], _disp(stuck, slave)[0]
        x_slip = _disp(slipping, slave)[0]
        assert min(x_free, x_stuck) < x_slip < max(x_free, x_stuck)
