"""``assign_scalar_variable_process``.

Assign (and by default fix) a double or component variable on the nodes of a model part.

Keys: ``model_part_name`` and ``variable_name`` (required), ``value`` (number, function string of
t, x, y, z, X, Y, Z, or ``{"name": "csv_table", ...}``; default 0.0), ``constrained`` (true),
``interval`` ([0, "End"]), ``local_axes`` ({}), ``mesh_id`` (legacy, 0), ``help``.

In every step whose TIME is in the interval: fix the DoF on every node (if constrained) and write
the historical value; at the end of that step the DoF is freed again. ``ExecuteBeforeSolutionLoop``
also applies the value, so it holds at the start time.
"""

from __future__ import annotations

from .._core import Model
from ..parameters import Parameters
from ._assignments import NodalAssignment, NodalAssignmentProcess, read_target
from ._utilities import COMMON_DEFAULTS, SCALAR_KINDS, TARGET_KEYS, scalar_value_of, validate
from .interval import Interval
from .process import Process

DEFAULTS = {
    **COMMON_DEFAULTS,
    "constrained": True,
    "value": None,
    "local_axes": {},
}


def Factory(settings: Parameters, model: Model) -> Process:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return AssignScalarVariableProcess(model, settings["Parameters"])


class AssignScalarVariableProcess(NodalAssignmentProcess):
    """Assign a scalar nodal value, fixed from step start to step end.

    Args:
        model: the model holding the model part.
        settings: the ``Parameters`` block (validated here; missing keys get their defaults).

    Raises:
        InputError: unknown key, unknown model part or variable, a vector variable, a variable the
            solver does not store historically, or a bad value or interval.
    """

    def __init__(self, model: Model, settings: Parameters) -> None:
        validate(settings, DEFAULTS, TARGET_KEYS, "assign_scalar_variable_process")
        model_part, variable, _ = read_target(model, settings, SCALAR_KINDS, historical=True)
        value = scalar_value_of(settings)
        interval = Interval.from_parameters(settings["interval"])
        constrained = settings["constrained"].GetBool()
        super().__init__([NodalAssignment(model_part, variable, value, interval, constrained)])
