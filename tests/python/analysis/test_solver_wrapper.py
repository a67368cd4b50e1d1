"""Solver selection by solver_type, and the contact / unsupported solver messages."""

from __future__ import annotations

from typing import Any

import pytest
from analysis_cases import solver_settings

import contact_app as ca
from contact_app.analysis.solvers import (
    CreateSolver,
    CreateSolverByParameters,
    ImplicitMechanicalSolver,
    StaticMechanicalSolver,
)
from contact_app.parameters import Parameters


def _settings(**changes: Any) -> Parameters:
    settings = solver_settings(None, 3, 1.0, **changes)
    return Parameters(settings, source="case.json", path=("solver_settings",))


@pytest.mark.parametrize(
    ("solver_type", "cls"),
    [
        ("Static", StaticMechanicalSolver),
        ("static", StaticMechanicalSolver),
        ("STATIC", StaticMechanicalSolver),
        ("Dynamic", ImplicitMechanicalSolver),
        ("dynamic", ImplicitMechanicalSolver),
    ],
)
def test_solver_type_selects_the_solver_in_any_case(solver_type: str, cls: type) -> None:
    solver = CreateSolverByParameters(ca.Model(), _settings(solver_type=solver_type))
    assert type(solver) is cls


def test_create_solver_reads_the_whole_project_parameters() -> None:
    parameters = Parameters(
        {
            "problem_data": {"parallel_type": "OpenMP"},
            "solver_settings": _settings(solver_type="Dynamic").GetValue(),
        }
    )
    assert isinstance(CreateSolver(ca.Model(), parameters), ImplicitMechanicalSolver)


@pytest.mark.parametrize(
    ("changes", "error", "message"),
    [
        ({}, ca.InputError, 'missing required key "solver_type"'),
        ({"solver_type": "Statik"}, ca.InputError, 'did you mean "static"'),
        ({"solver_type": "eigen_value"}, ca.ConfigurationError, 'the "eigen_value" solver'),
        (
            {"solver_type": "Dynamic", "time_integration_method": "explicit"},
            ca.ConfigurationError,
            "explicit",
        ),
        (
            {"solver_type": "Dynamic", "time_integration_method": "implicitt"},
            ca.InputError,
            "time_integration_method",
        ),
        (
            {"solver_type": "Static", "contact_settings": {}},
            ca.InputError,
            "mortar_type is empty",
        ),
        (
            {"solver_type": "Dynamic", "mpc_contact_settings": {"contact_type": "Frictionles"}},
            ca.InputError,
            "Frictionless",
        ),
        (
            {"solver_type": "Static", "time_integration_method": "implicit"},
            ca.InputError,
            'unknown key "time_integration_method"',
        ),
    ],
)
def test_selection_errors(changes: dict[str, Any], error: type[Exception], message: str) -> None:
    with pytest.raises(error, match=message):
        CreateSolverByParameters(ca.Model(), _settings(**changes))


def test_mpi_is_not_supported() -> None:
    with pytest.raises(ca.ConfigurationError, match="MPI"):
        CreateSolverByParameters(ca.Model(), _settings(solver_type="Static"), "MPI")


def test_an_existing_model_part_is_reused() -> None:
    model = ca.Model()
    part = model.CreateModelPart("Structure")
    solver = CreateSolverByParameters(model, _settings(solver_type="Static"))
    assert solver.main_model_part == part
