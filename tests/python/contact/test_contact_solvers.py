"""Contact solver options beyond the reference cases' defaults."""

from __future__ import annotations

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
    solver = analysis._GetSolver()._GetLinearSolver()
    assert isinstance(solver, ca.MixedULMLinearSolver)
    assert solver.LastSolveWasCondensed()
    assert solver.LastCondensedMultipliers() > 0
