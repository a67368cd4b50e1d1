"""Static MPC contact solver (Kratos ``mpc_contact_structural_mechanics_static_solver``).

The static structural solver plus ``mpc_contact_settings``: contact through multipoint
constraints, the MPC active-set criterion and the MPC contact Newton strategy.
"""

from __future__ import annotations

import contact_app as ca
from contact_app.analysis.paths import PathResolver
from contact_app.analysis.solvers.static_solver import StaticMechanicalSolver
from contact_app.parameters import Parameters

from .mpc_auxiliary_methods_solvers import MPCContactSolverMixin


class MPCContactStaticMechanicalSolver(MPCContactSolverMixin, StaticMechanicalSolver):
    """Static MPC contact solver."""


def CreateSolver(
    model: ca.Model, custom_settings: Parameters, paths: PathResolver | None = None
) -> MPCContactStaticMechanicalSolver:
    """Create the static MPC contact solver (Kratos module-level factory)."""
    return MPCContactStaticMechanicalSolver(model, custom_settings, paths)
