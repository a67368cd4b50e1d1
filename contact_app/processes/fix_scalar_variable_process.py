"""``fix_scalar_variable_process``.

Fix the DoF of a double or component variable on the nodes of a model part without changing its
value.

Keys: ``model_part_name`` and ``variable_name`` (required), ``constrained`` (true; false makes the
process do nothing), ``interval`` ([0, "End"]), ``mesh_id`` (legacy, 0), ``help``.

Fixed at the start of every step in the interval (and before the solution loop), freed at the end
of that step.
"""

from __future__ import annotations

from .._core import Model
from ..model_part_lookup import get_model_part
from ..parameters import Parameters
from ._assignments import NodalAssignment
from ._utilities import SCALAR_KINDS, get_variable, validate
from .interval import Interval
from .process import Process

DEFAULTS = {
    "help": "",
    "mesh_id": 0,
    "model_part_name": "",
    "variable_name": "",
    "interval": [0.0, 1e30],
    "constrained": True,
}


def Factory(settings: Parameters, model: Model) -> Process:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return FixScalarVariableProcess(model, settings["Parameters"])


class FixScalarVariableProcess(Process):
    """Hold a nodal DoF fixed from step start to step end, value untouched.

    Args:
        model: the model holding the model part.
        settings: the ``Parameters`` block.

    Raises:
        InputError: unknown key, model part or variable; a vector variable; a bad interval.
    """

    def __init__(self, model: Model, settings: Parameters) -> None:
        validate(
            settings,
            DEFAULTS,
            ("model_part_name", "variable_name"),
            "fix_scalar_variable_process",
        )
        model_part = get_model_part(
            model, settings["model_part_name"].GetString(), settings.Where("model_part_name")
        )
        variable = get_variable(
            settings["variable_name"].GetString(), settings.Where("variable_name"), SCALAR_KINDS
        )
        self.assignment = NodalAssignment(
            model_part,
            variable,
            None,
            Interval.from_parameters(settings["interval"]),
            settings["constrained"].GetBool(),
        )

    def ExecuteBeforeSolutionLoop(self) -> None:
        """Fix at the start time too."""
        self.ExecuteInitializeSolutionStep()

    def ExecuteInitializeSolutionStep(self) -> None:
        """Fix if TIME is in the interval."""
        self.assignment.apply()

    def ExecuteFinalizeSolutionStep(self) -> None:
        """Free the DoFs fixed in this step."""
        self.assignment.release()
