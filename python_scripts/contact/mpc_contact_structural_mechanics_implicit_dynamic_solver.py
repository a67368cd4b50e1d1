"""Implicit dynamic MPC contact solver.

Kratos ``mpc_contact_structural_mechanics_implicit_dynamic_solver``: the implicit (Bossak /
Newmark) structural solver plus ``mpc_contact_settings``, as the static one.
"""

from __future__ import annotations

import contact_app as ca
from contact_app.analysis.paths import PathResolver
from contact_app.analysis.solvers.implicit_dynamic_solver import ImplicitMechanicalSolver
from contact_app.parameters import Parameters

from .mpc_auxiliary_methods_solvers import MPCContactSolverMixin


class MPCContactImplicitMechanicalSolver(MPCContactSolverMixin, ImplicitMechanicalSolver):
    """Implicit dynamic MPC contact solver."""


def CreateSolver(
    model: ca.Model, custom_settings: Parameters, paths: PathResolver | None = None
) -> MPCContactImplicitMechanicalSolver:
    """Create the implicit dynamic MPC contact solver (Kratos module-level factory)."""
    return MPCContactImplicitMechanicalSolver(model, custom_settings, paths)
