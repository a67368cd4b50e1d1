"""``from_json_check_result_process``.

Compare nodal (and integration-point) results with a reference JSON file written by
``json_output_process`` (layout in ``_json_results``).

Keys: ``check_variables`` ([]), ``gauss_points_check_variables`` ([]), ``input_file_name``
(required; relative paths start from the working directory), ``model_part_name`` (required),
``sub_model_part_name`` (""), ``check_for_flag`` ("" = every node; else only nodes — and elements —
with that flag set), ``historical_value`` (true; false reads the nodes' non-historical values),
``tolerance`` (1e-3, absolute), ``relative_tolerance`` (1e-6), ``time_frequency`` (1.0),
``use_node_coordinates`` (false), ``check_only_local_entities`` (false; every entity is local in a
serial run, so it changes nothing).

At the end of a step DELTA_TIME is added to a counter; only when the counter **strictly exceeds**
``time_frequency`` is it reset and the step checked (so 0.0 checks every step). A value passes iff
``|a - b| <= max(relative_tolerance * max(|a|, |b|), tolerance)``, the reference ``b`` being taken
at the stored TIME nearest to the current one (ties: the later). Every mismatch of the step is
listed in one :class:`ResultCheckError`. ``worst_relative_errors`` / ``worst_absolute_errors``
keep, per column (``DISPLACEMENT_X``, ...), the largest ``|a - b| / max(|a|, |b|)`` and ``|a - b|``
seen.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

from .. import _core
from .._core import InputError, Model
from ..json_input import load_file
from ..parameters import Parameters
from ._json_results import (
    Column,
    Value,
    element_key,
    gauss_values,
    nearest_index,
    nodal_value,
    node_key,
    read_columns,
    results_model_part,
)
from ._utilities import validate
from .process import Process

DEFAULTS = {
    "check_variables": [],
    "gauss_points_check_variables": [],
    "input_file_name": "",
    "model_part_name": "",
    "sub_model_part_name": "",
    "check_for_flag": "",
    "historical_value": True,
    "tolerance": 1e-3,
    "relative_tolerance": 1e-6,
    "time_frequency": 1.0,
    "use_node_coordinates": False,
    "check_only_local_entities": False,
}
MAX_LISTED_FAILURES = 10


class ResultCheckError(AssertionError):
    """A checked value differs from its reference by more than the tolerances."""


def Factory(settings: Parameters, model: Model) -> Process:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return FromJsonCheckResultProcess(model, settings["Parameters"])


class FromJsonCheckResultProcess(Process):
    """Check results against a reference file at the end of the steps ``time_frequency`` selects.

    Args:
        model: the model holding the model part.
        settings: the ``Parameters`` block.

    Raises:
        InputError: unknown key, model part, variable or flag; a variable the solver does not store
            historically while ``historical_value`` is true.
    """

    def __init__(self, model: Model, settings: Parameters) -> None:
        validate(
            settings,
            DEFAULTS,
            ("input_file_name", "model_part_name"),
            "from_json_check_result_process",
        )
        self.settings = settings
        self.model_part = results_model_part(model, settings)
        self.historical, self.columns, self.gauss_columns, self.flag = read_columns(
            settings, self.model_part, "check_variables", "gauss_points_check_variables"
        )
        self.input_file_name = settings["input_file_name"].GetString()
        self.tolerance = settings["tolerance"].GetDouble()
        self.relative_tolerance = settings["relative_tolerance"].GetDouble()
        self.time_frequency = settings["time_frequency"].GetDouble()
        self.use_node_coordinates = settings["use_node_coordinates"].GetBool()
        names = [c.name for c in self.columns + self.gauss_columns]
        self.worst_relative_errors: dict[str, float] = dict.fromkeys(names, 0.0)
        self.worst_absolute_errors: dict[str, float] = dict.fromkeys(names, 0.0)
        self.checked_times: list[float] = []
        self._data: dict[str, Any] | None = None
        self._time_counter = 0.0

    def ExecuteInitialize(self) -> None:
        """Read the reference file."""
        self._reference()

    def ExecuteFinalizeSolutionStep(self) -> None:
        """Check this step if the time since the last check exceeds ``time_frequency``.

        Raises:
            ResultCheckError: some value differs from its reference beyond the tolerances.
            InputError: the reference file lacks an entity or variable that is checked.
        """
        process_info = self.model_part.ProcessInfo
        self._time_counter += process_info[_core.DELTA_TIME]
        if self._time_counter > self.time_frequency:
            self._time_counter = 0.0
            self.check(process_info[_core.TIME])

    def GetRestartState(self) -> dict[str, Any]:
        """The time since the last check (a restarted run checks at the same times)."""
        return {"time_counter": self._time_counter}

    def SetRestartState(self, state: dict[str, Any]) -> None:
        """Resume the counter of the saving run."""
        self._time_counter = float(state["time_counter"])

    def check(self, time: float) -> None:
        """Compare every checked value with the reference at the stored time nearest to ``time``.

        Raises:
            ResultCheckError: some value differs from its reference beyond the tolerances.
            InputError: the reference file lacks an entity or variable that is checked.
        """
        data = self._reference()
        index = nearest_index(data["TIME"], time)
        failures: list[str] = []
        count = 0
        for node in self.model_part.Nodes:
            if self.flag is not None and not node.Is(self.flag):
                continue
            entry = self._entry(data, node_key(node, self.use_node_coordinates), f"node {node.Id}")
            for column in self.columns:
                reference = self._series(entry, column.name, f"node {node.Id}")
                value = nodal_value(node, column, self.historical)
                count += 1
                self._compare(column, f"node {node.Id}", value, reference, index, failures)
        if self.gauss_columns:
            process_info = self.model_part.ProcessInfo
            for element in self.model_part.Elements:
                if self.flag is not None and not element.Is(self.flag):
                    continue
                label = f"element {element.Id}"
                entry = self._entry(data, element_key(element), label)
                values = gauss_values(element, self.gauss_columns, process_info)
                for column in self.gauss_columns:
                    per_point = self._series(entry, column.name, label)
                    for point, value in enumerate(values[column.name]):
                        reference = self._series(per_point, str(point), label)
                        count += 1
                        self._compare(
                            column, f"{label} point {point}", value, reference, index, failures
                        )
        self.checked_times.append(time)
        if failures:
            listed = failures[:MAX_LISTED_FAILURES]
            more = len(failures) - len(listed)
            raise ResultCheckError(
                f'{len(failures)} of {count} checked values of "{self.model_part.FullName()}" '
                f'differ from "{self.input_file_name}" at TIME {time:.10g} '
                f"(reference TIME {data['TIME'][index]:.10g})\n  "
                + "\n  ".join(listed)
                + (f"\n  ... and {more} more" if more else "")
                + f"\n  allowed:  |value - reference| <= max(relative_tolerance "
                f"{self.relative_tolerance:g} * max(|value|, |reference|), tolerance "
                f"{self.tolerance:g})"
            )

    # -- helpers --

    def _reference(self) -> dict[str, Any]:
        if self._data is None:
            self._data = self._read()
        return self._data

    def _read(self) -> dict[str, Any]:
        path = Path(self.input_file_name)
        where = self.settings.Where("input_file_name")
        data = load_file(path, "reference file", where)
        times = data.get("TIME") if isinstance(data, dict) else None
        if not isinstance(times, list) or not times:
            raise InputError(
                f'the reference file "{path}" has no "TIME" list\n  where:    {where}\n'
                "  expected: the layout json_output_process writes"
            )
        return data

    def _entry(self, data: dict[str, Any], key: str, label: str) -> dict[str, Any]:
        entry = data.get(key)
        if not isinstance(entry, dict):
            raise InputError(
                f'the reference file "{self.input_file_name}" has no results of {label} ("{key}")\n'
                f"  where:    {self.settings.Where('input_file_name')}\n"
                "  fix:      check model_part_name and check_for_flag, or regenerate the file with "
                "json_output_process"
            )
        return entry

    def _series(self, entry: dict[str, Any], key: str, label: str) -> Any:
        series = entry.get(key)
        if series is None:
            raise InputError(
                f'the reference file "{self.input_file_name}" has no "{key}" for {label}\n'
                f"  where:    {self.settings.Where('input_file_name')}\n"
                "  fix:      check check_variables / gauss_points_check_variables, or regenerate "
                "the file"
            )
        return series

    def _compare(
        self,
        column: Column,
        label: str,
        value: Value,
        series: Any,
        index: int,
        failures: list[str],
    ) -> None:
        if not isinstance(series, list) or index >= len(series):
            raise InputError(
                f'the reference file "{self.input_file_name}" stores fewer values of '
                f"{column.name} for {label} than TIME entries\n"
                f"  where:    {self.settings.Where('input_file_name')}"
            )
        reference = series[index]
        if reference is None:
            failures.append(f"{column.name} of {label}: the reference has no value at this time")
            return
        values = value if isinstance(value, list) else [value]
        references = reference if isinstance(reference, list) else [reference]
        if len(values) != len(references):
            failures.append(
                f"{column.name} of {label}: {len(values)} components, the reference has "
                f"{len(references)}"
            )
            return
        for a, b in zip(values, references, strict=True):
            b = float(b)
            difference = abs(a - b)
            scale = max(abs(a), abs(b))
            relative = difference / scale if scale > 0.0 else 0.0
            if math.isnan(difference):
                difference = relative = math.inf
            name = column.name
            self.worst_absolute_errors[name] = max(self.worst_absolute_errors[name], difference)
            self.worst_relative_errors[name] = max(self.worst_relative_errors[name], relative)
            if not math.isclose(a, b, rel_tol=self.relative_tolerance, abs_tol=self.tolerance):
                failures.append(
                    f"{name} of {label}: value {a:.10g}, reference {b:.10g}, "
                    f"|difference| {difference:.3g} (relative {relative:.3g})"
                )
