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
from ..model_part_lookup import get_model_part
from ..parameters import Parameters
from ._assignments import ConditionAssignment
from ._utilities import LocalAxes, array_components, get_variable, scalar_values_of, validate
from .interval import Interval
from .process import Process

DEFAULTS = {
    "help": "",
    "mesh_id": 0,
    "model_part_name": "",
    "variable_name": "",
    "interval": [0.0, 1e30],
    "value": [0.0, 0.0, 0.0],
    "local_axes": {},
}


def Factory(settings: Parameters, model: Model) -> Process:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return AssignVectorVariableToConditionsProcess(model, settings["Parameters"])


class AssignVectorVariableToConditionsProcess(Process):
    """Set the non-null components of a condition 3-vector in the steps of the interval.

    Args:
        model: the model holding the model part.
        settings: the ``Parameters`` block.

    Raises:
        InputError: unknown key, model part or variable; not a 3-vector; a bad value or interval.
    """

    def __init__(self, model: Model, settings: Parameters) -> None:
        validate(
            settings,
            DEFAULTS,
            ("model_part_name", "variable_name"),
            "assign_vector_variable_to_conditions_process",
        )
        model_part = get_model_part(
            model, settings["model_part_name"].GetString(), settings.Where("model_part_name")
        )
        where = settings.Where("variable_name")
        variable = get_variable(settings["variable_name"].GetString(), where, ("Array",))
        local_axes = LocalAxes.from_parameters(settings["local_axes"])
        values = scalar_values_of(settings["value"], 3, local_axes)
        interval = Interval.from_parameters(settings["interval"])
        self.assignments = [
            ConditionAssignment(model_part, component, value, interval)
            for component, value in zip(array_components(variable, where), values, strict=True)
            if value is not None
        ]

    def ExecuteInitializeSolutionStep(self) -> None:
        """Set the condition values if TIME is in the interval."""
        for assignment in self.assignments:
            assignment.apply()
