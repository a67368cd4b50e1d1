"""``assign_vector_by_direction_process``.

Assign (and by default fix) ``modulus * direction`` as a nodal 3-vector variable.

Keys: ``model_part_name``, ``variable_name`` (a 3-vector), ``modulus`` (number or function string)
and ``direction`` ([d_x, d_y, d_z] of numbers or function strings, or
``"automatic_inwards_normal"``/``"automatic_outwards_normal"``: the unit sum of the area-weighted
condition normals of the part) are required; ``constrained`` (true), ``interval`` ([0, "End"]),
``local_axes`` ({}), ``mesh_id`` (legacy, 0), ``help``.

A numeric direction is normalised (length below 1e-12 is an error); a direction containing a
function string is used as written and each component becomes ``(d_i)*(modulus)``. The X and Y
components are assigned in 2D (DOMAIN_SIZE 2), X, Y and Z in 3D, each like
``assign_scalar_variable_process``.
"""

from __future__ import annotations

from .._core import Model
from ..parameters import Parameters
from ._assignments import NodalAssignment, NodalAssignmentProcess, read_target
from ._direction import component_values, domain_size
from ._utilities import COMMON_DEFAULTS, TARGET_KEYS, LocalAxes, validate
from .interval import Interval
from .process import Process

DEFAULTS = {
    **COMMON_DEFAULTS,
    "modulus": None,
    "constrained": True,
    "direction": None,
    "local_axes": {},
}


def Factory(settings: Parameters, model: Model) -> Process:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return AssignVectorByDirectionProcess(model, settings["Parameters"])


class AssignVectorByDirectionProcess(NodalAssignmentProcess):
    """Assign ``modulus * unit direction`` on the nodes, fixed from step start to step end.

    Args:
        model: the model holding the model part.
        settings: the ``Parameters`` block.

    Raises:
        InputError: unknown key, model part or variable; a bad modulus, direction or interval;
            DOMAIN_SIZE not 2 or 3.
    """

    def __init__(self, model: Model, settings: Parameters) -> None:
        validate(
            settings,
            DEFAULTS,
            (*TARGET_KEYS, "modulus", "direction"),
            "assign_vector_by_direction_process",
        )
        target = read_target(model, settings, ("Array",), historical=True)
        count = domain_size(target.model_part, settings.Where())
        local_axes = LocalAxes.from_parameters(settings["local_axes"])
        values = component_values(settings, target.model_part, count, 1.0e-12, local_axes)
        interval = Interval.from_parameters(settings["interval"])
        constrained = settings["constrained"].GetBool()
        super().__init__(
            [
                NodalAssignment(target.model_part, component, value, interval, constrained)
                for component, value in zip(target.components(), values, strict=False)
            ]
        )
