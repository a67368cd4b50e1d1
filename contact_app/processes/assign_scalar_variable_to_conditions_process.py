"""``assign_scalar_variable_to_conditions_process``.

Set a double or component variable as the value of every condition of a model part (e.g. a pressure
read by load conditions).

Keys: ``model_part_name`` and ``variable_name`` (required), ``value`` (number or function string;
default 0.0), ``interval`` ([0, "End"]), ``local_axes`` ({}), ``mesh_id`` (legacy, 0), ``help``.

In every step whose TIME is in the interval (``ExecuteInitializeSolutionStep`` only) each condition
gets ``SetValue(variable, value)``; a spatial function is evaluated at the condition's centre (x, y,
z from the current, X, Y, Z from the initial coordinates of its nodes — Kratos passes X = Y = Z = 0
here). Values are kept after the interval.
"""

from __future__ import annotations

from .._core import Model
from ..model_part_lookup import get_model_part
from ..parameters import Parameters
from ._assignments import ConditionAssignment
from ._utilities import SCALAR_KINDS, LocalAxes, ScalarValue, get_variable, validate
from .interval import Interval
from .process import Process

DEFAULTS = {
    "help": "",
    "mesh_id": 0,
    "model_part_name": "",
    "variable_name": "",
    "interval": [0.0, 1e30],
    "value": None,
    "local_axes": {},
}


def Factory(settings: Parameters, model: Model) -> Process:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return AssignScalarVariableToConditionsProcess(model, settings["Parameters"])


class AssignScalarVariableToConditionsProcess(Process):
    """Set a scalar condition value in the steps of the interval.

    Args:
        model: the model holding the model part.
        settings: the ``Parameters`` block.

    Raises:
        InputError: unknown key, model part or variable; a vector variable; a bad value or interval.
    """

    def __init__(self, model: Model, settings: Parameters) -> None:
        validate(
            settings,
            DEFAULTS,
            ("model_part_name", "variable_name"),
            "assign_scalar_variable_to_conditions_process",
        )
        if settings["value"].IsNull():
            settings["value"].SetDouble(0.0)
        model_part = get_model_part(
            model, settings["model_part_name"].GetString(), settings.Where("model_part_name")
        )
        variable = get_variable(
            settings["variable_name"].GetString(), settings.Where("variable_name"), SCALAR_KINDS
        )
        local_axes = LocalAxes.from_parameters(settings["local_axes"])
        self.assignment = ConditionAssignment(
            model_part,
            variable,
            ScalarValue.from_parameters(settings["value"], local_axes),
            Interval.from_parameters(settings["interval"]),
        )

    def ExecuteInitializeSolutionStep(self) -> None:
        """Set the condition values if TIME is in the interval."""
        self.assignment.apply()
