"""Convergence criteria by name: structural names, contact names, unknown names."""

from __future__ import annotations

from typing import Any

import pytest

import contact_app as ca
from contact_app.analysis.solvers.convergence_criteria_factory import CreateConvergenceCriterion
from contact_app.parameters import Parameters


def _settings(name: str) -> Parameters:
    settings: dict[str, Any] = {
        "convergence_criterion": name,
        "echo_level": 0,
        "displacement_relative_tolerance": 1e-4,
        "displacement_absolute_tolerance": 1e-9,
        "residual_relative_tolerance": 1e-4,
        "residual_absolute_tolerance": 1e-9,
    }
    return Parameters(settings, source="case.json", path=("solver_settings",))


@pytest.mark.parametrize(
    ("name", "kind", "residual", "displacement"),
    [
        ("residual_criterion", ca.ResidualCriteria, True, False),
        ("displacement_criterion", ca.DisplacementCriteria, False, True),
        ("and_criterion", ca.CompositeCriteria, True, True),
        ("or_criterion", ca.CompositeCriteria, True, True),
    ],
)
def test_structural_names(name: str, kind: type, residual: bool, displacement: bool) -> None:
    created = CreateConvergenceCriterion(_settings(name))
    assert isinstance(created.criterion, kind)
    assert (created.residual is not None) == residual
    assert (created.displacement is not None) == displacement


@pytest.mark.parametrize("name", ["contact_residual_criterion", "contact_mixed_criterion"])
def test_contact_names_need_the_contact_solvers(name: str) -> None:
    with pytest.raises(ca.ConfigurationError, match="without contact solver"):
        CreateConvergenceCriterion(_settings(name))


def test_unknown_name_suggests_the_closest() -> None:
    with pytest.raises(ca.InputError, match='did you mean "and_criterion"') as failure:
        CreateConvergenceCriterion(_settings("and_criterio"))
    assert "case.json › solver_settings › convergence_criterion" in str(failure.value)
