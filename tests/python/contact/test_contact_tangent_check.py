"""The contact strategy's refresh in the directional tangent check (CheckTangentAlong).

At every perturbed state the check recomputes what a contact iteration refreshes before its
build: the pairs' nodal sums (weighted gaps, slips, areas) and, with normals that follow the
iterate, the nodal and pair normals (docs/theory/structural.md §6 "Checking the assembled
tangent"). On the non-matching 2D stick-slip block in slip with the penalty frictional family,
whose nodal-penalty, slip-direction and normal couplings make the assembled tangent exact
(docs/theory/mortar.md §7), A v must equal the central differences; measured ≤ 1e-8 relative at
every iteration of the first slip step.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
from test_frictional_stick_slip import (
    NON_MATCHING,
    SLIP_STEPS,
    STICK_STEP,
    _parameters,
    _write_case,
)

import contact_app as ca
from contact_app.analysis import StructuralMechanicsAnalysis
from contact_app.analysis.reporting import Reporter
from contact_app.parameters import Parameters


class _CheckedAnalysis(StructuralMechanicsAnalysis):
    """Checks the tangent after every Newton iteration of the steps in ``steps``.

    ``errors`` holds (sets unchanged by the last update, |A v - fd| / |fd|) per iteration: only with
    unchanged sets does the tangent differentiate the normals (NormalsInTangent); on this flat
    interface the held rotation is below 1e-8 of the whole residual's change.
    """

    def __init__(self, *args, steps: tuple[int, ...], **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.steps = steps
        self.errors: list[tuple[bool, float]] = []

    def _TrySolveStep(self):  # noqa: N802 - Kratos name
        strategy = self._GetSolver().GetSolutionStrategy()
        mp = self._GetSolver().main_model_part
        step = mp.ProcessInfo[ca.STEP]
        if step not in self.steps:
            return super()._TrySolveStep()

        def check() -> None:
            info = mp.ProcessInfo
            settled = info[ca.ACTIVE_SET_CONVERGED] and info[ca.SLIP_SET_CONVERGED]
            dofs = list(strategy.GetBuilderAndSolver().GetDofSet())
            direction = np.random.default_rng(3).standard_normal(len(dofs))
            # A perturbation of 1e-9 against slides of 1e-6: inside every kink of the contact laws.
            tangent, central, _ = strategy.CheckTangentAlong(direction * 1e-3, 1e-6)
            error = float(np.linalg.norm(tangent - central) / np.linalg.norm(central))
            self.errors.append((settled, error))

        strategy.SetIterationObserver(check)
        try:
            return super()._TrySolveStep()
        finally:
            strategy.SetIterationObserver(None)


def _checked_run(directory: Path, step: int) -> _CheckedAnalysis:
    """The non-matching penalty frictional block up to ``step``, its tangent checked there."""
    _write_case(directory, NON_MATCHING, 0.3)
    parameters = _parameters(directory, "PenaltyContactFrictional", 2)
    parameters["problem_data"]["end_time"] = float(step)
    analysis = _CheckedAnalysis(
        ca.Model(),
        Parameters(json.dumps(parameters)),
        reporter=Reporter(quiet=True),
        steps=(step,),
    )
    analysis.Run()
    mp = analysis.model.GetModelPart("Structure")
    assert mp.ProcessInfo[ca.CONSIDER_NORMAL_VARIATION] != 0  # the normals follow the iterate
    return analysis


def test_penalty_frictional_slip_tangent_is_exact_on_the_whole_model(tmp_path: Path) -> None:
    analysis = _checked_run(tmp_path, SLIP_STEPS[0])
    contact = analysis.model.GetModelPart("Structure").GetSubModelPart("Contact")
    assert any(n.Is(ca.SLIP) for n in contact.Nodes)
    print(f"penalty frictional slip step: (sets settled, |Av - fd| / |fd|) {analysis.errors}")
    assert any(unchanged for unchanged, _ in analysis.errors)
    assert max(error for _, error in analysis.errors) < 1e-7


def test_penalty_frictional_stick_tangent_is_exact_on_the_whole_model(tmp_path: Path) -> None:
    """Stick: the cross-pair blocks of the nodal stick traction come from NodalPenaltyCoupling.

    A sticking node pushes every pair with kappa eps (e + T), T the slip all its pairs transmit,
    so each pair's residual reads the other pairs' unknowns through T (docs/theory/mortar.md §8).
    """
    analysis = _checked_run(tmp_path, STICK_STEP)
    contact = analysis.model.GetModelPart("Structure").GetSubModelPart("Contact")
    sticking = [n for n in contact.Nodes if n.Is(ca.ACTIVE) and not n.Is(ca.SLIP)]
    assert sticking
    print(f"penalty frictional stick step: (sets settled, |Av - fd| / |fd|) {analysis.errors}")
    assert any(unchanged for unchanged, _ in analysis.errors)
    assert max(error for _, error in analysis.errors) < 1e-7
