"""``json_output_process``.

Write nodal (and integration-point) results over time to a JSON file in the layout
``from_json_check_result_process`` reads (see ``_json_results``).

Keys: ``output_variables`` ([]), ``gauss_points_output_variables`` ([]), ``output_file_name``
(required), ``model_part_name`` (required), ``sub_model_part_name`` (""), ``check_for_flag`` (""
= every node; else only nodes — and elements — with that flag; other times get ``null``),
``time_frequency`` (1.0), ``historical_value`` (true), ``resultant_solution`` (false: true writes
the sum over the nodes under ``"RESULTANT"`` instead of one entry per node),
``use_node_coordinates`` (false: true keys nodes by their initial coordinates).

``ExecuteBeforeSolutionLoop`` writes the empty skeleton; at the end of a step DELTA_TIME is added to
a counter and only when it **strictly exceeds** ``time_frequency`` is it reset and TIME plus the
values appended and the whole file rewritten.

After a restart (ProcessInfo IS_RESTARTED) the file of the interrupted run is read back, cut to the
entries it held when the restart file was written (steps written after it, by a run killed later,
are dropped) and continued with the counter of that moment, so the whole run's file is the one a
run without the restart writes. Without the file the restarted run writes its own steps only.
"""

from __future__ import annotations

import json
import logging
import os
from pathlib import Path
from typing import Any

import numpy as np

from .. import _core
from .._core import InputError, Model
from ..launch_rank import is_output_rank
from ..parameters import Parameters
from ._json_results import (
    element_key,
    gauss_values,
    nodal_value,
    node_key,
    read_columns,
    results_model_part,
)
from ._utilities import validate
from .process import Process

LOGGER = logging.getLogger(__name__)

DEFAULTS = {
    "output_variables": [],
    "gauss_points_output_variables": [],
    "output_file_name": "",
    "model_part_name": "",
    "sub_model_part_name": "",
    "check_for_flag": "",
    "time_frequency": 1.0,
    "historical_value": True,
    "resultant_solution": False,
    "use_node_coordinates": False,
}


def Factory(settings: Parameters, model: Model) -> Process:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return JsonOutputProcess(model, settings["Parameters"])


class JsonOutputProcess(Process):
    """Append results to a JSON file at the end of the steps ``time_frequency`` selects.

    Args:
        model: the model holding the model part.
        settings: the ``Parameters`` block.

    Raises:
        InputError: unknown key, model part, variable or flag; a variable the solver does not store
            historically while ``historical_value`` is true; an output file name that is empty.
    """

    def __init__(self, model: Model, settings: Parameters) -> None:
        validate(settings, DEFAULTS, ("output_file_name", "model_part_name"), "json_output_process")
        self.model_part = results_model_part(model, settings)
        self.output_file_name = settings["output_file_name"].GetString()
        if not self.output_file_name:
            raise InputError(
                f"output_file_name is empty\n  where:    {settings.Where('output_file_name')}\n"
                '  fix:      name the file, e.g. "case_results.json"'
            )
        self.historical, self.columns, self.gauss_columns, self.flag = read_columns(
            settings, self.model_part, "output_variables", "gauss_points_output_variables"
        )
        self.time_frequency = settings["time_frequency"].GetDouble()
        self.resultant_solution = settings["resultant_solution"].GetBool()
        self.use_node_coordinates = settings["use_node_coordinates"].GetBool()
        self.data: dict[str, Any] | None = None
        self._time_counter = 0.0
        self._restart_state: dict[str, Any] | None = None

    def ExecuteBeforeSolutionLoop(self) -> None:
        """Write the skeleton (TIME and one empty list per entity and column); restarts: above."""
        if self.model_part.ProcessInfo[_core.IS_RESTARTED] and self._resume():
            return
        self._skeleton()
        self._write()

    def GetRestartState(self) -> dict[str, Any]:
        """The counter and the number of entries written so far."""
        written = len(self.data["TIME"]) if self.data is not None else 0
        return {"time_counter": self._time_counter, "entries": written}

    def SetRestartState(self, state: dict[str, Any]) -> None:
        """Keep the saved counter and entry count for ``ExecuteBeforeSolutionLoop``."""
        self._restart_state = state

    def _resume(self) -> bool:
        """Continue the file of the interrupted run; False (with a warning) when it is unusable."""
        path = Path(self.output_file_name)
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError) as failure:
            LOGGER.warning(
                'json_output_process: after the restart "%s" cannot be continued (%s); it is '
                "written again with the steps after the restart only",
                path,
                failure,
            )
            return False
        if not isinstance(data, dict) or not isinstance(data.get("TIME"), list):
            LOGGER.warning(
                'json_output_process: "%s" has no TIME list; it is written again with the steps '
                "after the restart only",
                path,
            )
            return False
        if self._restart_state is not None:
            entries = int(self._restart_state["entries"])
            self._time_counter = float(self._restart_state["time_counter"])
        else:  # a restart file without this process' state: the entries up to its TIME
            time = float(self.model_part.ProcessInfo[_core.TIME])
            reach = time + 1e-9 * max(1.0, abs(time))
            entries = sum(1 for t in data["TIME"] if t <= reach)
        if len(data["TIME"]) < entries:
            LOGGER.warning(
                'json_output_process: "%s" holds %d of the %d entries written before the restart; '
                "it goes on from them",
                path,
                len(data["TIME"]),
                entries,
            )
        _truncate(data, entries)
        self.data = data
        self._write()
        return True

    def ExecuteFinalizeSolutionStep(self) -> None:
        """Append this step if the time since the last output exceeds ``time_frequency``."""
        process_info = self.model_part.ProcessInfo
        self._time_counter += process_info[_core.DELTA_TIME]
        if self._time_counter > self.time_frequency:
            self._time_counter = 0.0
            self.append(process_info[_core.TIME])

    def append(self, time: float) -> None:
        """Append TIME and the current values and rewrite the file."""
        data = self._skeleton()
        data["TIME"].append(float(time))
        count = len(data["TIME"])
        nodes = [n for n in self.model_part.Nodes if self._selected(n)]
        if self.resultant_solution:
            resultant = data["RESULTANT"]
            for column in self.columns:
                values = [np.asarray(nodal_value(n, column, self.historical)) for n in nodes]
                total = np.sum(values, axis=0) if values else 0.0
                resultant[column.name].append(_plain(total))
        else:
            for node in nodes:
                entry = data.setdefault(node_key(node, self.use_node_coordinates), {})
                for column in self.columns:
                    series = entry.setdefault(column.name, [None] * (count - 1))
                    series.append(nodal_value(node, column, self.historical))
        if self.gauss_columns:
            process_info = self.model_part.ProcessInfo
            for element in self.model_part.Elements:
                if not self._selected(element):
                    continue
                entry = data.setdefault(element_key(element), {})
                at_points = gauss_values(element, self.gauss_columns, process_info)
                for column in self.gauss_columns:
                    per_point = entry.setdefault(column.name, {})
                    for point, value in enumerate(at_points[column.name]):
                        per_point.setdefault(str(point), [None] * (count - 1)).append(value)
        _pad(data, count)
        self._write()

    # -- helpers --

    def _selected(self, entity: Any) -> bool:
        return self.flag is None or entity.Is(self.flag)

    def _skeleton(self) -> dict[str, Any]:
        if self.data is not None:
            return self.data
        data: dict[str, Any] = {"TIME": []}
        if self.resultant_solution:
            data["RESULTANT"] = {column.name: [] for column in self.columns}
        elif self.columns:
            for node in self.model_part.Nodes:
                if self._selected(node):
                    key = node_key(node, self.use_node_coordinates)
                    data[key] = {column.name: [] for column in self.columns}
        if self.gauss_columns:
            for element in self.model_part.Elements:
                if self._selected(element):
                    data[element_key(element)] = {column.name: {} for column in self.gauss_columns}
        self.data = data
        return data

    def _write(self) -> None:
        if not is_output_rank():  # the other MPI ranks hold the same results (launch_rank.py)
            return
        path = Path(self.output_file_name)
        if path.parent != Path():
            path.parent.mkdir(parents=True, exist_ok=True)
        temporary = path.with_name(path.name + ".tmp")
        with open(temporary, "w", encoding="utf-8") as stream:
            json.dump(self.data, stream)
        os.replace(temporary, path)


def _plain(value: Any) -> float | list[float]:
    array = np.asarray(value, dtype=float)
    return float(array) if array.ndim == 0 else [float(v) for v in array.ravel()]


def _truncate(tree: dict[str, Any], count: int) -> None:
    """Cut every series (TIME included) to its first ``count`` entries."""
    for value in tree.values():
        if isinstance(value, dict):
            _truncate(value, count)
        elif isinstance(value, list):
            del value[count:]


def _pad(tree: dict[str, Any], count: int) -> None:
    """Append null to every series shorter than TIME (entities not written at this time)."""
    for key, value in tree.items():
        if key == "TIME":
            continue
        if isinstance(value, dict):
            _pad(value, count)
        elif isinstance(value, list) and len(value) < count:
            value.extend([None] * (count - len(value)))
