"""``modulus`` times ``direction`` for the assign-by-direction processes."""

from __future__ import annotations

from typing import Any

import numpy as np

from .. import _core
from .._core import InputError
from ..parameters import Parameters
from ._utilities import LocalAxes, ScalarValue
from .function_expression import FunctionExpression

AUTOMATIC = ("automatic_inwards_normal", "automatic_outwards_normal")


def area_normal(points: np.ndarray) -> np.ndarray:
    """Return the area-weighted normal of a face given by its (k, 3) corner points.

    A line (2 points) gives ``(dy, -dx, 0)`` (Kratos' 2D orientation); a polygon gives Newell's
    vector ``1/2 sum p_i x p_(i+1)`` (``1/2 (p1 - p0) x (p2 - p0)`` for a triangle).
    """
    if len(points) == 2:
        tangent = points[1] - points[0]
        return np.array([tangent[1], -tangent[0], 0.0])
    return 0.5 * np.sum(np.cross(points, np.roll(points, -1, axis=0)), axis=0)


def automatic_direction(model_part: Any, kind: str, where: str) -> np.ndarray:
    """Return the unit sum of the condition normals of ``model_part`` (minus it for inwards).

    Raises:
        InputError: the part has no conditions or their normals cancel.
    """
    total = np.zeros(3)
    for condition in model_part.Conditions:
        geometry = condition.GetGeometry()
        corners = min(geometry.PointsNumber(), _corner_count(geometry.Name()))
        points = np.array([(n.X, n.Y, n.Z) for n in list(condition.GetNodes())[:corners]])
        total += area_normal(points)
    norm = float(np.linalg.norm(total))
    if norm < 1.0e-12:
        raise InputError(
            f'the direction "{kind}" needs the normals of the conditions of '
            f'"{model_part.FullName()}", but '
            + (
                "it has no conditions"
                if model_part.NumberOfConditions() == 0
                else "they cancel out"
            )
            + f"\n  where:    {where}\n"
            "  fix:      give the direction as [d_x, d_y, d_z]"
        )
    unit = total / norm
    return -unit if kind == "automatic_inwards_normal" else unit


def _corner_count(geometry_name: str) -> int:
    """Number of corner nodes (quadratic geometries list their corners first)."""
    for prefix, count in (("Line", 2), ("Triangle", 3), ("Quadrilateral", 4)):
        if geometry_name.startswith(prefix):
            return count
    return 1_000_000


def component_values(
    settings: Parameters,
    model_part: Any,
    count: int,
    min_norm: float,
    local_axes: LocalAxes | None,
) -> list[ScalarValue]:
    """Return the first ``count`` components of ``modulus * direction``.

    A numeric direction is normalised first (``|d| < min_norm`` is an error); a direction with a
    function string is used as written. Components are numbers when modulus and direction are
    numbers, otherwise the function string ``(d_i)*(modulus)``.

    Raises:
        InputError: a bad modulus or direction.
    """
    modulus = settings["modulus"]
    if not (modulus.IsNumber() or modulus.IsString()):
        raise InputError(
            f"modulus is {modulus.WriteJsonString()}\n  where:    {modulus.Where()}\n"
            '  expected: a number or a function string such as "1.0e3*t"'
        )
    if modulus.IsString():
        FunctionExpression(modulus.GetString(), modulus.Where())  # reports errors at its own key
    direction = settings["direction"]
    where = direction.Where()
    entries: list[float | str]
    if direction.IsString():
        kind = direction.GetString()
        if kind not in AUTOMATIC:
            raise InputError(
                f'unknown direction "{kind}"\n  where:    {where}\n'
                f'  expected: [d_x, d_y, d_z] or "{AUTOMATIC[0]}" or "{AUTOMATIC[1]}"'
            )
        entries = [float(v) for v in automatic_direction(model_part, kind, where)]
    elif (
        direction.IsArray()
        and direction.size() == 3
        and all(e.IsNumber() or e.IsString() for e in direction)
    ):
        entries = [e.GetDouble() if e.IsNumber() else e.GetString() for e in direction]
        if all(isinstance(e, float) for e in entries):
            norm = float(np.linalg.norm(entries))
            if norm < min_norm:
                raise InputError(
                    f"the direction {direction.WriteJsonString()} has length {norm:g}\n"
                    f"  where:    {where}\n  expected: a non-zero vector"
                )
            entries = [float(e) / norm for e in entries]
    else:
        raise InputError(
            f"the direction {direction.WriteJsonString()} is not valid\n  where:    {where}\n"
            "  expected: [d_x, d_y, d_z] (numbers or function strings), "
            '"automatic_inwards_normal" or "automatic_outwards_normal"'
        )
    modulus_text = repr(modulus.GetDouble()) if modulus.IsNumber() else modulus.GetString()
    values = []
    for entry in entries[:count]:
        if isinstance(entry, float) and modulus.IsNumber():
            values.append(ScalarValue(constant=entry * modulus.GetDouble()))
            continue
        entry_text = entry if isinstance(entry, str) else repr(entry)
        function = FunctionExpression(
            f"({entry_text})*({modulus_text})", f"{where} and {modulus.Where()}"
        )
        values.append(ScalarValue(function=function, local_axes=local_axes))
    return values


def domain_size(model_part: Any, where: str) -> int:
    """Return DOMAIN_SIZE of the ProcessInfo (2 or 3).

    Raises:
        InputError: DOMAIN_SIZE is not 2 or 3.
    """
    size = model_part.ProcessInfo[_core.DOMAIN_SIZE]
    if size not in (2, 3):
        size = model_part.GetRootModelPart().ProcessInfo[_core.DOMAIN_SIZE]
    if size not in (2, 3):
        raise InputError(
            f'DOMAIN_SIZE of model part "{model_part.FullName()}" is {size}\n'
            f"  where:    {where}\n  expected: 2 or 3\n"
            "  fix:      set solver_settings.domain_size (the solver copies it to the ProcessInfo)"
        )
    return int(size)
