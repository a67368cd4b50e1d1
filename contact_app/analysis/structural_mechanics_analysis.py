"""Structural analysis stage (Kratos ``structural_mechanics_analysis``) and ``run``.

Top-level keys of ``ProjectParameters.json``:

* ``problem_data`` (required): ``problem_name``, ``parallel_type`` ("OpenMP"), ``echo_level``,
  ``start_time`` (0.0), ``end_time`` (required).
* ``solver_settings`` (required): validated by the solver (``solvers/mechanical_solver.py``).
* ``processes``, ``output_processes``: objects whose values are lists of process descriptors.
* ``modelers``: must be empty (modelers are not supported).
* ``analysis_stage``: accepted when it names the structural analysis.
* ``restart_options``: ``SaveRestart``, ``RestartFrequency``, ``LoadRestart``, ``Restart Step``,
  ``RestartControl``, ``Serializer Trace`` (``contact_app/io/restart_utility.py``; ``LoadRestart``
  becomes ``model_import_settings.input_type`` "rest").
* ``constraints_data``, any key starting with ``_``: ignored (``_`` = a disabled block).

Anything else is an error. The process lists of old files at the top level
(``constraints_process_list``, ``loads_process_list``, ...) are rejected as Kratos does ("the old
way"); so is mixing them with ``processes``. ``end_time`` below ``start_time`` is an error (a typo
in most cases); ``end_time == start_time`` runs no step.
"""

from __future__ import annotations

import copy
import json
import logging
import math
import os
from pathlib import Path
from typing import Any

import contact_app as ca

from ..io.restart_utility import ProcessStates, RestartUtility
from ..json_input import quote
from ..launch_rank import is_output_rank, launch_rank
from ..parameters import Parameters, suggest
from .analysis_stage import AnalysisStage
from .outputs import CheckOutputs
from .paths import PathResolver
from .process_factory import KratosProcessFactory
from .reporting import Reporter
from .solvers.solver_wrapper import CreateSolver
from .validation import choice, error, not_supported

logger = logging.getLogger("contact_app.analysis")

TOP_LEVEL_KEYS = (
    "problem_data",
    "solver_settings",
    "processes",
    "output_processes",
    "modelers",
    "analysis_stage",
)
IGNORED_KEYS = ("restart_options", "constraints_data")  # restart_options: checked on its own
#: ``restart_options`` of the Kratos structural analysis (contact_app/io/restart_utility.py).
RESTART_OPTION_KEYS: dict[str, Any] = {
    "SaveRestart": False,
    "RestartFrequency": 0.0,
    "LoadRestart": False,
    "Restart Step": 0.0,
    "RestartControl": "time",
    "Serializer Trace": "no_trace",
}
LEGACY_PROCESS_LISTS = (
    "constraints_process_list",
    "loads_process_list",
    "list_other_processes",
    "json_output_process",
    "json_check_process",
    "check_analytic_results_process",
    "contact_process_list",
)
PROBLEM_DATA_KEYS: dict[str, Any] = {
    "problem_name": "",
    "parallel_type": "OpenMP",
    "echo_level": 0,
    "start_time": 0.0,
    "end_time": 1.0,
}
#: Keys old files had in problem_data that now live in solver_settings.
MOVED_TO_SOLVER = ("model_part_name", "domain_size", "time_step", "time_stepping")
STRUCTURAL_STAGES = (
    "KratosMultiphysics.StructuralMechanicsApplication.structural_mechanics_analysis",
    "KratosMultiphysics.ContactStructuralMechanicsApplication.contact_structural_mechanics_analysis",
)


def _as_parameters(project_parameters: Parameters | dict[str, Any]) -> Parameters:
    if isinstance(project_parameters, Parameters):
        return project_parameters
    if isinstance(project_parameters, dict):  # a copy: the caller's dict stays as written
        return Parameters(copy.deepcopy(project_parameters), source="<parameters>")
    raise TypeError(
        f"project_parameters must be Parameters or a dict, got {type(project_parameters).__name__}"
    )


def ValidateProjectParameters(parameters: Parameters) -> None:
    """Check the top-level keys and ``problem_data`` (defaults added).

    Raises:
        InputError: not an object, unknown key (with a suggestion), legacy process lists, missing
            problem_data / solver_settings / end_time, wrong types, end_time < start_time.
        ConfigurationError: modelers, a non-structural analysis_stage.

    """
    if not parameters.IsSubParameter():
        raise error(
            parameters,
            None,
            "the parameters are not a JSON object",
            '{"problem_data": ..., "solver_settings": ...}',
        )
    keys = parameters.keys()
    legacy = [k for k in keys if k in LEGACY_PROCESS_LISTS]
    if legacy:
        has_new = False
        if parameters.Has("processes") and parameters["processes"].IsSubParameter():
            has_new = any(value.size() for value in parameters["processes"].values())
        what = (
            "mixing of process initialization is not allowed: "
            if has_new
            else "the old way to create the processes was removed: "
        )
        raise error(
            parameters,
            legacy[0],
            f'{what}top-level "{legacy[0]}"',
            'process lists inside "processes": {"' + legacy[0] + '": [ ... ]}',
            f'move "{legacy[0]}" into the "processes" object',
        )
    if parameters.Has("output_configuration"):
        raise error(
            parameters,
            "output_configuration",
            'top-level "output_configuration" is not used any more',
            '"output_processes": {"vtk_output": [ ... ]}',
            "describe outputs as output processes (vtk_output_process, json_output_process)",
        )
    for key in keys:
        if key in TOP_LEVEL_KEYS or key in IGNORED_KEYS or key.startswith("_"):
            continue
        raise error(
            parameters,
            key,
            f'unknown top-level key "{quote(key)}"',
            "one of "
            + ", ".join(f'"{k}"' for k in TOP_LEVEL_KEYS)
            + ' (or a key starting with "_" to disable a block)',
            suggest(key, list(TOP_LEVEL_KEYS) + list(IGNORED_KEYS)),
        )
    for key in ("problem_data", "solver_settings"):
        if not parameters.Has(key):
            raise error(parameters, key, f'missing required key "{key}"', f'a "{key}" object')
        if not parameters[key].IsSubParameter():
            raise error(parameters, key, f'"{key}" is not an object', "an object { ... }")
    _ValidateProblemData(parameters["problem_data"])
    solver_settings = parameters["solver_settings"]
    for key in ("time_stepping", "domain_size"):
        if not solver_settings.Has(key):
            raise error(
                solver_settings,
                key,
                f'missing required key "{key}"',
                f'"{key}" in solver_settings',
                f'add "{key}" to solver_settings'
                + (
                    ' (e.g. "time_stepping": {"time_step": 1.0})'
                    if key == "time_stepping"
                    else " (2 or 3)"
                ),
            )
    for key in ("processes", "output_processes"):
        if parameters.Has(key):
            block = parameters[key]
            if not block.IsSubParameter():
                raise error(
                    parameters,
                    key,
                    f'"{key}" is not an object',
                    '{"list_name": [ {descriptor}, ... ]}',
                )
            for name, value in block.items():
                if not value.IsArray():
                    raise error(
                        block, name, f'"{name}" is not a list of processes', "[ {descriptor}, ... ]"
                    )
    if parameters.Has("modelers") and parameters["modelers"].size():
        raise not_supported(
            parameters,
            "modelers",
            "modelers",
            "give the mesh as an mdpa file (model_import_settings)",
        )
    if parameters.Has("analysis_stage"):
        stage = parameters["analysis_stage"].GetString()
        if stage not in STRUCTURAL_STAGES:
            raise not_supported(
                parameters,
                "analysis_stage",
                f'the analysis stage "{stage}"',
                f'use "{STRUCTURAL_STAGES[0]}"',
            )
    if parameters.Has("restart_options"):
        _ValidateRestartOptions(parameters)


def RestartBaseName(parameters: Parameters) -> str:
    """Base name of restart files: problem_name, else the mesh file name, else the model part."""
    name = parameters["problem_data"]["problem_name"].GetString()
    if name:
        return name
    solver = parameters["solver_settings"]
    imports = solver["model_import_settings"] if solver.Has("model_import_settings") else None
    if (
        imports is not None
        and imports.Has("input_filename")
        and imports["input_filename"].GetString()
    ):
        return Path(imports["input_filename"].GetString()).stem
    return solver["model_part_name"].GetString() if solver.Has("model_part_name") else "Structure"


def RestartLabel(value: float, control: str) -> str:
    """The file label of a restart TIME (12 significant digits) or STEP, as the files are named."""
    return str(int(value)) if control == "step" else str(float(f"{value:.12g}"))


def _ValidateRestartOptions(parameters: Parameters) -> None:
    """Check restart_options; LoadRestart becomes model_import_settings input_type "rest"."""
    options = parameters["restart_options"]
    if not options.IsSubParameter():
        raise error(parameters, "restart_options", '"restart_options" is not an object', "{...}")
    if options.Has("Restart_Step") and not options.Has("Restart Step"):
        options.AddValue("Restart Step", options["Restart_Step"])  # the older GiD spelling
        options.RemoveValue("Restart_Step")
    options.ValidateAndAssignDefaults(RESTART_OPTION_KEYS)
    control = choice(options, "RestartControl", ("time", "step"), "RestartControl")
    choice(
        options, "Serializer Trace", ("no_trace", "trace_error", "trace_all"), "Serializer Trace"
    )
    if options["Serializer Trace"].GetString() != "no_trace":
        logger.warning(
            "%s: restart files are always binary with every section checked; no trace is written",
            options.Where("Serializer Trace"),
        )
    for key in ("RestartFrequency", "Restart Step"):
        value = options[key].GetDouble()
        if not math.isfinite(value) or value < 0.0:
            raise error(options, key, f"{key} {value} is not a finite number >= 0", "0 or more")
    if not options["LoadRestart"].GetBool():
        return
    solver = parameters["solver_settings"]
    if not solver.Has("model_import_settings"):
        solver.AddValue("model_import_settings", {})
    imports = solver["model_import_settings"]
    base = RestartBaseName(parameters)
    label = RestartLabel(options["Restart Step"].GetDouble(), control)
    for key, text in (
        ("input_type", "rest"),
        ("input_filename", base),
        ("restart_load_file_label", label),
    ):
        if imports.Has(key):
            imports.RemoveValue(key)
        imports.AddValue(key, text)


def _ValidateProblemData(problem_data: Parameters) -> None:
    for key in MOVED_TO_SOLVER:
        if problem_data.Has(key):
            raise error(
                problem_data,
                key,
                f'"{key}" in problem_data is the old way, which was removed',
                f'"{key}" in solver_settings',
                f'move "{key}" to solver_settings'
                + (' as "time_stepping": {"time_step": ...}' if key == "time_step" else ""),
            )
    if not problem_data.Has("end_time"):
        raise error(
            problem_data,
            "end_time",
            'missing required key "end_time"',
            "the end time of the analysis",
        )
    problem_data.ValidateAndAssignDefaults(PROBLEM_DATA_KEYS)
    choice(problem_data, "parallel_type", ("OpenMP", "MPI"), "parallel_type")
    if problem_data["parallel_type"].GetString() == "MPI":
        raise not_supported(problem_data, "parallel_type", 'parallel_type "MPI"', 'use "OpenMP"')
    start, end = problem_data["start_time"].GetDouble(), problem_data["end_time"].GetDouble()
    if end < start:
        raise error(
            problem_data,
            "end_time",
            f"end_time {end} is before start_time {start}",
            "end_time ≥ start_time (equal runs no step)",
            "swap the two values or correct the typo",
        )


class StructuralMechanicsAnalysis(AnalysisStage):
    """Structural (and, later, contact) analysis of a ``ProjectParameters.json``.

    Everything is validated in the constructor before any file is read (solver settings,
    materials, process modules, linear solver and criterion names); the mdpa is read by
    ``Initialize``.

    Args:
        model: the model to work on.
        project_parameters: the parameters (``Parameters`` or a plain dict); completed in place.
        base_dir: folder of the parameters file: relative paths that do not exist from the working
            directory are looked up there (None = working directory only).
        stop_on_non_convergence: True: raise ``ConvergenceError`` at the first unconverged step;
            False: go on from it; None: as ``solver_settings.on_non_converged_step`` says
            ("stop" by default).
        reporter: console report (default: table and summary on stdout).
        safe: create only contact_app's own processes (no module from the case folder).
        parameters_file: the parameters file itself, which no output may overwrite.

    Raises:
        InputError: invalid parameters (the message says what, where and how to fix it).
        ConfigurationError: an option contact_app does not implement (yet).

    """

    def __init__(
        self,
        model: ca.Model,
        project_parameters: Parameters | dict[str, Any],
        *,
        base_dir: str | Path | None = None,
        stop_on_non_convergence: bool | None = None,
        reporter: Reporter | None = None,
        safe: bool = False,
        parameters_file: str | Path | None = None,
    ):
        if not isinstance(model, ca.Model):
            raise TypeError(f"model must be a contact_app.Model, got {type(model).__name__}")
        parameters = _as_parameters(project_parameters)
        ValidateProjectParameters(parameters)
        super().__init__(
            model, parameters, stop_on_non_convergence=stop_on_non_convergence, reporter=reporter
        )
        self.paths = PathResolver(base_dir)
        self.contact_problem = any(
            parameters["solver_settings"].Has(k)
            for k in ("contact_settings", "mpc_contact_settings")
        )
        self._factory = KratosProcessFactory(model, self.paths, safe=safe)
        self._restart: Any = None
        self._GetSolver().AddVariables()
        self._expected_steps = self._GetSolver().CountSteps(self.start_time, self.end_time)
        self._CheckProcessModules()
        inputs = self._GetSolver().InputFiles()
        if parameters_file is not None:
            inputs.append((str(parameters_file), "the parameters file"))
        CheckOutputs(parameters, ("processes", "output_processes"), self.paths, inputs)

    def _CreateSolver(self) -> Any:
        return CreateSolver(self.model, self.project_parameters, self.paths)

    def _CheckProcessModules(self) -> None:
        """Resolve every process module now, so that a typo fails before the mesh is read."""
        for key in ("processes", "output_processes"):
            if self.project_parameters.Has(key):
                for process_list in self.project_parameters[key].values():
                    for item in process_list:
                        self._factory.ResolveModule(item)

    def _CreateProcesses(self, parameter_name: str) -> list[Any]:
        if not self.project_parameters.Has(parameter_name):
            return []
        processes: list[Any] = []
        for process_list in self.project_parameters[parameter_name].values():
            processes += self._factory.ConstructListOfProcesses(process_list)
        return processes

    def Initialize(self) -> None:
        """Kratos Initialize, plus ``ProjectParametersOutput.json`` when echo_level > 1."""
        super().Initialize()
        if launch_rank() > 0:
            logger.info(
                "MPI rank %d: this rank computes the same model as rank 0, which alone writes the "
                "files and prints the run's table",
                launch_rank(),
            )
        self._restart = self._CreateRestartSaver()
        if self.echo_level > 1 and is_output_rank():
            with open("ProjectParametersOutput.json", "w", encoding="utf-8") as stream:
                json.dump(self.project_parameters.GetValue(), stream, indent=4)

    def _ExpectedSteps(self) -> int | None:
        return self._expected_steps

    def OutputSolutionStep(self) -> None:
        """Kratos OutputSolutionStep, then the restart file of the step when one is due."""
        super().OutputSolutionStep()
        if self._restart is not None and self._restart.IsRestartOutputStep() and is_output_rank():
            info = self._GetSolver().main_model_part.ProcessInfo
            info[ca.RESTART_PROCESS_STATES] = ProcessStates(self._GetListOfProcesses())
            self._restart.SaveRestart()

    def _CreateRestartSaver(self) -> Any:
        """The RestartUtility of ``restart_options.SaveRestart`` (None when not saving)."""
        if not self.project_parameters.Has("restart_options"):
            return None
        options = self.project_parameters["restart_options"]
        if not options["SaveRestart"].GetBool():
            return None
        return RestartUtility(
            self._GetSolver().main_model_part,
            RestartBaseName(self.project_parameters),
            restart_save_frequency=options["RestartFrequency"].GetDouble(),
            restart_control_type=options["RestartControl"].GetString(),
        )

    def Finalize(self) -> None:
        """Kratos Finalize, then the summary (with the files the outputs wrote)."""
        super().Finalize()
        self.reporter.files = self._WrittenFiles()
        self.reporter.finish()

    def _WrittenFiles(self) -> list[str]:
        """Files under the output paths of the processes modified since the run started."""
        started = self.reporter.started_wall
        found: set[str] = set()
        candidates: list[str] = []
        for key in ("processes", "output_processes"):
            if not self.project_parameters.Has(key):
                continue
            for process_list in self.project_parameters[key].values():
                for item in process_list:
                    if (
                        item.IsSubParameter()
                        and item.Has("Parameters")
                        and item["Parameters"].IsSubParameter()
                    ):
                        settings = item["Parameters"]
                        for name in ("output_file_name", "output_path", "folder_name"):
                            if settings.Has(name) and settings[name].IsString():
                                candidates.append(settings[name].GetString())
        if self.echo_level > 1:
            candidates.append("ProjectParametersOutput.json")
        for candidate in candidates:
            path = Path(candidate)
            files = [path] if path.is_file() else (sorted(path.rglob("*")) if path.is_dir() else [])
            for file in files:
                if file.is_file() and file.stat().st_mtime >= started - 1.0:
                    found.add(os.path.relpath(file) if not file.is_absolute() else str(file))
        return sorted(found)


def run(
    path_or_dict: str | Path | dict[str, Any] | Parameters,
    *,
    stop_on_non_convergence: bool | None = None,
    quiet: bool = False,
    model: ca.Model | None = None,
    safe: bool = False,
) -> StructuralMechanicsAnalysis:
    """Run an analysis from a ``ProjectParameters.json`` path or an in-memory tree.

    Relative paths inside a file resolve against the working directory, falling back to the
    file's own folder (see :mod:`contact_app.analysis.paths`).

    Args:
        path_or_dict: the parameters file, or the parameters as a dict / ``Parameters``.
        stop_on_non_convergence: True: stop with ``ConvergenceError`` at the first unconverged
            step; False: go on; None: ``solver_settings.on_non_converged_step`` ("stop").
        quiet: no console table or summary.
        model: the model to fill (default: a new one).
        safe: run only contact_app's own processes (``contact-app run --safe``).

    Returns:
        The finished analysis (its ``model`` holds the results).

    Raises:
        InputError, ConfigurationError: invalid input, before anything runs.
        ConvergenceError: a step that did not converge (unless the run goes on from it).

    """
    base_dir: Path | None = None
    path: Path | None = None
    if isinstance(path_or_dict, str | Path):
        path = Path(path_or_dict)
        parameters = Parameters.from_file(path)
        base_dir = path.resolve().parent
    else:
        parameters = _as_parameters(path_or_dict)
    analysis = StructuralMechanicsAnalysis(
        model if model is not None else ca.Model(),
        parameters,
        base_dir=base_dir,
        stop_on_non_convergence=stop_on_non_convergence,
        reporter=Reporter(quiet=quiet or not is_output_rank()),
        safe=safe,
        parameters_file=path,
    )
    analysis.Run()
    return analysis
