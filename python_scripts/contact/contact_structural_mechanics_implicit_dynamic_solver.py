"""Implicit dynamic contact solver.

Kratos ``contact_structural_mechanics_implicit_dynamic_solver``.

The implicit (Bossak / Newmark) structural solver plus ``contact_settings``, as the static one.
"""

from __future__ import annotations

import contact_app as ca
from contact_app.analysis.paths import PathResolver
from contact_app.analysis.solvers.implicit_dynamic_solver import ImplicitMechanicalSolver
from contact_app.parameters import Parameters

from .auxiliary_methods_solvers import ContactSolverMixin


class ContactImplicitMechanicalSolver(ContactSolverMixin, ImplicitMechanicalSolver):
    """Implicit dynamic mortar contact solver."""


def CreateSolver(
    model: ca.Model, custom_settings: Parameters, paths: PathResolver | None = None
) -> ContactImplicitMechanicalSolver:
    """Create the implicit dynamic contact solver (Kratos module-level factory)."""
    return ContactImplicitMechanicalSolver(model, custom_settings, paths)
