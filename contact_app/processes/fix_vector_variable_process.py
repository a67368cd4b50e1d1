"""``fix_vector_variable_process``.

Fix the DoFs of chosen components of a 3-vector variable on the nodes of a model part without
changing their values.

Keys: ``model_part_name`` and ``variable_name`` (required; a 3-vector), ``constrained`` (one bool or
three; default [true, true, true]; false components are left alone), ``interval`` ([0, "End"]),
``mesh_id`` (legacy, 0), ``help``.

Each component with a true flag behaves as ``fix_scalar_variable_process`` on ``<VAR>_X/_Y/_Z``.
"""

from __future__ import annotations

from .._core import Model
from ..parameters import Parameters
from ._assignments import NodalAssignment, NodalAssignmentProcess, read_target
from ._utilities import COMMON_DEFAULTS, TARGET_KEYS, flags_of, validate
from .interval import Interval
from .process import Process

DEFAULTS = {
    **COMMON_DEFAULTS,
    "constrained": None,
}


def Factory(settings: Parameters, model: Model) -> Process:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return FixVectorVariableProcess(model, settings["Parameters"])


class FixVectorVariableProcess(NodalAssignmentProcess):
    """Hold the chosen components of a nodal 3-vector fixed from step start to step end.

    Args:
        model: the model holding the model part.
        settings: the ``Parameters`` block.

    Raises:
        InputError: unknown key, model part or variable; not a 3-vector; a bad constrained array
            or interval.
    """

    def __init__(self, model: Model, settings: Parameters) -> None:
        validate(settings, DEFAULTS, TARGET_KEYS, "fix_vector_variable_process")
        if settings["constrained"].IsNull():
            settings.AddValue("constrained", [True, True, True])
        target = read_target(model, settings, ("Array",), historical=False)
        interval = Interval.from_parameters(settings["interval"])
        fixed = flags_of(settings["constrained"], 3)
        super().__init__(
            [
                NodalAssignment(target.model_part, component, None, interval, True)
                for component, fix in zip(target.components(), fixed, strict=True)
                if fix
            ]
        )
