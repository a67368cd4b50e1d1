"""Convergence criteria of the contact solvers (Kratos ``contact_convergence_criteria_factory``).

See ``docs/theory/contact_strategies.md`` §4 and ``docs/input_layer.md`` §2. The user's criterion
judges the unknowns; it is combined (AND) with the mortar criterion of the ``mortar_type``, which
updates the active (and stick/slip) set after every iteration and reports convergence when the set
no longer changes.

| ``convergence_criterion`` | displacement block | multiplier block |
|---|---|---|
| ``contact_displacement_criterion`` | increment | increment |
| ``contact_residual_criterion`` | residual | residual |
| ``contact_mixed_criterion`` | residual | increment |
| ``contact_and_criterion`` / ``contact_or_criterion`` | residual AND/OR increment (both blocks) | |
| a structural name | the structural criterion | not judged separately |

Deviation: the reference leaves the penalty families without the mortar criterion when a
structural criterion name is used, so their active set would never be updated; here every
formulation gets it.
"""

from __future__ import annotations

from typing import Any

import contact_app as ca
from contact_app._core import MortarType
from contact_app.analysis.solvers.convergence_criteria_factory import (
    CONTACT_CRITERIA,
    ConvergenceCriterion,
    CreateConvergenceCriterion,
)
from contact_app.parameters import Parameters


class BlockView:
    """One block of a contact criterion seen as a (ratio, absolute) criterion by the reporter."""

    def __init__(self, criterion: Any, block: int) -> None:
        self.criterion = criterion
        self.block = block

    def LastRatio(self) -> float:
        """Ratio of the block in the last check."""
        return float(self.criterion.LastRatio(self.block))

    def LastAbsolute(self) -> float:
        """Absolute norm of the block in the last check."""
        return float(self.criterion.LastAbsolute(self.block))


def _tolerances(settings: Parameters, measure: str, frictional: bool) -> Any:
    """Block tolerances for ``measure`` ("displacement" or "residual")."""
    contact = settings["contact_settings"]
    tolerances = ca.ContactCriteriaTolerances()
    tolerances.displacement_relative = settings[f"{measure}_relative_tolerance"].GetDouble()
    tolerances.displacement_absolute = settings[f"{measure}_absolute_tolerance"].GetDouble()
    tolerances.lm_relative = contact[f"contact_{measure}_relative_tolerance"].GetDouble()
    tolerances.lm_absolute = contact[f"contact_{measure}_absolute_tolerance"].GetDouble()
    for kind in ("stick", "slip"):
        for bound in ("relative", "absolute"):
            key = f"frictional_{kind}_contact_{measure}_{bound}_tolerance"
            setattr(tolerances, f"{kind}_{bound}", contact[key].GetDouble())
    tolerances.ratio_normal_tangent_threshold = contact[
        "ratio_normal_tangent_threshold"
    ].GetDouble()
    tolerances.ensure_contact = contact["ensure_contact"].GetBool()
    tolerances.split_frictional = frictional
    return tolerances


def CreateContactConvergenceCriterion(
    settings: Parameters, mortar_type: MortarType
) -> ConvergenceCriterion:
    """The criterion of a contact solver: the user's one AND the mortar (active-set) one.

    Args:
        settings: ``solver_settings`` with ``contact_settings`` (defaults assigned).
        mortar_type: the validated formulation (its criterion family, friction, pure slip).
    """
    name = settings["convergence_criterion"].GetString()
    echo_level = settings["echo_level"].GetInt()
    mortar = ca.BaseMortarConvergenceCriteria(
        mortar_type.criterion, pure_slip=mortar_type.pure_slip
    )
    mortar.SetEchoLevel(echo_level)
    if name not in CONTACT_CRITERIA:
        structural = CreateConvergenceCriterion(settings)
        combined = ca.AndCriteria(structural.criterion, mortar)
        return ConvergenceCriterion(
            combined, residual=structural.residual, displacement=structural.displacement
        )
    contact = settings["contact_settings"]
    frictional = mortar_type.frictional and contact["frictional_decomposed"].GetBool()
    increment, residual = ca.ContactBlockMeasure.INCREMENT, ca.ContactBlockMeasure.RESIDUAL

    def make(disp: Any, lm: Any, measure: str) -> Any:
        criterion = ca.DisplacementLagrangeMultiplierContactCriteria(
            disp, lm, _tolerances(settings, measure, frictional)
        )
        criterion.SetEchoLevel(echo_level)
        return criterion

    if name == "contact_displacement_criterion":
        user = make(increment, increment, "displacement")
        views: dict[str, Any] = {"displacement": BlockView(user, 0)}
    elif name == "contact_residual_criterion":
        user = make(residual, residual, "residual")
        views = {"residual": BlockView(user, 0)}
    elif name == "contact_mixed_criterion":
        user = make(residual, increment, "residual")
        views = {"residual": BlockView(user, 0)}
    else:
        by_residual = make(residual, residual, "residual")
        by_increment = make(increment, increment, "displacement")
        combine = ca.AndCriteria if name == "contact_and_criterion" else ca.OrCriteria
        user = combine(by_residual, by_increment)
        views = {"residual": BlockView(by_residual, 0), "displacement": BlockView(by_increment, 0)}
    combined = ca.AndCriteria(user, mortar)
    combined.SetEchoLevel(echo_level)
    return ConvergenceCriterion(combined, **views)
