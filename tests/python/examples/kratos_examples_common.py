"""What the reference fixtures of the example-collection models record, for both systems.

The models are the reference's public example collection in ``../shared/kratos_examples`` (read
from there at run time, never copied). This module is plain Python over a Kratos-like API: the
oracle script (``scripts/oracle/kratos_examples.py``) passes ``KratosMultiphysics`` and its
analysis class, the tests and the benchmark pass ``contact_app`` and ours, and both record the same
numbers the same way:

* per step: TIME, Newton iterations (``NL_ITERATION_NUMBER``), wall and CPU time (of the process:
  one thread) since the previous step,
  whether the solver said it converged, the number of ACTIVE slave nodes and the largest
  |AUGMENTED_NORMAL_CONTACT_PRESSURE| on them;
* at a few steps (``snapshot``): the displacement of named nodes (chosen from the mesh alone, see
  ``pick_nodes``), the REACTION summed over every part a constraint process fixes, the number of
  active slave nodes, the largest and median |pressure| on them, and the contact force
  sum(NODAL_AREA * pressure) over them.
"""

from __future__ import annotations

import copy
import hashlib
import json
import re
import statistics
import time
from pathlib import Path
from typing import Any

EXAMPLES = Path(__file__).resolve().parents[4] / "shared" / "kratos_examples"

#: name -> (case folder under EXAMPLES, parameters file)
MODELS: dict[str, tuple[str, str]] = {
    "press_fit_2d": ("press_fit/source/2D", "ProjectParameters.json"),
    "press_fit_3d": ("press_fit/source/3D", "ProjectParameters.json"),
    "cylinders_vertical": ("cylinders/source/vertical_movement", "ProjectParameters.json"),
    "cylinders_horizontal_1": ("cylinders/source/horizontal_movement_1", "ProjectParameters.json"),
    "cylinders_horizontal_2": ("cylinders/source/horizontal_movement_2", "ProjectParameters.json"),
    "cylinders_horizontal_2_frictional": (
        "cylinders/source/horizontal_movement_2",
        "ProjectParameters_frictional.json",
    ),
    "hyperelastic_tubes": ("hyperelastic_tubes/source", "ProjectParameters.json"),
    "double_arch": ("double_arch/source", "ProjectParameters.json"),
    "double_arch_frictional": ("double_arch/source", "ProjectParameters_frictional.json"),
}

#: The wall-time cap of one run of the reference (seconds): the issue's "about two minutes".
REFERENCE_CAP = 120.0


def case_folder(name: str) -> Path:
    return EXAMPLES / MODELS[name][0]


def raw_parameters(name: str) -> dict:
    folder, parameters = MODELS[name]
    return json.loads((EXAMPLES / folder / parameters).read_text())


def mdpa_path(name: str) -> Path:
    raw = raw_parameters(name)
    stem = raw["solver_settings"]["model_import_settings"]["input_filename"]
    return case_folder(name) / f"{stem}.mdpa"


def mdpa_sha256(name: str) -> str:
    return hashlib.sha256(mdpa_path(name).read_bytes()).hexdigest()


def prepared_parameters(name: str, end_time: float | None = None) -> dict:
    """The model's parameters as they are, with absolute input paths, no outputs, ``end_time``.

    The run can then take place in any (scratch) folder and writes nothing. Nothing else is
    changed: solver, contact and time-stepping settings are the model's own.
    """
    raw = copy.deepcopy(raw_parameters(name))
    folder = case_folder(name)
    settings = raw["solver_settings"]
    imports = settings["model_import_settings"]
    imports["input_filename"] = str(folder / imports["input_filename"])
    materials = settings.get("material_import_settings", {})
    if "materials_filename" in materials:
        materials["materials_filename"] = str(folder / materials["materials_filename"])
    raw["output_processes"] = {}
    raw["problem_data"]["echo_level"] = 0
    if end_time is not None:
        raw["problem_data"]["end_time"] = end_time
    return raw


def body_parts(name: str) -> list[str]:
    """The sub model parts of the mdpa that hold elements (the bodies), in file order."""
    text = mdpa_path(name).read_text()
    parts = []
    for match in re.finditer(
        r"^Begin SubModelPart (\S+).*?^\s*Begin SubModelPartElements\s*\n(.*?)^\s*End "
        r"SubModelPartElements",
        text,
        flags=re.MULTILINE | re.DOTALL,
    ):
        if match.group(2).strip():
            parts.append(match.group(1))
    return parts


def contact_parts(raw: dict) -> list[str]:
    """The sub model parts named by the contact processes, in order, without repeats."""
    names: list[str] = []
    for process in raw["processes"].get("contact_process_list", []):
        for group in process["Parameters"].get("contact_model_part", {}).values():
            for part in group:
                if part not in names:
                    names.append(part)
    return names


def supports(raw: dict) -> list[str]:
    """The parts whose DISPLACEMENT a constraint process fixes in at least one component."""
    names: list[str] = []
    for process in raw["processes"].get("constraints_process_list", []):
        settings = process["Parameters"]
        if settings.get("variable_name") != "DISPLACEMENT":
            continue
        if not any(value is not None for value in settings.get("value", [])):
            continue
        part = settings["model_part_name"].split(".", 1)[-1]
        if part not in names:
            names.append(part)
    return names


def _nearest_to_centroid(nodes: list) -> int:
    coordinates = [(n.X0, n.Y0, n.Z0) for n in nodes]
    centre = [sum(c[i] for c in coordinates) / len(coordinates) for i in range(3)]
    best = min(
        range(len(nodes)),
        key=lambda k: (sum((coordinates[k][i] - centre[i]) ** 2 for i in range(3)), nodes[k].Id),
    )
    return int(nodes[best].Id)


def pick_nodes(main: Any, name: str) -> dict[str, int]:
    """Named nodes, from the mesh only: the node nearest the centroid of each body and contact part.

    The same rule on the same mdpa gives the same ids in both systems.
    """
    raw = raw_parameters(name)
    picked: dict[str, int] = {}
    for part in body_parts(name) + contact_parts(raw):
        nodes = list(main.GetSubModelPart(part).Nodes)
        if nodes:
            picked[f"{part}_centroid"] = _nearest_to_centroid(nodes)
    return picked


def _slave_nodes(km: Any, main: Any) -> list:
    part = main.GetSubModelPart("Contact") if main.HasSubModelPart("Contact") else main
    return [node for node in part.Nodes if node.Is(km.SLAVE)]


def contact_state(km: Any, main: Any) -> dict[str, float]:
    """Active slave nodes, largest and median |augmented normal pressure|, contact force."""
    pressures = []
    force = 0.0
    for node in _slave_nodes(km, main):
        if not node.Is(km.ACTIVE):
            continue
        pressure = float(node.GetValue(km.AUGMENTED_NORMAL_CONTACT_PRESSURE))
        pressures.append(abs(pressure))
        force += float(node.GetValue(km.NODAL_AREA)) * pressure
    return {
        "active": len(pressures),
        "pressure_max": max(pressures, default=0.0),
        "pressure_median": statistics.median(pressures) if pressures else 0.0,
        "contact_force": force,
    }


def snapshot(km: Any, main: Any, name: str, nodes: dict[str, int]) -> dict:
    """The full record of one step (see the module's docstring)."""
    raw = raw_parameters(name)
    displacement = {}
    for label, node_id in nodes.items():
        value = main.GetNode(node_id).GetSolutionStepValue(km.DISPLACEMENT)
        displacement[label] = [float(value[0]), float(value[1]), float(value[2])]
    reactions = {}
    for part in supports(raw):
        total = [0.0, 0.0, 0.0]
        for node in main.GetSubModelPart(part).Nodes:
            value = node.GetSolutionStepValue(km.REACTION)
            for i in range(3):
                total[i] += float(value[i])
        reactions[part] = total
    return {
        "time": float(main.ProcessInfo[km.TIME]),
        "step": int(main.ProcessInfo[km.STEP]),
        "displacement": displacement,
        "reactions": reactions,
        **contact_state(km, main),
    }


def recording_analysis(base: type, km: Any) -> type:
    """``base`` (a StructuralMechanicsAnalysis) recording every step, stopping at a wall cap.

    ``history`` gets one entry per finalized step; ``snapshots`` the full record of every step
    (``keep_snapshots`` filters which are kept: a callable of TIME, default all). The loop stops
    before starting a step once ``wall_cap`` seconds have passed since ``Initialize`` ended.
    """

    class Recording(base):
        def __init__(self, model, parameters, name, *, wall_cap=None, keep_snapshots=None, **kw):
            super().__init__(model, parameters, **kw)
            self.example = name
            self.wall_cap = wall_cap
            self.keep_snapshots = keep_snapshots
            self.history: list[dict] = []
            self.snapshots: list[dict] = []
            self.nodes: dict[str, int] = {}
            self.capped = False
            self.initialize_time = 0.0
            self._constructed = time.perf_counter()
            self._mark = self._constructed
            self._cpu_mark = time.process_time()
            self._loop_started = None
            self._last_converged = None

        def Initialize(self):  # noqa: N802 - Kratos name
            super().Initialize()
            main = self.model.GetModelPart("Structure")
            self.nodes = pick_nodes(main, self.example)
            solver = self._GetSolver()
            solve = solver.SolveSolutionStep

            def solve_and_note():
                converged = solve()
                self._last_converged = bool(converged) if converged is not None else None
                return converged

            solver.SolveSolutionStep = solve_and_note
            self._mark = self._loop_started = time.perf_counter()
            self._cpu_mark = time.process_time()
            self.initialize_time = self._loop_started - self._constructed

        def KeepAdvancingSolutionLoop(self):  # noqa: N802 - Kratos name
            if self.wall_cap is not None and self._loop_started is not None:
                if time.perf_counter() - self._loop_started > self.wall_cap:
                    self.capped = True
                    return False
            return super().KeepAdvancingSolutionLoop()

        def FinalizeSolutionStep(self):  # noqa: N802 - Kratos name
            super().FinalizeSolutionStep()
            now = time.perf_counter()
            cpu = time.process_time()
            main = self.model.GetModelPart("Structure")
            record = snapshot(km, main, self.example, self.nodes)
            self.history.append(
                {
                    "time": record["time"],
                    "iterations": int(main.ProcessInfo[km.NL_ITERATION_NUMBER]),
                    "wall": now - self._mark,
                    "cpu": cpu - self._cpu_mark,
                    "converged": self._last_converged,
                    "active": record["active"],
                    "pressure_max": record["pressure_max"],
                }
            )
            if self.keep_snapshots is None or self.keep_snapshots(record["time"]):
                self.snapshots.append(record)
            self._mark = time.perf_counter()
            self._cpu_mark = time.process_time()

    return Recording


def at_time(records: list[dict], when: float, tolerance: float = 1.0e-9) -> dict | None:
    """The record at TIME ``when`` (within ``tolerance``), or None."""
    for record in records:
        if abs(record["time"] - when) <= tolerance * max(1.0, abs(when)):
            return record
    return None


def run_ours(
    name: str, end_time: float | None = None, wall_cap: float | None = None, keep_snapshots=None
) -> tuple[Any, str | None]:
    """Run contact_app on a model (in a scratch folder) to ``end_time``; (analysis, failure).

    ``failure`` is the first line of the ConvergenceError that stopped the run, or None. The
    import stays inside: the oracle's environment has no contact_app.
    """
    import os
    import tempfile

    import contact_app as ca
    from contact_app.analysis import StructuralMechanicsAnalysis
    from contact_app.analysis.reporting import Reporter

    raw = prepared_parameters(name, end_time)
    analysis_class = recording_analysis(StructuralMechanicsAnalysis, ca)
    previous = Path.cwd()
    failure = None
    with tempfile.TemporaryDirectory() as scratch:
        os.chdir(scratch)
        try:
            analysis = analysis_class(
                ca.Model(),
                raw,
                name,
                wall_cap=wall_cap,
                keep_snapshots=keep_snapshots,
                reporter=Reporter(quiet=True),
            )
            try:
                analysis.Run()
            except ca.ConvergenceError as error:
                failure = str(error).strip().splitlines()[0]
        finally:
            os.chdir(previous)
    return analysis, failure
