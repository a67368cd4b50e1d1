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
from ..parameters import Parameters
from ._assignments import NodalAssignment, NodalAssignmentProcess, read_target
from ._utilities import COMMON_DEFAULTS, SCALAR_KINDS, TARGET_KEYS, validate
from .interval import Interval
from .process import Process

DEFAULTS = {
    **COMMON_DEFAULTS,
    "constrained": True,
}


def Factory(settings: Parameters, model: Model) -> Process:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return FixScalarVariableProcess(model, settings["Parameters"])


class FixScalarVariableProcess(NodalAssignmentProcess):
    """Hold a nodal DoF fixed from step start to step end, value untouched.

    Args:
        model: the model holding the model part.
        settings: the ``Parameters`` block.

    Raises:
        InputError: unknown key, model part or variable; a vector variable; a bad interval.
    """

    def __init__(self, model: Model, settings: Parameters) -> None:
        validate(settings, DEFAULTS, TARGET_KEYS, "fix_scalar_variable_process")
        model_part, variable, _ = read_target(model, settings, SCALAR_KINDS, historical=False)
        interval = Interval.from_parameters(settings["interval"])
        constrained = settings["constrained"].GetBool()
        super().__init__([NodalAssignment(model_part, variable, None, interval, constrained)])
