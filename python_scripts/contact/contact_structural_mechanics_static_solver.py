"""Static contact solver (Kratos ``contact_structural_mechanics_static_solver``).

The static structural solver plus ``contact_settings``: the variables and DoFs of the
``mortar_type``, the contact convergence criteria and the contact Newton strategy.
"""

from __future__ import annotations

import contact_app as ca
from contact_app.analysis.paths import PathResolver
from contact_app.analysis.solvers.static_solver import StaticMechanicalSolver
from contact_app.parameters import Parameters

from .auxiliary_methods_solvers import ContactSolverMixin


class ContactStaticMechanicalSolver(ContactSolverMixin, StaticMechanicalSolver):
    """Static mortar contact solver."""


def CreateSolver(
    model: ca.Model, custom_settings: Parameters, paths: PathResolver | None = None
) -> ContactStaticMechanicalSolver:
    """Create the static contact solver (Kratos module-level factory)."""
    return ContactStaticMechanicalSolver(model, custom_settings, paths)
