"""Implicit dynamic structural solver (Kratos ``structural_mechanics_implicit_dynamic_solver``).

Extra settings: ``time_integration_method`` "implicit", ``scheme_type`` "bossak" (or "newmark" =
Bossak with ``damp_factor_m`` = 0), ``damp_factor_m`` -0.3, ``newmark_beta`` 0.25,
``rayleigh_alpha``/``rayleigh_beta`` 0.0 (written to the ProcessInfo; Properties values take
precedence in the elements). ``pseudo_static``, ``backward_euler``/``bdf1..5`` and ``relaxation``
are Kratos schemes that contact_app does not implement yet.
"""

from __future__ import annotations

from typing import Any

import contact_app as ca

from ...parameters import Parameters
from ..paths import PathResolver
from ..validation import choice, not_supported
from .mechanical_solver import MechanicalSolver

SCHEME_TYPES = (
    "bossak",
    "newmark",
    "pseudo_static",
    "backward_euler",
    "bdf1",
    "bdf2",
    "bdf3",
    "bdf4",
    "bdf5",
    "relaxation",
)


class ImplicitMechanicalSolver(MechanicalSolver):
    """Implicit dynamic solver: Bossak or Newmark displacement scheme, VELOCITY/ACCELERATION."""

    @classmethod
    def GetDefaultParameters(cls) -> dict[str, Any]:
        """Base defaults plus the time-integration keys."""
        defaults = super().GetDefaultParameters()
        defaults.update(
            {
                "time_integration_method": "implicit",
                "scheme_type": "bossak",
                "damp_factor_m": -0.3,
                "newmark_beta": 0.25,
                "rayleigh_alpha": 0.0,
                "rayleigh_beta": 0.0,
            }
        )
        return defaults

    def ValidateSettings(self) -> None:
        """Base checks plus the scheme: its name, and its parameters through a trial scheme."""
        super().ValidateSettings()
        settings = self.settings
        method = choice(settings, "time_integration_method", ("implicit", "explicit"))
        if method == "explicit":
            raise not_supported(
                settings, "time_integration_method", "the explicit dynamic solver", 'use "implicit"'
            )
        scheme = choice(settings, "scheme_type", SCHEME_TYPES, "scheme_type")
        if scheme not in ("bossak", "newmark"):
            raise not_supported(
                settings, "scheme_type", f'the "{scheme}" scheme', 'use "bossak" or "newmark"'
            )
        try:
            ca.ResidualBasedBossakDisplacementScheme(*self._SchemeParameters())
        except ca.InputError as failure:
            first, _, rest = str(failure).partition("\n")
            raise ca.InputError(f"{first}\n  where:    {settings.Where()}\n{rest}") from None

    def _SchemeParameters(self) -> tuple[float, float]:
        """(damp_factor_m, newmark_beta) of the scheme; Newmark is Bossak with damp_factor_m = 0."""
        settings = self.settings
        alpha_m = settings["damp_factor_m"].GetDouble()
        if settings["scheme_type"].GetString() == "newmark":
            alpha_m = 0.0
        return alpha_m, settings["newmark_beta"].GetDouble()

    def _CreateScheme(self) -> Any:
        info = self.main_model_part.ProcessInfo
        info[ca.RAYLEIGH_ALPHA] = self.settings["rayleigh_alpha"].GetDouble()
        info[ca.RAYLEIGH_BETA] = self.settings["rayleigh_beta"].GetDouble()
        return ca.ResidualBasedBossakDisplacementScheme(*self._SchemeParameters())

    def _HistoricalVariables(self) -> list[Any]:
        return super()._HistoricalVariables() + [ca.VELOCITY, ca.ACCELERATION]

    def _DofsWithoutReactions(self) -> list[Any]:
        return [
            ca.VELOCITY_X,
            ca.VELOCITY_Y,
            ca.VELOCITY_Z,
            ca.ACCELERATION_X,
            ca.ACCELERATION_Y,
            ca.ACCELERATION_Z,
        ]


def CreateSolver(
    model: ca.Model, custom_settings: Parameters, paths: PathResolver | None = None
) -> ImplicitMechanicalSolver:
    """Create the implicit dynamic solver (Kratos module-level factory)."""
    return ImplicitMechanicalSolver(model, custom_settings, paths)
