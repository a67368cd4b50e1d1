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
from ..model_part_lookup import get_model_part
from ..parameters import Parameters
from ._assignments import NodalAssignment
from ._utilities import (
    SCALAR_KINDS,
    LocalAxes,
    ScalarValue,
    check_historical,
    get_variable,
    validate,
)
from .interval import Interval
from .process import Process

DEFAULTS = {
    "help": "",
    "mesh_id": 0,
    "model_part_name": "",
    "variable_name": "",
    "interval": [0.0, 1e30],
    "constrained": True,
    "value": None,
    "local_axes": {},
}


def Factory(settings: Parameters, model: Model) -> Process:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return AssignScalarVariableProcess(model, settings["Parameters"])


class AssignScalarVariableProcess(Process):
    """Assign a scalar nodal value, fixed from step start to step end.

    Args:
        model: the model holding the model part.
        settings: the ``Parameters`` block (validated here; missing keys get their defaults).

    Raises:
        InputError: unknown key, unknown model part or variable, a vector variable, a variable the
            solver does not store historically, or a bad value or interval.
    """

    def __init__(self, model: Model, settings: Parameters) -> None:
        validate(
            settings,
            DEFAULTS,
            ("model_part_name", "variable_name"),
            "assign_scalar_variable_process",
        )
        if settings["value"].IsNull():
            settings["value"].SetDouble(0.0)
        model_part = get_model_part(
            model, settings["model_part_name"].GetString(), settings.Where("model_part_name")
        )
        where = settings.Where("variable_name")
        variable = get_variable(settings["variable_name"].GetString(), where, SCALAR_KINDS)
        check_historical(model_part, variable, where)
        local_axes = LocalAxes.from_parameters(settings["local_axes"])
        self.assignment = NodalAssignment(
            model_part,
            variable,
            ScalarValue.from_parameters(settings["value"], local_axes),
            Interval.from_parameters(settings["interval"]),
            settings["constrained"].GetBool(),
        )

    def ExecuteBeforeSolutionLoop(self) -> None:
        """Apply the value at the start time too."""
        self.ExecuteInitializeSolutionStep()

    def ExecuteInitializeSolutionStep(self) -> None:
        """Fix and assign if TIME is in the interval."""
        self.assignment.apply()

    def ExecuteFinalizeSolutionStep(self) -> None:
        """Free the DoFs fixed in this step."""
        self.assignment.release()
