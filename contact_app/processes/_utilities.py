"""Helpers shared by the core processes.

Settings validation, variable and flag look-up, values given as numbers, function strings or CSV
tables, and ``local_axes``.
"""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from .. import _core
from .._core import InputError, Model
from ..json_input import decode, quote, read_bytes
from ..model_part_lookup import get_model_part
from ..parameters import Parameters, suggest
from .function_expression import FunctionExpression

SCALAR_KINDS = ("Double", "Component")

# The keys (and their order) every assign/fix process starts its DEFAULTS with.
COMMON_DEFAULTS: dict[str, Any] = {
    "help": "",
    "mesh_id": 0,
    "model_part_name": "",
    "variable_name": "",
    "interval": [0.0, 1e30],
}


# The keys every assign/fix process needs (``validate``'s ``required``).
TARGET_KEYS = ("model_part_name", "variable_name")


def validate(
    settings: Parameters, defaults: dict[str, Any], required: Sequence[str] = (), what: str = ""
) -> None:
    """Check ``settings`` against ``defaults`` (unknown keys are errors) and add missing defaults.

    Args:
        settings: the ``Parameters`` block of a process descriptor.
        defaults: key -> default value; ``None`` accepts any JSON kind (checked by the caller).
        required: keys the user must give.
        what: the process name, for messages.

    Raises:
        InputError: a required key is missing, a key is unknown or a value has the wrong kind.
    """
    for key in required:
        if not settings.Has(key):
            raise InputError(
                f'missing key "{key}"\n  where:    {settings.Where(key)}\n'
                f"  expected: {what or 'this process'} needs {key}\n"
                f'  fix:      add "{key}" to the Parameters block'
            )
    settings.ValidateAndAssignDefaults(defaults)


def model_part_of(model: Model, settings: Parameters) -> Any:
    """Return the model part ``settings["model_part_name"]`` names (InputError if none)."""
    return get_model_part(
        model, settings["model_part_name"].GetString(), settings.Where("model_part_name")
    )


def get_variable(name: str, where: str, kinds: Sequence[str] | None = None) -> Any:
    """Return the registered variable ``name``, optionally checking its kind.

    Args:
        name: a Kratos variable name (``DISPLACEMENT_X``).
        where: location of the name in the settings, for messages.
        kinds: accepted ``Type()`` values ("Double", "Component", "Array", ...); None = any.

    Raises:
        InputError: unknown name (with a suggestion) or a kind not in ``kinds``.
    """
    try:
        variable = _core.get_variable(name)
    except KeyError:
        raise _unknown_name(
            "variable",
            name,
            where,
            _core.registered_variables(),
            "a registered Kratos variable name such as DISPLACEMENT_X",
        ) from None
    if kinds is not None and variable.Type() not in kinds:
        raise InputError(
            f'variable "{name}" is of kind {variable.Type()}\n  where:    {where}\n'
            f"  expected: a variable of kind {' or '.join(kinds)}"
        )
    return variable


def get_flag(name: str, where: str) -> Any:
    """Return the registered flag ``name``; InputError (with a suggestion) if there is none."""
    try:
        return _core.get_flag(name)
    except KeyError:
        raise _unknown_name(
            "flag",
            name,
            where,
            _core.registered_flags(),
            "a Kratos flag name such as ACTIVE, SLAVE or MASTER",
        ) from None


def _unknown_name(
    kind: str, name: str, where: str, registered: Iterable[str], expected: str
) -> InputError:
    """The error for a variable or flag name that is not registered, with the nearest name."""
    hint = suggest(name, list(registered))
    return InputError(
        f'unknown {kind} "{quote(name)}"\n  where:    {where}\n'
        f"  expected: {expected}" + (f"\n  fix:      {hint}" if hint else "")
    )


def array_components(variable: Any, where: str) -> list[Any]:
    """Return the ``_X, _Y, _Z`` component variables of a 3-vector variable."""
    return [get_variable(f"{variable.Name()}_{axis}", where) for axis in "XYZ"]


def check_historical(
    model_part: Any,
    variable: Any,
    where: str,
    fix: str = 'write "historical_value": false to use the nodes\' non-historical values',
) -> None:
    """Raise InputError unless ``variable`` (or its source vector) is a solution-step variable."""
    source = variable.GetSourceVariable() if variable.IsComponent() else variable
    if not model_part.GetRootModelPart().HasNodalSolutionStepVariable(source):
        raise InputError(
            f"{variable.Name()} is not a historical (solution-step) variable of model part "
            f'"{model_part.GetRootModelPart().Name}"\n  where:    {where}\n'
            "  expected: a variable the solver declares with AddNodalSolutionStepVariable\n"
            f"  fix:      use a variable of the solver, or {fix}"
        )


def coordinates(nodes: Iterable[Any]) -> tuple[np.ndarray, np.ndarray]:
    """Return the (n, 3) current and (n, 3) initial coordinates of ``nodes``."""
    current, initial = [], []
    for node in nodes:
        current.append((node.X, node.Y, node.Z))
        initial.append((node.X0, node.Y0, node.Z0))
    return np.array(current, dtype=float).reshape(-1, 3), np.array(initial, dtype=float).reshape(
        -1, 3
    )


class LocalAxes:
    """``local_axes``: the local system function strings are evaluated in.

    Points are mapped to ``R (p - origin)`` (rows of R = ``axes``) before the evaluation.

    Args:
        origin: (3,) origin of the local system.
        axes: (3, 3) local axes, one per row.
    """

    def __init__(self, origin: Sequence[float], axes: Sequence[Sequence[float]]) -> None:
        self.origin = np.asarray(origin, dtype=float)
        self.axes = np.asarray(axes, dtype=float)

    @classmethod
    def from_parameters(cls, settings: Parameters) -> LocalAxes | None:
        """Read ``{"origin": [3], "axes": [[3], [3], [3]]}``; None for ``{}``."""
        if settings.size() == 0:
            return None
        settings.ValidateAndAssignDefaults(
            {"origin": [0.0, 0.0, 0.0], "axes": [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]}
        )
        origin = settings["origin"].GetVector()
        axes = settings["axes"].GetMatrix()
        if len(origin) != 3 or len(axes) != 3 or any(len(row) != 3 for row in axes):
            raise InputError(
                "local_axes needs a 3-vector origin and 3 x 3 axes\n"
                f"  where:    {settings.Where()}\n"
                '  expected: {"origin": [x, y, z], "axes": [[..3..], [..3..], [..3..]]}'
            )
        return cls(origin, axes)

    def transform(self, points: np.ndarray) -> np.ndarray:
        """Return (n, 3) local coordinates of (n, 3) global points."""
        return (points - self.origin) @ self.axes.T


class CsvTable:
    """A ``{"name": "csv_table", "filename": ...}`` value: piecewise linear in TIME.

    Beyond the first and last rows the table is extrapolated linearly.
    """

    DEFAULTS: dict[str, Any] = {
        "name": "csv_table",
        "filename": "",
        "delimiter": ",",
        "skiprows": 0,
        "first_column_id": 0,
        "second_column_id": 1,
        "na_replace": 0.0,
    }

    def __init__(self, settings: Parameters) -> None:
        settings.ValidateAndAssignDefaults(self.DEFAULTS)
        if settings["name"].GetString() != "csv_table":
            raise InputError(
                f'unknown table kind "{settings["name"].GetString()}"\n'
                f"  where:    {settings.Where('name')}\n"
                '  expected: "csv_table"'
            )
        filename = settings["filename"].GetString()
        columns = (settings["first_column_id"].GetInt(), settings["second_column_id"].GetInt())
        na_replace = settings["na_replace"].GetDouble()
        where = settings.Where("filename")
        text = decode(read_bytes(filename, "table", where), Path(filename).name)
        rows = list(csv.reader(io.StringIO(text), delimiter=settings["delimiter"].GetString()))
        points: list[tuple[float, float]] = []
        for number, row in enumerate(rows[settings["skiprows"].GetInt() :], 1):
            if not row or all(not cell.strip() for cell in row):
                continue
            try:
                pair = [row[c].strip() for c in columns]
                x, y = (float(v) if v and v.lower() != "nan" else na_replace for v in pair)
                point = (x, y)
                if not all(math.isfinite(v) for v in point):
                    raise ValueError("not finite")
                points.append(point)
            except (IndexError, ValueError):
                raise InputError(
                    f'row {number} of "{filename}" has no finite numbers in columns {columns}\n'
                    f"  where:    {where}\n  fix:      check delimiter, skiprows and column ids"
                ) from None
        if not points:
            raise InputError(f'the table "{filename}" is empty\n  where:    {where}')
        points.sort()
        self.times = np.array([p[0] for p in points])
        self.values = np.array([p[1] for p in points])

    def __call__(self, time: float) -> float:
        """Return the value at ``time``."""
        times, values = self.times, self.values
        if len(times) == 1:
            return float(values[0])
        if time <= times[0]:
            i = 0
        elif time >= times[-1]:
            i = len(times) - 2
        else:
            return float(np.interp(time, times, values))
        slope = (values[i + 1] - values[i]) / (times[i + 1] - times[i])
        return float(values[i] + slope * (time - times[i]))


class ScalarValue:
    """A value given as a number, a function string or a CSV table.

    Args:
        constant: the number, or
        function: the compiled function string, or
        table: the table.
        local_axes: the local system function strings are evaluated in (None = global).
    """

    def __init__(
        self,
        constant: float | None = None,
        function: FunctionExpression | None = None,
        table: CsvTable | None = None,
        local_axes: LocalAxes | None = None,
    ) -> None:
        self.constant = constant
        self.function = function
        self.table = table
        self.local_axes = local_axes

    @classmethod
    def from_parameters(cls, value: Parameters, local_axes: LocalAxes | None = None) -> ScalarValue:
        """Read a number, a function string or a table object.

        Raises:
            InputError: another JSON kind, or an invalid function string or table.
        """
        if value.IsNumber():
            return cls(constant=value.GetDouble())
        if value.IsString():
            return cls(
                function=FunctionExpression(value.GetString(), value.Where()), local_axes=local_axes
            )
        if value.IsSubParameter():
            return cls(table=CsvTable(value))
        raise InputError(
            f"the value {value.WriteJsonString()} is neither a number nor a function string\n"
            f"  where:    {value.Where()}\n"
            '  expected: a number, a function string such as "0.1*t", or a csv_table object'
        )

    @property
    def depends_on_space(self) -> bool:
        """True for a function string of x, y, z, X, Y or Z."""
        return self.function is not None and self.function.depends_on_space

    def at_time(self, time: float) -> float:
        """Return the value at ``time`` (for values that do not depend on space: at (0, 0, 0))."""
        if self.constant is not None:
            return self.constant
        if self.table is not None:
            return self.table(time)
        assert self.function is not None
        return self.function(time)

    def at_points(self, time: float, current: np.ndarray, initial: np.ndarray) -> np.ndarray:
        """Return the (n,) values at (n, 3) current and initial coordinates."""
        if not self.depends_on_space:
            return np.full(len(current), self.at_time(time))
        assert self.function is not None
        if self.local_axes is not None:
            current = self.local_axes.transform(current)
            initial = self.local_axes.transform(initial)
        return self.function.values_at(time, current, initial)

    def __repr__(self) -> str:
        if self.constant is not None:
            return f"{self.constant!r}"
        if self.function is not None:
            return repr(self.function.expression)
        return "csv_table"


def scalar_values_of(
    values: Parameters, count: int, local_axes: LocalAxes | None
) -> list[ScalarValue | None]:
    """Read a ``[v_x, v_y, v_z]`` array whose entries are numbers, strings or null (= untouched).

    Raises:
        InputError: not an array of ``count`` entries.
    """
    if not values.IsArray() or values.size() != count:
        raise InputError(
            f"the value {values.WriteJsonString()} is not an array of {count} entries\n"
            f"  where:    {values.Where()}\n"
            "  expected: [v_x, v_y, v_z], each a number, a function string or null (untouched)"
        )
    return [
        None if entry.IsNull() else ScalarValue.from_parameters(entry, local_axes)
        for entry in values
    ]


def scalar_value_of(settings: Parameters) -> ScalarValue:
    """Read ``value`` (null = 0.0) in the system of ``local_axes``."""
    if settings["value"].IsNull():
        settings["value"].SetDouble(0.0)
    return ScalarValue.from_parameters(
        settings["value"], LocalAxes.from_parameters(settings["local_axes"])
    )


def vector_value_of(settings: Parameters) -> list[ScalarValue | None]:
    """Read ``value`` ([v_x, v_y, v_z], null = untouched) in the system of ``local_axes``."""
    return scalar_values_of(settings["value"], 3, LocalAxes.from_parameters(settings["local_axes"]))


def flags_of(constrained: Parameters, count: int) -> list[bool]:
    """Read ``constrained``: one bool (for every component) or an array of ``count`` bools."""
    if constrained.IsBool():
        return [constrained.GetBool()] * count
    if (
        constrained.IsArray()
        and constrained.size() == count
        and all(entry.IsBool() for entry in constrained)
    ):
        return [entry.GetBool() for entry in constrained]
    raise InputError(
        f"constrained is {constrained.WriteJsonString()}\n  where:    {constrained.Where()}\n"
        f"  expected: true/false or an array of {count} of them"
    )


def is_close(value: float, reference: float, relative: float, absolute: float) -> bool:
    """``|a - b| <= max(rel * max(|a|, |b|), abs)`` (Python's math.isclose)."""
    return math.isclose(value, reference, rel_tol=relative, abs_tol=absolute)
