"""``assign_vector_variable_to_conditions_process``.

Set components of a 3-vector variable as the value of every condition of a model part (e.g.
LINE_LOAD, SURFACE_LOAD).

Keys: ``model_part_name`` and ``variable_name`` (required; a 3-vector), ``value`` ([v_x, v_y, v_z],
each a number, a function string or null = component untouched; default [0, 0, 0]), ``interval``
([0, "End"]), ``local_axes`` ({}), ``mesh_id`` (legacy, 0), ``help``.

Each non-null component behaves as ``assign_scalar_variable_to_conditions_process`` on
``<VAR>_X/_Y/_Z``.
"""

from __future__ import annotations

from .._core import Model
from ..parameters import Parameters
from ._assignments import ConditionAssignment, ConditionAssignmentProcess, read_target
from ._utilities import COMMON_DEFAULTS, TARGET_KEYS, validate, vector_value_of
from .interval import Interval
from .process import Process

DEFAULTS = {
    **COMMON_DEFAULTS,
    "value": [0.0, 0.0, 0.0],
    "local_axes": {},
}


def Factory(settings: Parameters, model: Model) -> Process:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return AssignVectorVariableToConditionsProcess(model, settings["Parameters"])


class AssignVectorVariableToConditionsProcess(ConditionAssignmentProcess):
    """Set the non-null components of a condition 3-vector in the steps of the interval.

    Args:
        model: the model holding the model part.
        settings: the ``Parameters`` block.

    Raises:
        InputError: unknown key, model part or variable; not a 3-vector; a bad value or interval.
    """

    def __init__(self, model: Model, settings: Parameters) -> None:
        validate(settings, DEFAULTS, TARGET_KEYS, "assign_vector_variable_to_conditions_process")
        target = read_target(model, settings, ("Array",), historical=False)
        values = vector_value_of(settings)
        interval = Interval.from_parameters(settings["interval"])
        super().__init__(
            [
                ConditionAssignment(target.model_part, component, value, interval)
                for component, value in zip(target.components(), values, strict=True)
                if value is not None
            ]
        )
