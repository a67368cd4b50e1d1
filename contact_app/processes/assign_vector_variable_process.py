"""``assign_vector_variable_process``.

Assign (and by default fix) components of a 3-vector variable on the nodes of a model part.

Keys: ``model_part_name`` and ``variable_name`` (required; a 3-vector such as DISPLACEMENT),
``value`` ([v_x, v_y, v_z], each a number, a function string or null = component untouched;
default [0, 0, 0]), ``constrained`` (one bool or three; default true), ``interval`` ([0, "End"]),
``local_axes`` ({}), ``mesh_id`` (legacy, 0), ``help``.

Each non-null component behaves as ``assign_scalar_variable_process`` on ``<VAR>_X/_Y/_Z``: fixed
(if constrained) and assigned at the start of every step in the interval, freed at its end.
"""

from __future__ import annotations

from .._core import Model
from ..model_part_lookup import get_model_part
from ..parameters import Parameters
from ._assignments import NodalAssignment
from ._utilities import (
    LocalAxes,
    array_components,
    check_historical,
    flags_of,
    get_variable,
    scalar_values_of,
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
    "constrained": None,
    "value": [0.0, 0.0, 0.0],
    "local_axes": {},
}


def Factory(settings: Parameters, model: Model) -> Process:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return AssignVectorVariableProcess(model, settings["Parameters"])


class AssignVectorVariableProcess(Process):
    """Assign the non-null components of a nodal 3-vector, each fixed from step start to end.

    Args:
        model: the model holding the model part.
        settings: the ``Parameters`` block.

    Raises:
        InputError: unknown key, model part or variable; not a 3-vector variable; a value or
            constrained array of the wrong size; a bad function string or interval.
    """

    def __init__(self, model: Model, settings: Parameters) -> None:
        validate(
            settings,
            DEFAULTS,
            ("model_part_name", "variable_name"),
            "assign_vector_variable_process",
        )
        if settings["constrained"].IsNull():
            settings["constrained"].SetBool(True)
        model_part = get_model_part(
            model, settings["model_part_name"].GetString(), settings.Where("model_part_name")
        )
        where = settings.Where("variable_name")
        variable = get_variable(settings["variable_name"].GetString(), where, ("Array",))
        check_historical(model_part, variable, where)
        local_axes = LocalAxes.from_parameters(settings["local_axes"])
        values = scalar_values_of(settings["value"], 3, local_axes)
        constrained = flags_of(settings["constrained"], 3)
        interval = Interval.from_parameters(settings["interval"])
        self.assignments = [
            NodalAssignment(model_part, component, value, interval, fixed)
            for component, value, fixed in zip(
                array_components(variable, where), values, constrained, strict=True
            )
            if value is not None
        ]

    def ExecuteBeforeSolutionLoop(self) -> None:
        """Apply the values at the start time too."""
        self.ExecuteInitializeSolutionStep()

    def ExecuteInitializeSolutionStep(self) -> None:
        """Fix and assign the non-null components if TIME is in the interval."""
        for assignment in self.assignments:
            assignment.apply()

    def ExecuteFinalizeSolutionStep(self) -> None:
        """Free the DoFs fixed in this step."""
        for assignment in self.assignments:
            assignment.release()
