"""Static structural solver (Kratos ``structural_mechanics_static_solver``)."""

from __future__ import annotations

from typing import Any

import contact_app as ca

from ...parameters import Parameters
from ..paths import PathResolver
from .mechanical_solver import MechanicalSolver


class StaticMechanicalSolver(MechanicalSolver):
    """Static solver: incremental-update static scheme (u += Δx on free DoFs, no inertia)."""

    def _CreateScheme(self) -> Any:
        return ca.ResidualBasedIncrementalUpdateStaticScheme()


def CreateSolver(
    model: ca.Model, custom_settings: Parameters, paths: PathResolver | None = None
) -> StaticMechanicalSolver:
    """Create the static solver (Kratos module-level factory)."""
    return StaticMechanicalSolver(model, custom_settings, paths)
