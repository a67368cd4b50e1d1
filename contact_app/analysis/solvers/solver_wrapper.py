"""Solver selection by ``solver_type`` (Kratos ``python_solvers_wrapper_structural``).

| ``solver_type`` (any case) | ``time_integration_method`` | module |
|---|---|---|
| ``static`` | – | :mod:`.static_solver` |
| ``dynamic`` | ``implicit`` (default) | :mod:`.implicit_dynamic_solver` |

With ``contact_settings`` (or ``mpc_contact_settings``) in the solver settings the module is
``contact_app.contact.contact_<base>`` (``mpc_contact_<base>``), where ``<base>`` is
``structural_mechanics_static_solver`` or ``structural_mechanics_implicit_dynamic_solver`` as in
Kratos. Each module has ``CreateSolver(model, settings, paths)`` returning a
:class:`~.mechanical_solver.MechanicalSolver` subclass, so the contact solvers plug in by adding
those modules.
"""

from __future__ import annotations

import importlib
from types import ModuleType

import contact_app as ca

from ...parameters import Parameters, suggest
from ..paths import PathResolver
from ..validation import error, not_supported
from . import implicit_dynamic_solver, static_solver
from .mechanical_solver import MechanicalSolver

#: Kratos base module per (solver_type, time_integration_method).
BASE_MODULES = {
    ("static", ""): "structural_mechanics_static_solver",
    ("dynamic", "implicit"): "structural_mechanics_implicit_dynamic_solver",
}
STRUCTURAL_MODULES: dict[str, ModuleType] = {
    "structural_mechanics_static_solver": static_solver,
    "structural_mechanics_implicit_dynamic_solver": implicit_dynamic_solver,
}
#: Other Kratos structural solver types, recognised to give a precise message.
OTHER_KRATOS_TYPES = (
    "eigen_value",
    "harmonic_analysis",
    "formfinding",
    "adjoint_static",
    "prebuckling",
)


def _base_module(settings: Parameters) -> str:
    if not settings.Has("solver_type"):
        raise error(
            settings,
            "solver_type",
            'missing required key "solver_type"',
            '"Static" or "Dynamic"',
            'add "solver_type": "Static"',
        )
    written = settings["solver_type"].GetString()
    solver_type = written.lower()
    if solver_type == "static":
        return BASE_MODULES[("static", "")]
    if solver_type == "dynamic":
        method = "implicit"
        if settings.Has("time_integration_method"):
            method = settings["time_integration_method"].GetString()
        if method == "explicit":
            raise not_supported(
                settings, "time_integration_method", "the explicit dynamic solver", 'use "implicit"'
            )
        if method != "implicit":
            raise error(
                settings,
                "time_integration_method",
                f'unknown time_integration_method "{method}"',
                '"implicit" or "explicit"',
            )
        return BASE_MODULES[("dynamic", "implicit")]
    if solver_type in OTHER_KRATOS_TYPES:
        raise not_supported(
            settings, "solver_type", f'the "{written}" solver', 'use "Static" or "Dynamic"'
        )
    raise error(
        settings,
        "solver_type",
        f'unknown solver_type "{written}"',
        '"Static" or "Dynamic" (any case)',
        suggest(solver_type, ["static", "dynamic", *OTHER_KRATOS_TYPES]),
    )


def _contact_module(settings: Parameters, base: str) -> ModuleType:
    key = "contact_settings" if settings.Has("contact_settings") else "mpc_contact_settings"
    prefix = "contact_" if key == "contact_settings" else "mpc_contact_"
    name = f"contact_app.contact.{prefix}{base}"
    try:
        return importlib.import_module(name)
    except ModuleNotFoundError as failure:
        if failure.name is None or not name.startswith(failure.name):
            raise
    raise not_supported(
        settings,
        key,
        f"the contact solver {prefix}{base} ({key})",
        "the contact solvers are static and implicit dynamic (Bossak/Newmark); remove the contact "
        "settings to run the structural problem alone",
    )


def CreateSolverByParameters(
    model: ca.Model,
    solver_settings: Parameters,
    parallelism: str = "OpenMP",
    paths: PathResolver | None = None,
) -> MechanicalSolver:
    """Create the solver that ``solver_settings`` selects.

    Args:
        model: the model.
        solver_settings: the ``solver_settings`` block (validated and completed in place).
        parallelism: ``problem_data.parallel_type``; only "OpenMP" is supported.
        paths: how relative paths resolve.

    Raises:
        InputError: missing or unknown solver_type, invalid settings.
        ConfigurationError: MPI, a solver contact_app does not implement (yet).

    """
    if parallelism != "OpenMP":
        raise ca.ConfigurationError(
            f'parallel_type "{parallelism}" is not supported\n  fix:      use "OpenMP"'
        )
    base = _base_module(solver_settings)
    if solver_settings.Has("contact_settings") or solver_settings.Has("mpc_contact_settings"):
        module = _contact_module(solver_settings, base)
    else:
        module = STRUCTURAL_MODULES[base]
    solver: MechanicalSolver = module.CreateSolver(model, solver_settings, paths)
    return solver


def CreateSolver(
    model: ca.Model, custom_settings: Parameters, paths: PathResolver | None = None
) -> MechanicalSolver:
    """Create the solver from the whole project parameters (solver_settings + problem_data)."""
    parallelism = "OpenMP"
    if custom_settings.Has("problem_data") and custom_settings["problem_data"].Has("parallel_type"):
        parallelism = custom_settings["problem_data"]["parallel_type"].GetString()
    return CreateSolverByParameters(model, custom_settings["solver_settings"], parallelism, paths)
