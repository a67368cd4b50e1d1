"""The result-file layout shared by ``json_output_process`` and ``from_json_check_result_process``.

::

    {"TIME": [t0, t1, ...],
     "NODE_<id>": {"DISPLACEMENT_X": [v0, v1, ...], "<VECTOR_VAR>": [[...], [...]], ...},
     "ELEMENT_<id>": {"VON_MISES_STRESS": {"0": [v0, v1, ...], "1": [...]}, ...},
     "RESULTANT": {"REACTION_X": [...]}}

3-vector variables are split into ``_X/_Y/_Z`` columns; other vectors (``Vector``) store one list
per time. With ``use_node_coordinates`` nodes are keyed ``X_<x0>_Y_<y0>_Z_<z0>`` (initial
coordinates, 6 decimals) instead of ``NODE_<id>``. ``null`` marks a time at which the entity was
not written (``check_for_flag`` did not hold).
"""

from __future__ import annotations

import bisect
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._core import Model
from ..model_part_lookup import get_model_part
from ..parameters import Parameters
from ._utilities import array_components, check_historical, get_flag, get_variable, model_part_of

NODAL_KINDS = ("Double", "Component", "Array", "Vector")
GAUSS_KINDS = ("Double", "Array", "Vector")

Value = float | list[float]


@dataclass(frozen=True)
class Column:
    """One column of the file: its key, the variable read and (gauss points) the component."""

    name: str
    variable: Any
    index: int | None = None


def nodal_columns(names: list[str], where: str) -> list[Column]:
    """Return the columns of nodal variable names (3-vectors split into components)."""
    columns = []
    for name in names:
        variable = get_variable(name, where, NODAL_KINDS)
        if variable.Type() == "Array":
            columns += [Column(c.Name(), c) for c in array_components(variable, where)]
        else:
            columns.append(Column(name, variable))
    return columns


def gauss_columns(names: list[str], where: str) -> list[Column]:
    """Return the columns of integration-point variable names (3-vectors split)."""
    columns = []
    for name in names:
        variable = get_variable(name, where, GAUSS_KINDS)
        if variable.Type() == "Array":
            columns += [Column(f"{name}_{axis}", variable, i) for i, axis in enumerate("XYZ")]
        else:
            columns.append(Column(name, variable))
    return columns


def _plain(value: Any) -> Value:
    if isinstance(value, int | float):
        return float(value)
    return [float(v) for v in np.asarray(value, dtype=float).ravel()]


def nodal_value(node: Any, column: Column, historical: bool) -> Value:
    """Return the historical (buffer step 0) or non-historical value of a node."""
    if historical:
        return _plain(node.GetSolutionStepValue(column.variable))
    return _plain(node.GetValue(column.variable))


def gauss_values(entity: Any, columns: list[Column], process_info: Any) -> dict[str, list[Value]]:
    """Return column name -> value per integration point of an element or condition."""
    cache: dict[str, list[Any]] = {}
    result: dict[str, list[Value]] = {}
    for column in columns:
        name = column.variable.Name()
        if name not in cache:
            cache[name] = list(entity.CalculateOnIntegrationPoints(column.variable, process_info))
        values = cache[name]
        if column.index is None:
            result[column.name] = [_plain(v) for v in values]
        else:
            result[column.name] = [float(np.asarray(v).ravel()[column.index]) for v in values]
    return result


def node_key(node: Any, use_node_coordinates: bool) -> str:
    """Return the file key of a node."""
    if use_node_coordinates:
        return f"X_{node.X0:.6f}_Y_{node.Y0:.6f}_Z_{node.Z0:.6f}"
    return f"NODE_{node.Id}"


def element_key(element: Any) -> str:
    """Return the file key of an element."""
    return f"ELEMENT_{element.Id}"


def nearest_index(times: list[float], time: float) -> int:
    """Index of the stored time nearest to ``time`` (ties: the later one; outside: first/last)."""
    position = bisect.bisect_left(times, time)
    if position == 0:
        return 0
    if position >= len(times):
        return len(times) - 1
    before, after = times[position - 1], times[position]
    return position if after - time <= time - before else position - 1


def results_model_part(model: Model, settings: Parameters) -> Any:
    """Return ``model_part_name``, or its sub-model part ``sub_model_part_name`` if given."""
    model_part = model_part_of(model, settings)
    sub_name = settings["sub_model_part_name"].GetString()
    if sub_name:
        model_part = get_model_part(
            model, f"{model_part.FullName()}.{sub_name}", settings.Where("sub_model_part_name")
        )
    return model_part


def read_columns(
    settings: Any, model_part: Any, nodal_key: str, gauss_key: str
) -> tuple[bool, list[Column], list[Column], Any]:
    """Read what the JSON output and check processes share from their settings.

    Returns (historical, nodal columns, Gauss-point columns, flag or None); checks that historical
    variables are solution-step variables of ``model_part``.
    """
    historical = settings["historical_value"].GetBool()
    where = settings.Where(nodal_key)
    columns = nodal_columns(settings[nodal_key].GetStringArray(), where)
    if historical:
        for column in columns:
            check_historical(model_part, column.variable, where)
    gauss = gauss_columns(settings[gauss_key].GetStringArray(), settings.Where(gauss_key))
    flag_name = settings["check_for_flag"].GetString()
    flag = get_flag(flag_name, settings.Where("check_for_flag")) if flag_name else None
    return historical, columns, gauss, flag
