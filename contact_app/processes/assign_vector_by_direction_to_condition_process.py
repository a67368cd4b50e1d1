"""``assign_vector_by_direction_to_condition_process``.

Set ``modulus * direction`` as a 3-vector value of every condition of a model part (e.g.
SURFACE_LOAD of a pressure-like load).

Keys: ``model_part_name``, ``variable_name`` (a 3-vector), ``modulus`` (number or function string)
and ``direction`` ([d_x, d_y, d_z] of numbers or function strings, or
``"automatic_inwards_normal"``/``"automatic_outwards_normal"``: the unit sum of the area-weighted
condition normals of the part, computed once at construction) are required; ``interval``
([0, "End"]), ``local_axes`` ({}), ``mesh_id`` (legacy, 0), ``help``.

A numeric direction is normalised (length below 1e-6 is an error); a direction containing a
function string is used as written and each component becomes ``(d_i)*(modulus)``. The X, Y and Z
components are always assigned, each like ``assign_scalar_variable_to_conditions_process``.
"""

from __future__ import annotations

from .._core import Model
from ..parameters import Parameters
from ._assignments import ConditionAssignment, ConditionAssignmentProcess, read_target
from ._direction import component_values
from ._utilities import COMMON_DEFAULTS, TARGET_KEYS, LocalAxes, validate
from .interval import Interval
from .process import Process

DEFAULTS = {
    **COMMON_DEFAULTS,
    "modulus": None,
    "direction": None,
    "local_axes": {},
}


def Factory(settings: Parameters, model: Model) -> Process:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return AssignVectorByDirectionToConditionProcess(model, settings["Parameters"])


class AssignVectorByDirectionToConditionProcess(ConditionAssignmentProcess):
    """Set ``modulus * unit direction`` on the conditions in the steps of the interval.

    Args:
        model: the model holding the model part.
        settings: the ``Parameters`` block.

    Raises:
        InputError: unknown key, model part or variable; a bad modulus, direction or interval.
    """

    def __init__(self, model: Model, settings: Parameters) -> None:
        validate(
            settings,
            DEFAULTS,
            (*TARGET_KEYS, "modulus", "direction"),
            "assign_vector_by_direction_to_condition_process",
        )
        target = read_target(model, settings, ("Array",), historical=False)
        local_axes = LocalAxes.from_parameters(settings["local_axes"])
        values = component_values(settings, target.model_part, 3, 1.0e-6, local_axes)
        interval = Interval.from_parameters(settings["interval"])
        super().__init__(
            [
                ConditionAssignment(target.model_part, component, value, interval)
                for component, value in zip(target.components(), values, strict=True)
            ]
        )
