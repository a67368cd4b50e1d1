"""``penalty_contact_process``: pure-penalty mortar contact (Kratos ``PenaltyContactProcess``).

The ALM process without multipliers (``docs/input_layer.md`` §4): the same keys with other
defaults (``advance_ALM_parameters.penalty`` 1e16, ``max_gap_factor`` 5e-4, ``tangent_factor``
1e-3), condition stems ``Penalty[NV]Frictionless|Frictional[Axisym]MortarContact``, no scale
factor, and the automatic penalty ε = 1e4 · stiffness_factor · E / h (the reference's factor).
"""

from __future__ import annotations

import sys
from typing import Any

import contact_app as ca
from contact_app.parameters import Parameters

from .alm_contact_process import ALMContactProcess, alm_defaults

#: Factor of the automatic penalty over the ALM estimate E/h (the reference's choice).
AUTOMATIC_PENALTY_FACTOR = 1.0e4
#: Penalty used when the automatic or manual one is zero.
FALLBACK_PENALTY = 1.0e16


def penalty_defaults() -> dict[str, Any]:
    """Every key of the penalty process with its default."""
    defaults = alm_defaults()
    defaults["tangent_factor"] = 1.0e-2
    defaults["advance_ALM_parameters"]["penalty"] = 1.0e16
    defaults["advance_ALM_parameters"]["max_gap_factor"] = 5.0e-4
    return defaults


def Factory(settings: Parameters, model: ca.Model) -> PenaltyContactProcess:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return PenaltyContactProcess(model, settings["Parameters"])


class PenaltyContactProcess(ALMContactProcess):
    """Penalty mortar contact between the pairs of interface parts (see ALMContactProcess)."""

    process_name = "penalty_contact_process"
    method = "Penalty"

    @classmethod
    def _defaults(cls) -> dict[str, Any]:
        return penalty_defaults()

    def _initialize_problem_parameters(self) -> None:
        info = self.main_model_part.ProcessInfo
        alm = self.settings["advance_ALM_parameters"]
        if alm["manual_ALM"].GetBool():
            info[ca.INITIAL_PENALTY] = alm["penalty"].GetDouble()
        else:
            self._estimate_penalty(alm)
            info[ca.INITIAL_PENALTY] = AUTOMATIC_PENALTY_FACTOR * info[ca.INITIAL_PENALTY]
        if info[ca.INITIAL_PENALTY] < sys.float_info.epsilon:
            info[ca.INITIAL_PENALTY] = FALLBACK_PENALTY
        info[ca.SCALE_FACTOR] = 1.0
