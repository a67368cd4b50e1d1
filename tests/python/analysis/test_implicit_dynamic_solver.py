"""Implicit dynamic solver: extra defaults, schemes, Rayleigh values, variables and DoFs."""

from __future__ import annotations

from typing import Any

import pytest
from analysis_cases import solver_settings

import contact_app as ca
from contact_app.analysis.solvers import ImplicitMechanicalSolver
from contact_app.parameters import Parameters


def _solver(**changes: Any) -> ImplicitMechanicalSolver:
    settings = solver_settings("Dynamic", 2, 0.1, **changes)
    return ImplicitMechanicalSolver(ca.Model(), Parameters(settings, source="case.json"))


def test_dynamic_defaults() -> None:
    settings = _solver().settings
    assert settings["time_integration_method"].GetString() == "implicit"
    assert settings["scheme_type"].GetString() == "bossak"
    assert settings["damp_factor_m"].GetDouble() == -0.3
    assert settings["newmark_beta"].GetDouble() == 0.25
    assert settings["rayleigh_alpha"].GetDouble() == 0.0
    assert settings["rayleigh_beta"].GetDouble() == 0.0


def test_rayleigh_values_go_to_the_process_info_with_the_scheme() -> None:
    solver = _solver(rayleigh_alpha=0.5, rayleigh_beta=0.01)
    solver._GetScheme()
    info = solver.main_model_part.ProcessInfo
    assert (info[ca.RAYLEIGH_ALPHA], info[ca.RAYLEIGH_BETA]) == (0.5, 0.01)


def test_newmark_is_bossak_without_numerical_damping() -> None:
    assert _solver(scheme_type="newmark", damp_factor_m=-0.2)._SchemeParameters() == (0.0, 0.25)
    assert _solver()._SchemeParameters() == (-0.3, 0.25)


@pytest.mark.parametrize(
    ("changes", "error", "message"),
    [
        ({"scheme_type": "bosak"}, ca.InputError, 'did you mean "bossak"'),
        ({"scheme_type": "bdf2"}, ca.ConfigurationError, 'the "bdf2" scheme'),
        ({"scheme_type": "pseudo_static"}, ca.ConfigurationError, "pseudo_static"),
        ({"damp_factor_m": -0.8}, ca.InputError, "damp_factor_m"),
        ({"newmark_beta": -0.1}, ca.InputError, "newmark_beta"),
    ],
)
def test_scheme_errors_are_found_at_construction(
    changes: dict[str, Any], error: type[Exception], message: str
) -> None:
    with pytest.raises(error, match=message):
        _solver(**changes)


def test_velocity_and_acceleration_are_variables_and_dofs() -> None:
    solver = _solver()
    solver.AddVariables()
    part = solver.main_model_part
    assert part.HasNodalSolutionStepVariable(ca.VELOCITY)
    assert part.HasNodalSolutionStepVariable(ca.ACCELERATION)
    part.CreateNewNode(1, 0.0, 0.0, 0.0)
    solver.AddDofs()
    node = part.GetNode(1)
    assert node.HasDofFor(ca.ACCELERATION_X) and node.HasDofFor(ca.VELOCITY_Y)
    assert node.HasDofFor(ca.DISPLACEMENT_Z)
