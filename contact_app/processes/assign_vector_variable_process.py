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
from ..parameters import Parameters
from ._assignments import NodalAssignment, NodalAssignmentProcess, read_target
from ._utilities import COMMON_DEFAULTS, TARGET_KEYS, flags_of, validate, vector_value_of
from .interval import Interval
from .process import Process

DEFAULTS = {
    **COMMON_DEFAULTS,
    "constrained": None,
    "value": [0.0, 0.0, 0.0],
    "local_axes": {},
}


def Factory(settings: Parameters, model: Model) -> Process:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return AssignVectorVariableProcess(model, settings["Parameters"])


class AssignVectorVariableProcess(NodalAssignmentProcess):
    """Assign the non-null components of a nodal 3-vector, each fixed from step start to end.

    Args:
        model: the model holding the model part.
        settings: the ``Parameters`` block.

    Raises:
        InputError: unknown key, model part or variable; not a 3-vector variable; a value or
            constrained array of the wrong size; a bad function string or interval.
    """

    def __init__(self, model: Model, settings: Parameters) -> None:
        validate(settings, DEFAULTS, TARGET_KEYS, "assign_vector_variable_process")
        if settings["constrained"].IsNull():
            settings["constrained"].SetBool(True)
        target = read_target(model, settings, ("Array",), historical=True)
        values = vector_value_of(settings)
        constrained = flags_of(settings["constrained"], 3)
        interval = Interval.from_parameters(settings["interval"])
        super().__init__(
            [
                NodalAssignment(target.model_part, component, value, interval, fixed)
                for component, value, fixed in zip(
                    target.components(), values, constrained, strict=True
                )
                if value is not None
            ]
        )
