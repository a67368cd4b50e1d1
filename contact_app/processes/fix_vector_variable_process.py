"""``fix_vector_variable_process``.

Fix the DoFs of chosen components of a 3-vector variable on the nodes of a model part without
changing their values.

Keys: ``model_part_name`` and ``variable_name`` (required; a 3-vector), ``constrained`` (one bool or
three; default [true, true, true]; false components are left alone), ``interval`` ([0, "End"]),
``mesh_id`` (legacy, 0), ``help``.

Fixed at the start of every step in the interval (and before the solution loop), freed at the end
of that step.
"""

from __future__ import annotations

from .._core import Model
from ..model_part_lookup import get_model_part
from ..parameters import Parameters
from ._assignments import NodalAssignment
from ._utilities import array_components, flags_of, get_variable, validate
from .interval import Interval
from .process import Process

DEFAULTS = {
    "help": "",
    "mesh_id": 0,
    "model_part_name": "",
    "variable_name": "",
    "interval": [0.0, 1e30],
    "constrained": None,
}


def Factory(settings: Parameters, model: Model) -> Process:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return FixVectorVariableProcess(model, settings["Parameters"])


class FixVectorVariableProcess(Process):
    """Hold the chosen components of a nodal 3-vector fixed from step start to step end.

    Args:
        model: the model holding the model part.
        settings: the ``Parameters`` block.

    Raises:
        InputError: unknown key, model part or variable; not a 3-vector; a bad constrained array
            or interval.
    """

    def __init__(self, model: Model, settings: Parameters) -> None:
        validate(
            settings,
            DEFAULTS,
            ("model_part_name", "variable_name"),
            "fix_vector_variable_process",
        )
        if settings["constrained"].IsNull():
            settings.AddValue("constrained", [True, True, True])
        model_part = get_model_part(
            model, settings["model_part_name"].GetString(), settings.Where("model_part_name")
        )
        where = settings.Where("variable_name")
        variable = get_variable(settings["variable_name"].GetString(), where, ("Array",))
        interval = Interval.from_parameters(settings["interval"])
        self.assignments = [
            NodalAssignment(model_part, component, None, interval, True)
            for component, fixed in zip(
                array_components(variable, where), flags_of(settings["constrained"], 3), strict=True
            )
            if fixed
        ]

    def ExecuteBeforeSolutionLoop(self) -> None:
        """Fix at the start time too."""
        self.ExecuteInitializeSolutionStep()

    def ExecuteInitializeSolutionStep(self) -> None:
        """Fix if TIME is in the interval."""
        for assignment in self.assignments:
            assignment.apply()

    def ExecuteFinalizeSolutionStep(self) -> None:
        """Free the DoFs fixed in this step."""
        for assignment in self.assignments:
            assignment.release()
