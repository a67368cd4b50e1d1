"""Contact solver options beyond the reference cases' defaults."""

from __future__ import annotations

import logging
from pathlib import Path

import pytest

import contact_app as ca
from contact_app.analysis import StructuralMechanicsAnalysis
from contact_app.analysis.reporting import Reporter
from contact_app.parameters import Parameters

CASES_DIR = Path(__file__).resolve().parents[3].parent / "shared" / "kratos_cases"
pytestmark = pytest.mark.skipif(not CASES_DIR.is_dir(), reason="../shared/kratos_cases missing")

TAYLOR = "ALM_frictionless_contact_test_2D/taylor_patch_test"


def _run(case: str, edit) -> StructuralMechanicsAnalysis:
    path = CASES_DIR / f"{case}_parameters.json"
    parameters = Parameters.from_file(path)
    parameters.AddValue("output_processes", {})
    parameters["processes"].AddValue("json_check_process", [])
    edit(parameters["solver_settings"])
    analysis = StructuralMechanicsAnalysis(
        ca.Model(), parameters, base_dir=path.parent, reporter=Reporter(quiet=True)
    )
    analysis.Run()
    return analysis


def _contact_displacements(analysis) -> dict[int, tuple[float, float]]:
    part = analysis.model.GetModelPart("Structure.Contact_Part")
    return {
        node.Id: (
            node.GetSolutionStepValue(ca.DISPLACEMENT_X),
            node.GetSolutionStepValue(ca.DISPLACEMENT_Y),
        )
        for node in part.Nodes
    }


@pytest.fixture(scope="module")
def default_solution() -> dict[int, tuple[float, float]]:
    """The default solver's converged contact displacements (they agree with Kratos)."""
    return _contact_displacements(_run(TAYLOR, lambda s: None))


@pytest.mark.parametrize(
    ("edit", "tolerance"),
    [
        (lambda s: s.AddValue("solving_strategy_settings", {"type": "line_search"}), 1e-6),
        (lambda s: s["contact_settings"].AddValue("simplified_semi_smooth_newton", True), 1e-6),
        (lambda s: s.AddValue("convergence_criterion", "contact_mixed_criterion"), 1e-6),
        (lambda s: s.AddValue("convergence_criterion", "contact_and_criterion"), 1e-6),
        # Accepted; the step converges, so nothing is cut.
        (lambda s: s["contact_settings"].AddValue("adaptative_strategy", True), 1e-12),
        # One residual over all DoFs at 1e-4: the Newton loop stops one iteration earlier.
        (lambda s: s.AddValue("convergence_criterion", "residual_criterion"), 1e-5),
    ],
    ids=[
        "line_search",
        "simplified_semi_smooth",
        "mixed",
        "and",
        "adaptative",
        "structural_residual",
    ],
)
def test_solver_variants_reach_the_same_solution(edit, tolerance, default_solution) -> None:
    analysis = _run(TAYLOR, edit)
    steps = analysis.reporter.steps
    assert steps and all(step.converged for step in steps)
    ours = _contact_displacements(analysis)
    scale = max(abs(v) for pair in default_solution.values() for v in pair)
    worst = max(
        abs(a - b) / scale
        for node, pair in default_solution.items()
        for a, b in zip(ours[node], pair, strict=True)
    )
    assert worst < tolerance  # the converged state does not depend on the solver path


def test_components_use_the_condensing_solver() -> None:
    def components(solver: Parameters) -> None:
        solver["contact_settings"].AddValue("mortar_type", "ALMContactFrictionlessComponents")

    path = CASES_DIR / f"{TAYLOR}_parameters.json"
    parameters = Parameters.from_file(path)
    parameters.AddValue("output_processes", {})
    parameters["processes"].AddValue("json_check_process", [])
    components(parameters["solver_settings"])
    parameters["processes"]["contact_process_list"][0]["Parameters"].AddValue(
        "contact_type", "FrictionlessComponents"
    )
    analysis = StructuralMechanicsAnalysis(
        ca.Model(), parameters, base_dir=path.parent, reporter=Reporter(quiet=True)
    )
    analysis.Run()
    condensing = analysis._GetSolver()._GetLinearSolver()
    assert isinstance(condensing, ca.StaticCondensationSolver)  # "auto": too small to condense
    assert not condensing.LastSolveWasCondensed()
    solver = condensing.InnerSolver()
    assert isinstance(solver, ca.MixedULMLinearSolver)
    assert solver.LastSolveWasCondensed()
    assert solver.LastCondensedMultipliers() > 0


def _solver_settings(forced: dict[str, bool]) -> Parameters:
    """The Taylor patch test's solver settings with the forced keys removed, then ``forced``."""
    settings = Parameters.from_file(CASES_DIR / f"{TAYLOR}_parameters.json")["solver_settings"]
    for key in ("reform_dofs_at_each_step", "clear_storage"):
        settings.RemoveValue(key)
    for key, value in forced.items():
        settings.AddValue(key, value)
    return settings


@pytest.mark.parametrize(
    ("forced", "named"),
    [
        (
            {"reform_dofs_at_each_step": False, "clear_storage": False},
            ["reform_dofs_at_each_step", "clear_storage"],
        ),
        ({"reform_dofs_at_each_step": False}, ["reform_dofs_at_each_step"]),
        ({"clear_storage": False, "reform_dofs_at_each_step": True}, ["clear_storage"]),
        ({"reform_dofs_at_each_step": True, "clear_storage": True}, []),
        ({}, []),
    ],
    ids=["both_false", "reform_false", "clear_false", "both_true", "not_given"],
)
def test_forced_dof_settings_warn_only_when_the_user_said_false(
    forced: dict[str, bool], named: list[str], caplog: pytest.LogCaptureFixture
) -> None:
    from contact_app.analysis.paths import PathResolver
    from contact_app.analysis.solvers.solver_wrapper import CreateSolverByParameters

    settings = _solver_settings(forced)
    with caplog.at_level(logging.WARNING, logger="contact_app"):
        CreateSolverByParameters(ca.Model(), settings, paths=PathResolver(CASES_DIR))
    # The contact pairs change the DoF set between steps: both are true whatever the file said.
    assert settings["reform_dofs_at_each_step"].GetBool()
    assert settings["clear_storage"].GetBool()
    # The case file's legacy keys (block_builder, line_search) have warnings of their own.
    warnings = [
        r.getMessage()
        for r in caplog.records
        if r.levelno >= logging.WARNING
        and ("reform_dofs_at_each_step" in r.getMessage() or "clear_storage" in r.getMessage())
    ]
    if not named:
        assert warnings == []
        return
    assert len(warnings) == 1
    message = warnings[0]
    assert "solver_settings" in message and "change between steps" in message
    for key in ("reform_dofs_at_each_step", "clear_storage"):
        assert (key in message) == (key in named)
