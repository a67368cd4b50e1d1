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
from ..parameters import Parameters
from ._assignments import ConditionAssignment, ConditionAssignmentProcess, read_target
from ._utilities import COMMON_DEFAULTS, SCALAR_KINDS, TARGET_KEYS, scalar_value_of, validate
from .interval import Interval
from .process import Process

DEFAULTS = {
    **COMMON_DEFAULTS,
    "value": None,
    "local_axes": {},
}


def Factory(settings: Parameters, model: Model) -> Process:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return AssignScalarVariableToConditionsProcess(model, settings["Parameters"])


class AssignScalarVariableToConditionsProcess(ConditionAssignmentProcess):
    """Set a scalar condition value in the steps of the interval.

    Args:
        model: the model holding the model part.
        settings: the ``Parameters`` block.

    Raises:
        InputError: unknown key, model part or variable; a vector variable; a bad value or interval.
    """

    def __init__(self, model: Model, settings: Parameters) -> None:
        validate(settings, DEFAULTS, TARGET_KEYS, "assign_scalar_variable_to_conditions_process")
        model_part, variable, _ = read_target(model, settings, SCALAR_KINDS, historical=False)
        value = scalar_value_of(settings)
        interval = Interval.from_parameters(settings["interval"])
        super().__init__([ConditionAssignment(model_part, variable, value, interval)])
