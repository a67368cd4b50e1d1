"""Base structural solver (Kratos ``structural_mechanics_solver.MechanicalSolver``).

It owns the main model part, validates ``solver_settings`` against :meth:`GetDefaultParameters`
(after converting the deprecated keys old files use, with a warning each), imports the mdpa and the
materials, adds variables and DoFs, and builds linear solver, builder and solver, convergence
criterion and strategy on demand. Derived solvers provide the scheme (:meth:`_CreateScheme`) and
may extend the defaults, variables and DoFs; the contact solvers derive from this class the same
way.
"""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Any

import contact_app as ca

from ...legacy_keys import convert_legacy_keys
from ...parameters import Parameters, suggest
from ..materials import CheckMeshProperties, MaterialsReader
from ..paths import PathResolver
from ..time_loop import count_steps
from ..validation import choice, error, not_supported, positive
from .convergence_criteria_factory import (
    ConvergenceCriterion,
    CreateConvergenceCriterion,
    check_criterion_name,
)

logger = logging.getLogger("contact_app.analysis")

#: Every key a ``linear_solver_settings`` block may hold (Kratos linear solver factories). Only
#: ``solver_type``, ``tolerance``, ``max_iteration``, ``ordering`` (contact_app's own: UMFPACK's
#: fill-reducing ordering, "auto", "amd" or "metis") and ``static_condensation`` (contact_app's
#: own: "auto", true or false; None here because it takes a string or a bool, checked by
#: :func:`static_condensation_mode`) change what contact_app does; the others tune Kratos'
#: iterative solvers and are accepted and ignored.
LINEAR_SOLVER_KEYS: dict[str, Any] = {
    "solver_type": "",
    "tolerance": 1.0e-6,
    "max_iteration": 1000,
    "ordering": "auto",
    "static_condensation": None,
    "scaling": False,
    "verbosity": 0,
    "echo_level": 0,
    "preconditioner_type": "",
    "krylov_type": "",
    "smoother_type": "",
    "coarsening_type": "",
    "gmres_krylov_space_dimension": 100,
    "block_size": 1,
    "use_block_matrices_if_possible": True,
    "coarse_enough": 1000,
    "max_levels": -1,
    "pre_sweeps": 1,
    "post_sweeps": 1,
    "use_gpgpu": False,
    "provide_coordinates": False,
    "reform_preconditioner_at_each_step": True,
    "symmetric_scaling": True,
}

#: The ``linear_solver_settings`` keys the PETSc Krylov solver (solver_type "amgcl", "gmres")
#: honours beyond tolerance and max_iteration (docs/running.md, "Iterative solver (PETSc)").
KRYLOV_KEYS = (
    "krylov_type",
    "preconditioner_type",
    "smoother_type",
    "coarsening_type",
    "gmres_krylov_space_dimension",
    "verbosity",
    "max_levels",
    "coarse_enough",
    "pre_sweeps",
    "post_sweeps",
    "reform_preconditioner_at_each_step",
)
#: Solvers of the iterative route: no static condensation under "auto", every ALM family condensed.
ITERATIVE_SOLVERS = ("petsc",)


def is_iterative(linear: Parameters) -> bool:
    """Whether ``linear_solver_settings.solver_type`` maps to the PETSc Krylov solver."""
    name = linear["solver_type"].GetString() if linear.Has("solver_type") else ""
    try:
        return bool(ca.ResolveLinearSolverName(name) in ITERATIVE_SOLVERS)
    except ca.InputError:
        return False


TIME_STEPPING_KEYS: dict[str, Any] = {
    "time_step": 1.0,
    "time_step_table": [],
    "time_step_intervals": {},
}

LINE_SEARCH_KEYS: dict[str, Any] = {
    "max_line_search_iterations": 5,
    "first_alpha_value": 0.5,
    "second_alpha_value": 1.0,
    "min_alpha": 0.1,
    "max_alpha": 2.0,
    "line_search_tolerance": 0.5,
}

MODEL_IMPORT_KEYS: dict[str, Any] = {
    "input_type": "mdpa",
    "input_filename": "",
    "reorder": False,
    "skip_timer": True,
    "ignore_variables_not_in_solution_step_data": False,
    "mesh_mapping": {},
    # input_type "rest" (Kratos RestartUtility):
    # <input_filename>__restart_files/<input_filename>_<label>.rest
    "restart_load_file_label": "",
    "load_restart_files_from_folder": True,
    "serializer_trace": "no_trace",
}
#: Extensions read through meshio when input_type is left at "mdpa" (detection by extension).
MESHIO_EXTENSIONS = (
    ".msh",
    ".vtu",
    ".vtk",
    ".inp",
    ".med",
    ".xdmf",
    ".xmf",
    ".mesh",
    ".obj",
    ".ply",
)

_FEATURE_FLAGS = {
    "volumetric_strain_dofs": "mixed displacement/volumetric-strain elements",
    "strain_dofs": "mixed displacement/strain elements",
    "pressure_dofs": "mixed displacement/pressure elements",
    "displacement_control": "displacement control",
    "rotation_dofs": "rotation DoFs (shells, beams)",
    "use_orthogonal_subscales": "orthogonal subscales",
    "use_old_stiffness_in_first_iteration": "use_old_stiffness_in_first_iteration",
}


#: ``on_non_converged_step``: "stop" (default) ends the run at a step that did not converge (after
#: step cutting, when it is on); "continue" goes on from that state, as Kratos does by default.
NON_CONVERGED_STEP_POLICIES = ("stop", "continue")
#: Why "stop" is the default, for the log, the summary and the error message.
STOP_DEFAULT_REASON = (
    "a step that did not converge is not an equilibrium, and every later step would start from it "
    "with results that look valid (Kratos goes on by default)"
)
#: Step cutting of an inverted element when the solver has no settings of its own (no
#: contact_settings): Kratos' adaptative_strategy defaults, split_factor 10, max_number_splits 3.
INVERTED_ELEMENT_CUTTING = (10.0, 3)


def static_condensation_mode(linear: Parameters) -> str:
    """``linear_solver_settings.static_condensation`` as the solver's mode: "auto", "on" or "off".

    Raises:
        InputError: neither "auto" nor a bool.

    """
    if not linear.Has("static_condensation"):
        return "auto"
    value = linear["static_condensation"]
    if value.IsBool():
        return "on" if value.GetBool() else "off"
    if value.IsString() and value.GetString() == "auto":
        return "auto"
    raise error(
        linear,
        "static_condensation",
        f"static_condensation is {value.WriteJsonString()}",
        '"auto", true or false',
        'remove the key ("auto": condense when the bodies are linear and the system is large), '
        "or give true / false",
    )


def bulk_not_linear(part: Any) -> str:
    """Why the stiffness of the bodies of ``part`` may change between iterations ("" = it cannot).

    Each element answers for itself (``Element.WhyStiffnessVaries``): it cannot for
    small-displacement elements (kinematics on the initial configuration) with a linear elastic
    law; finite-strain elements and the hyperelastic and Saint Venant-Kirchhoff laws change it
    with the displacement (docs/theory/static_condensation.md).
    """
    for element in part.Elements:
        reason = element.WhyStiffnessVaries()
        if reason:
            return f"element {element.Id} {reason}"
    return ""


class MechanicalSolver:
    """Structural solver base: settings, model part, variables, DoFs, strategy life cycle.

    Args:
        model: the model that holds (or will hold) the main model part.
        custom_settings: the ``solver_settings`` block; converted and validated in place.
        paths: how relative paths resolve (working directory, then the parameters' folder).

    Raises:
        InputError: unknown key (with a suggestion), wrong type, missing required key, bad value.
        ConfigurationError: a valid Kratos option contact_app does not implement.

    """

    def __init__(
        self, model: ca.Model, custom_settings: Parameters, paths: PathResolver | None = None
    ):
        self.model = model
        self.settings = custom_settings
        self.paths = paths or PathResolver()
        self._strategy: Any = None
        self._scheme: Any = None
        self._criterion: ConvergenceCriterion | None = None
        self._linear_solver: Any = None
        self._builder_and_solver: Any = None
        self._materials: MaterialsReader | None = None
        self._mdpa_path = ""
        self._meshio_path = ""
        self._restart_path = ""
        self._meshio_mapping: dict[str, Any] = {}
        self._meshio_where = ""
        self._time_step_table: Any = None
        #: The InvertedElementError of the last SolveSolutionStep that failed on one, else None.
        self.last_failure: Any = None

        self._ConvertDeprecatedSettings()
        had_domain_size = self.settings.Has("domain_size")
        self.settings.ValidateAndAssignDefaults(self.GetDefaultParameters())
        if not had_domain_size:
            raise error(
                self.settings,
                "domain_size",
                'missing required key "domain_size"',
                "2 or 3",
                'add "domain_size": 2 (or 3) to solver_settings',
            )
        self.ValidateSettings()
        self._CreateMainModelPart()

    # -- settings --

    @classmethod
    def GetDefaultParameters(cls) -> dict[str, Any]:
        """Every solver_settings key with its default (Kratos MechanicalSolver, newest)."""
        return {
            "solver_type": "mechanical_solver",
            "model_part_name": "",
            "computing_sub_model_part_name": "",
            "domain_size": -1,
            "echo_level": 0,
            "buffer_size": 2,
            "analysis_type": "non_linear",
            "model_import_settings": {"input_type": "mdpa"},
            "material_import_settings": {"materials_filename": ""},
            "time_stepping": {},
            "volumetric_strain_dofs": False,
            "strain_dofs": False,
            "rotation_dofs": False,
            "pressure_dofs": False,
            "displacement_control": False,
            "reform_dofs_at_each_step": False,
            "use_old_stiffness_in_first_iteration": False,
            "use_orthogonal_subscales": False,
            "compute_reactions": True,
            "solving_strategy_settings": {"type": "newton_raphson", "advanced_settings": {}},
            "builder_and_solver_settings": {"type": "block", "advanced_settings": {}},
            "clear_storage": False,
            "move_mesh_flag": True,
            "multi_point_constraints_used": True,
            "convergence_criterion": "residual_criterion",
            "displacement_relative_tolerance": 1.0e-4,
            "displacement_absolute_tolerance": 1.0e-9,
            "residual_relative_tolerance": 1.0e-4,
            "residual_absolute_tolerance": 1.0e-9,
            "max_iteration": 10,
            "linear_solver_settings": {},
            "auxiliary_variables_list": [],
            "auxiliary_dofs_list": [],
            "auxiliary_reaction_list": [],
            # contact_app's own keys (not in Kratos), docs/running.md "Non-convergence":
            "on_non_converged_step": "stop",
            "cut_step_on_inverted_element": True,
        }

    def _ConvertDeprecatedSettings(self) -> None:
        """Translate the keys of old files (Kratos does the same, with a warning per key)."""
        settings = self.settings
        convert_legacy_keys(settings, "solver_settings")  # renamed and removed keys (one table)
        if settings.Has("model_import_settings"):
            convert_legacy_keys(settings["model_import_settings"], "model_import_settings")
        if settings.Has("block_builder"):
            use_block = settings["block_builder"].GetBool()
            if settings.Has("builder_and_solver_settings") and settings[
                "builder_and_solver_settings"
            ].Has("type"):
                raise error(
                    settings,
                    "block_builder",
                    "both the deprecated block_builder and builder_and_solver_settings.type given",
                    "only builder_and_solver_settings.type",
                    'remove "block_builder"',
                )
            if not settings.Has("builder_and_solver_settings"):
                settings.AddValue("builder_and_solver_settings", {})
            settings["builder_and_solver_settings"].AddValue("use_block_builder", use_block)
            logger.warning(
                '%s is deprecated; converted to builder_and_solver_settings.type = "%s"',
                settings.Where("block_builder"),
                "block" if use_block else "elimination",
            )
            settings.RemoveValue("block_builder")
        if settings.Has("builder_and_solver_settings"):
            builder = settings["builder_and_solver_settings"]
            if builder.IsSubParameter() and not builder.Has("type"):
                use_block = (
                    builder["use_block_builder"].GetBool()
                    if builder.Has("use_block_builder")
                    else True
                )
                lagrange = (
                    builder["use_lagrange_BS"].GetBool()
                    if builder.Has("use_lagrange_BS")
                    else False
                )
                kind = ("block_lagrange" if lagrange else "block") if use_block else "elimination"
                for key in ("use_block_builder", "use_lagrange_BS"):
                    builder.RemoveValue(key)
                builder.AddValue("type", kind)
        if settings.Has("line_search"):
            use_line_search = settings["line_search"].GetBool()
            if use_line_search:
                if not settings.Has("solving_strategy_settings"):
                    settings.AddValue("solving_strategy_settings", {"type": "line_search"})
                else:
                    settings["solving_strategy_settings"].AddValue("type", "line_search")
            logger.warning(
                "%s is deprecated; %s",
                settings.Where("line_search"),
                'converted to solving_strategy_settings.type = "line_search"'
                if use_line_search
                else "false is the default; removed",
            )
            settings.RemoveValue("line_search")

    def ValidateSettings(self) -> None:
        """Check values, enumerations, sub-blocks and referenced files (before anything runs)."""
        settings = self.settings
        if not settings["model_part_name"].GetString():
            raise error(
                settings, "model_part_name", "model_part_name is empty", 'a name like "Structure"'
            )
        domain_size = settings["domain_size"].GetInt()
        if domain_size not in (2, 3):
            raise error(settings, "domain_size", f"domain_size is {domain_size}", "2 or 3")
        # Numbers (echo_level, buffer_size, max_iteration, tolerances) were range-checked by
        # ValidateAndAssignDefaults (contact_app/setting_ranges.py).
        for key, feature in _FEATURE_FLAGS.items():
            if settings[key].GetBool():
                raise not_supported(settings, key, feature, f'set "{key}": false or remove it')
        choice(settings, "analysis_type", ("linear", "non_linear"))
        choice(settings, "on_non_converged_step", NON_CONVERGED_STEP_POLICIES)
        self._CheckCriterionName()
        self._ValidateStrategySettings()
        self._ValidateBuilderSettings()
        self._ValidateLinearSolverSettings()
        self._ValidateTimeStepping()
        self._ValidateModelImport()
        self._ValidateMaterialImport()
        self._ValidateAuxiliaryLists()

    def _CheckCriterionName(self) -> None:
        """Refuse unknown criterion names (the contact solvers also accept the contact ones)."""
        check_criterion_name(self.settings)

    def _ValidateStrategySettings(self) -> None:
        strategy = self.settings["solving_strategy_settings"]
        strategy.ValidateAndAssignDefaults({"type": "newton_raphson", "advanced_settings": {}})
        kind = choice(
            strategy, "type", ("newton_raphson", "line_search", "arc_length"), "solving strategy"
        )
        if kind == "arc_length":
            raise not_supported(
                strategy, "type", "the arc-length strategy", 'use "newton_raphson" or "line_search"'
            )
        advanced = strategy["advanced_settings"]
        if kind == "line_search":
            advanced.ValidateAndAssignDefaults(LINE_SEARCH_KEYS)
        elif advanced.size():
            key = advanced.keys()[0]
            raise error(
                advanced,
                key,
                f'unknown key "{key}": the Newton-Raphson strategy has no advanced settings',
                "an empty object",
                'remove it (line search settings need "type": "line_search")',
            )

    def _ValidateBuilderSettings(self) -> None:
        builder = self.settings["builder_and_solver_settings"]
        builder.ValidateAndAssignDefaults({"type": "block", "advanced_settings": {}})
        kind = choice(
            builder, "type", ("block", "block_lagrange", "elimination"), "builder and solver"
        )
        if kind == "block_lagrange":
            raise not_supported(
                builder, "type", "the block builder with Lagrange constraints", 'use "block"'
            )
        advanced = builder["advanced_settings"]
        if advanced.size():
            raise not_supported(
                advanced, advanced.keys()[0], "builder and solver advanced settings", "remove them"
            )

    def _ValidateLinearSolverSettings(self) -> None:
        linear = self.settings["linear_solver_settings"]
        linear.Clone().ValidateAndAssignDefaults(LINEAR_SOLVER_KEYS)
        if linear.Has("solver_type"):
            name = linear["solver_type"].GetString()
            try:
                ca.ResolveLinearSolverName(name)
            except ca.InputError as failure:
                first, _, rest = str(failure).partition("\n")
                raise ca.InputError(
                    f"{first}\n  where:    {linear.Where('solver_type')}\n{rest}"
                ) from None
        if linear.Has("tolerance"):
            positive(linear, "tolerance")
        strings = ("krylov_type", "preconditioner_type", "smoother_type", "coarsening_type")
        if is_iterative(linear) and any(linear.Has(key) for key in strings):
            given = {key: linear[key].GetString() for key in strings if linear.Has(key)}
            try:
                ca.CheckKrylovSettings(**given)
            except ca.InputError as failure:
                first, _, rest = str(failure).partition("\n")
                key = next((k for k in given if f".{k} " in first), "solver_type")
                where = linear.Where(key)
                raise ca.InputError(f"{first}\n  where:    {where}\n{rest}") from None
        static_condensation_mode(linear)
        if linear.Has("ordering"):
            solver_type = linear["solver_type"].GetString() if linear.Has("solver_type") else ""
            try:
                ca.CreateLinearSolver(solver_type, ordering=linear["ordering"].GetString())
            except ca.InputError as failure:
                first, _, rest = str(failure).partition("\n")
                raise ca.InputError(
                    f"{first}\n  where:    {linear.Where('ordering')}\n{rest}"
                ) from None

    def _ValidateTimeStepping(self) -> None:
        stepping = self.settings["time_stepping"]
        stepping.Clone().ValidateAndAssignDefaults(TIME_STEPPING_KEYS)
        given = [key for key in TIME_STEPPING_KEYS if stepping.Has(key)]
        if len(given) != 1:
            raise error(
                stepping,
                None,
                "time_stepping must give exactly one of time_step, time_step_table, "
                f"time_step_intervals (found {', '.join(given) or 'none'})",
                '{"time_step": 0.1}',
                "give one constant time_step, or a table [[time, dt], ...]",
            )
        if stepping.Has("time_step"):
            pass  # its range is checked with the defaults (contact_app/setting_ranges.py)
        elif stepping.Has("time_step_table"):
            rows = stepping["time_step_table"].GetMatrix()
            if not rows or any(len(row) != 2 for row in rows):
                raise error(
                    stepping,
                    "time_step_table",
                    "time_step_table is not rows of [time, dt]",
                    "[[0.0, 0.1], [1.0, 0.2]]",
                )
            if any(row[1] <= 0.0 for row in rows):
                raise error(
                    stepping,
                    "time_step_table",
                    "time_step_table has a dt ≤ 0",
                    "positive time steps",
                )
            if any(b[0] <= a[0] for a, b in zip(rows, rows[1:], strict=False)):
                raise error(
                    stepping,
                    "time_step_table",
                    "the times of time_step_table do not increase",
                    "increasing times",
                )
        else:
            intervals = stepping["time_step_intervals"]
            if not intervals.size():
                raise error(
                    stepping,
                    "time_step_intervals",
                    "time_step_intervals is empty",
                    '{"0": {"interval": [0.0, "End"], "time_step": 0.1}}',
                )
            for interval in intervals.values():
                interval.ValidateAndAssignDefaults({"interval": [0.0, "End"], "time_step": 1.0})
                self._IntervalBounds(interval)
            logger.warning(
                "%s is deprecated; use time_step or time_step_table",
                stepping.Where("time_step_intervals"),
            )

    @staticmethod
    def _IntervalBounds(interval: Parameters) -> tuple[float, float]:
        bounds = interval["interval"]
        values = bounds.GetValue()
        if not (isinstance(values, list) and len(values) == 2):
            raise error(
                interval, "interval", "interval is not [begin, end]", '[0.0, 1.0] or [0.0, "End"]'
            )
        begin = bounds[0].GetDouble()
        end = 1.0e30 if values[1] == "End" else bounds[1].GetDouble()
        return begin, end

    def _ValidateModelImport(self) -> None:
        settings = self.settings["model_import_settings"]
        settings.ValidateAndAssignDefaults(MODEL_IMPORT_KEYS)
        kind = choice(
            settings,
            "input_type",
            ("mdpa", "meshio", "use_input_model_part", "rest"),
            "input_type",
        )
        filename = settings["input_filename"].GetString()
        if kind == "rest":
            self._ValidateRestartImport(settings, filename)
            return
        if kind == "mdpa" and filename.lower().endswith(MESHIO_EXTENSIONS):
            kind = "meshio"
        if kind == "meshio":
            if not filename:
                raise error(
                    settings,
                    "input_filename",
                    'missing required key "input_filename"',
                    "the mesh file name with its extension, e.g. hertz_2d.msh",
                )
            self._meshio_path = self.paths.input_path(
                filename, settings.Where("input_filename"), "mesh file"
            )
            if not settings["mesh_mapping"].IsSubParameter():
                raise error(settings, "mesh_mapping", "mesh_mapping is not an object", "{...}")
            self._meshio_mapping = settings["mesh_mapping"].GetValue()
            self._meshio_where = settings.Where("mesh_mapping")
            return
        if settings["mesh_mapping"].size():
            raise error(
                settings,
                "mesh_mapping",
                'mesh_mapping is only read with "input_type": "meshio"',
                "no mesh_mapping for an .mdpa file",
                "remove it, or read the mesh through meshio",
            )
        if kind == "mdpa":
            if not filename:
                raise error(
                    settings,
                    "input_filename",
                    'missing required key "input_filename"',
                    "the mdpa file name without the .mdpa extension",
                    '"input_filename": "my_case" for my_case.mdpa',
                )
            if filename.endswith(".mdpa"):
                logger.warning(
                    "%s includes the .mdpa extension, which Kratos would add again; used as given",
                    settings.Where("input_filename"),
                )
                filename = filename[: -len(".mdpa")]
            self._mdpa_path = self.paths.input_path(
                filename + ".mdpa", settings.Where("input_filename"), "mdpa file"
            )

    def _ValidateRestartImport(self, settings: Parameters, filename: str) -> None:
        """input_type "rest": the restart file must exist; its header and hash are checked here."""
        from ...io.restart_utility import SERIALIZER_TRACES, Inspect, RestartFile

        choice(settings, "serializer_trace", SERIALIZER_TRACES, "serializer_trace")
        label = settings["restart_load_file_label"].GetString()
        for key, value, expected in (
            ("input_filename", filename, "the base name of the restart files, e.g. hertz_2d"),
            ("restart_load_file_label", label, 'the TIME or STEP label of the file, e.g. "0.5"'),
        ):
            if not value:
                raise error(
                    settings, key, f'missing required key "{key}" for input_type "rest"', expected
                )
        name = RestartFile(filename, label, settings["load_restart_files_from_folder"].GetBool())
        self._restart_path = self.paths.input_path(
            str(name), settings.Where("restart_load_file_label"), "restart file"
        )
        summary = Inspect(self._restart_path)
        expected_name = self.settings["model_part_name"].GetString()
        if summary["model_part_name"] != expected_name:
            raise error(
                settings,
                "restart_load_file_label",
                f'the restart file "{self._restart_path}" holds the model part '
                f'"{summary["model_part_name"]}", not "{expected_name}"',
                "a restart file of solver_settings.model_part_name",
                "pick the restart file of this model part",
            )

    def _ValidateMaterialImport(self) -> None:
        settings = self.settings["material_import_settings"]
        settings.ValidateAndAssignDefaults({"materials_filename": "", "custom_reader": ""})
        if settings["custom_reader"].GetString():
            raise not_supported(
                settings, "custom_reader", "a custom materials reader", "use materials_filename"
            )
        filename = settings["materials_filename"].GetString()
        if filename:
            path = self.paths.input_path(
                filename, settings.Where("materials_filename"), "materials file"
            )
            self._materials = MaterialsReader(path)

    def _ValidateAuxiliaryLists(self) -> None:
        settings = self.settings
        for key in ("auxiliary_variables_list", "auxiliary_dofs_list", "auxiliary_reaction_list"):
            for index, name in enumerate(settings[key].GetStringArray()):
                if name not in ca.registered_variables():
                    raise error(
                        settings[key],
                        f"[{index}]",
                        f'unknown variable "{name}"',
                        "a registered variable",
                        suggest(name, ca.registered_variables()),
                    )
        dofs = settings["auxiliary_dofs_list"].GetStringArray()
        reactions = settings["auxiliary_reaction_list"].GetStringArray()
        if len(dofs) != len(reactions):
            raise error(
                settings,
                "auxiliary_reaction_list",
                f"{len(dofs)} auxiliary DoFs but {len(reactions)} reactions",
                "one reaction per auxiliary DoF",
            )

    def InputFiles(self) -> list[tuple[str, str]]:
        """(path, where it is named) of the files the solver reads: mesh and materials."""
        import_settings = self.settings["model_import_settings"]
        files = [
            (path, import_settings.Where("input_filename"))
            for path in (self._mdpa_path, self._meshio_path, self._restart_path)
            if path
        ]
        if self._materials is not None:
            where = self.settings["material_import_settings"].Where("materials_filename")
            files.append((self._materials.filename, where))
        return files

    # -- model part --

    def _CreateMainModelPart(self) -> None:
        name = self.settings["model_part_name"].GetString()
        if self.model.HasModelPart(name):
            self.main_model_part = self.model.GetModelPart(name)
        else:
            self.main_model_part = self.model.CreateModelPart(name, self.GetMinimumBufferSize())
            self.main_model_part.ProcessInfo[ca.DOMAIN_SIZE] = self.settings["domain_size"].GetInt()

    def GetMinimumBufferSize(self) -> int:
        """Smallest history depth the scheme needs."""
        return 2

    def GetComputingModelPart(self) -> ca.ModelPart:
        """The part the strategy assembles (computing_sub_model_part_name, else the main part)."""
        name = self.settings["computing_sub_model_part_name"].GetString()
        if not name:
            return self.main_model_part
        if not self.main_model_part.HasSubModelPart(name):
            raise error(
                self.settings,
                "computing_sub_model_part_name",
                f'no sub model part "{name}" in {self.main_model_part.Name}',
                "a direct sub model part of the main model part",
                suggest(name, self.main_model_part.GetSubModelPartNames()),
            )
        return self.main_model_part.GetSubModelPart(name)

    def _HistoricalVariables(self) -> list[Any]:
        return [
            ca.DISPLACEMENT,
            ca.REACTION,
            ca.POSITIVE_FACE_PRESSURE,
            ca.NEGATIVE_FACE_PRESSURE,
            ca.POINT_LOAD,
            ca.LINE_LOAD,
            ca.SURFACE_LOAD,
            ca.VOLUME_ACCELERATION,
        ]

    def AddVariables(self) -> None:
        """Declare the historical variables (before the mesh is read)."""
        part = self.main_model_part
        names = (
            self.settings["auxiliary_variables_list"].GetStringArray()
            + self.settings["auxiliary_dofs_list"].GetStringArray()
            + self.settings["auxiliary_reaction_list"].GetStringArray()
        )
        for variable in self._HistoricalVariables() + [ca.get_variable(n) for n in names]:
            part.AddNodalSolutionStepVariable(variable)

    def _DofsWithReactions(self) -> list[tuple[Any, Any]]:
        pairs = [
            (ca.DISPLACEMENT_X, ca.REACTION_X),
            (ca.DISPLACEMENT_Y, ca.REACTION_Y),
            (ca.DISPLACEMENT_Z, ca.REACTION_Z),
        ]
        dofs = self.settings["auxiliary_dofs_list"].GetStringArray()
        reactions = self.settings["auxiliary_reaction_list"].GetStringArray()
        for dof, reaction in zip(dofs, reactions, strict=True):
            pairs.append((ca.get_variable(dof), ca.get_variable(reaction)))
        return pairs

    def _DofsWithoutReactions(self) -> list[Any]:
        return []

    def AddDofs(self) -> None:
        """Add the DoFs (DISPLACEMENT_X/Y/Z ↔ REACTION_X/Y/Z, Z also in 2D) to every node."""
        pairs = self._DofsWithReactions()
        singles = self._DofsWithoutReactions()
        for node in self.main_model_part.Nodes:
            for variable, reaction in pairs:
                node.AddDof(variable, reaction)
            for variable in singles:
                node.AddDof(variable)

    def ImportModelPart(self) -> None:
        """Read the mdpa file (``input_type`` "mdpa"); nothing for "use_input_model_part".

        Raises:
            InputError: the mesh file defines no node (empty or unreadable), named as such rather
                than later as a model part missing from the materials file.
        """
        if self._restart_path:
            from ...io.restart_utility import Load

            Load(self.main_model_part, self._restart_path)
            self.main_model_part.ProcessInfo[ca.IS_RESTARTED] = True
            return
        if self._mdpa_path:
            ca.ModelPartIO(self._mdpa_path).ReadModelPart(self.main_model_part)
        elif self._meshio_path:
            from ...io import ImportMeshioModelPart

            ImportMeshioModelPart(
                self.main_model_part, self._meshio_path, self._meshio_mapping, self._meshio_where
            )
        mesh = self._mdpa_path or self._meshio_path
        if mesh and self.main_model_part.NumberOfNodes() == 0:
            raise error(
                self.settings["model_import_settings"],
                "input_filename",
                f'the mesh file "{mesh}" defines no nodes: it is empty or unreadable',
                "a mesh with a Begin Nodes block (or the cells and points of a meshio file)",
                "check that the file is the intended mesh and was written completely",
            )

    def PrepareModelPart(self) -> None:
        """Assign the materials, set and fill the history buffer, check the computing part.

        A restarted model part keeps the properties, buffer and ProcessInfo of its restart file.
        """
        if self.IsRestarted():
            self.GetComputingModelPart()
            return
        if self._materials is not None:
            self._materials.Apply(self.model)
        elif self.main_model_part.NumberOfElements():
            logger.info("no materials_filename: the properties of the mdpa are used as they are")
        mesh = self._mdpa_path or self._meshio_path
        if mesh:
            CheckMeshProperties(self.main_model_part, Path(mesh).name)
        self._SetAndFillBuffer()
        self.GetComputingModelPart()

    def IsRestarted(self) -> bool:
        """True once the model part was loaded from a restart file (ProcessInfo IS_RESTARTED)."""
        return bool(self.main_model_part.ProcessInfo[ca.IS_RESTARTED])

    def _SetAndFillBuffer(self) -> None:
        part = self.main_model_part
        size = max(self.settings["buffer_size"].GetInt(), self.GetMinimumBufferSize())
        part.SetBufferSize(size)
        info = part.ProcessInfo
        time, step, delta = info[ca.TIME], info[ca.STEP], info[ca.DELTA_TIME]
        info[ca.TIME] = time - delta * size
        for _ in range(size):
            part.CloneTimeStep(info[ca.TIME] + delta)
        info[ca.TIME], info[ca.STEP], info[ca.DELTA_TIME] = time, step, delta

    # -- strategy --

    def _CreateScheme(self) -> Any:
        raise NotImplementedError("derived solvers create the scheme")

    def _CreateLinearSolver(self) -> Any:
        linear = self.settings["linear_solver_settings"]
        solver_type = linear["solver_type"].GetString() if linear.Has("solver_type") else ""
        tolerance = linear["tolerance"].GetDouble() if linear.Has("tolerance") else 1.0e-6
        max_iteration = linear["max_iteration"].GetInt() if linear.Has("max_iteration") else 1000
        ordering = linear["ordering"].GetString() if linear.Has("ordering") else "auto"
        krylov: dict[str, Any] = {}
        for key in KRYLOV_KEYS:
            if linear.Has(key):
                value = linear[key]
                krylov[key] = (
                    value.GetString()
                    if value.IsString()
                    else value.GetBool()
                    if value.IsBool()
                    else value.GetInt()
                )
        return ca.CreateLinearSolver(solver_type, tolerance, max_iteration, ordering, **krylov)

    def _CreateBuilderAndSolver(self) -> Any:
        kind = self.settings["builder_and_solver_settings"]["type"].GetString()
        if kind == "elimination":
            return ca.ResidualBasedEliminationBuilderAndSolver(self._GetLinearSolver())
        return ca.ResidualBasedBlockBuilderAndSolver(self._GetLinearSolver())

    def _CreateConvergenceCriterion(self) -> ConvergenceCriterion:
        return CreateConvergenceCriterion(self.settings)

    def _CreateSolutionStrategy(self) -> Any:
        settings = self.settings
        common = {
            "compute_reactions": settings["compute_reactions"].GetBool(),
            "reform_step_dofs": settings["reform_dofs_at_each_step"].GetBool(),
            "move_mesh_flag": settings["move_mesh_flag"].GetBool(),
        }
        part = self.GetComputingModelPart()
        scheme, builder = self._GetScheme(), self._GetBuilderAndSolver()
        if settings["analysis_type"].GetString() == "linear":
            return ca.ResidualBasedLinearStrategy(part, scheme, builder, **common)
        criterion = self._GetConvergenceCriterion().criterion
        max_iteration = settings["max_iteration"].GetInt()
        strategy = settings["solving_strategy_settings"]
        if strategy["type"].GetString() == "line_search":
            advanced = {
                key: value.GetValue() for key, value in strategy["advanced_settings"].items()
            }
            return ca.LineSearchStrategy(
                part, scheme, criterion, builder, max_iteration=max_iteration, **common, **advanced
            )
        return ca.ResidualBasedNewtonRaphsonStrategy(
            part, scheme, criterion, builder, max_iteration=max_iteration, **common
        )

    def _GetScheme(self) -> Any:
        if self._scheme is None:
            self._scheme = self._CreateScheme()
        return self._scheme

    def _GetLinearSolver(self) -> Any:
        if self._linear_solver is None:
            self._linear_solver = self._CreateLinearSolver()
        return self._linear_solver

    def _GetBuilderAndSolver(self) -> Any:
        if self._builder_and_solver is None:
            self._builder_and_solver = self._CreateBuilderAndSolver()
        return self._builder_and_solver

    def _GetConvergenceCriterion(self) -> ConvergenceCriterion:
        if self._criterion is None:
            self._criterion = self._CreateConvergenceCriterion()
        return self._criterion

    def _GetSolutionStrategy(self) -> Any:
        if self._strategy is None:
            self._strategy = self._CreateSolutionStrategy()
        return self._strategy

    def GetConvergenceCriterion(self) -> ConvergenceCriterion | None:
        """The criterion and its parts (None for a linear analysis)."""
        if self.settings["analysis_type"].GetString() == "linear":
            return None
        return self._GetConvergenceCriterion()

    def GetBuilderAndSolver(self) -> Any:
        """The builder and solver (for timings)."""
        return self._GetBuilderAndSolver()

    def GetLinearSolver(self) -> Any:
        """The linear solver (for its statistics: name, ordering, fill, factor memory)."""
        return self._GetLinearSolver()

    def GetSolutionStrategy(self) -> Any:
        """The strategy (created on first use)."""
        return self._GetSolutionStrategy()

    # -- life cycle --

    def Initialize(self) -> None:
        """Create the strategy and initialize it (elements, conditions, criterion)."""
        strategy = self._GetSolutionStrategy()
        if self.settings["clear_storage"].GetBool():
            strategy.Clear()
        strategy.SetEchoLevel(self.settings["echo_level"].GetInt())
        strategy.Initialize()

    def Check(self) -> None:
        """Check the strategy (elements, conditions, scheme)."""
        self._GetSolutionStrategy().Check()

    def Clear(self) -> None:
        """Release the system storage."""
        self._GetSolutionStrategy().Clear()

    def SetEchoLevel(self, level: int) -> None:
        """Set the strategy echo level."""
        self.settings["echo_level"].SetInt(level)
        self._GetSolutionStrategy().SetEchoLevel(level)

    def ComputeDeltaTime(self) -> float:
        """Δt of the next step: time_step, time_step_table at TIME, or time_step_intervals."""
        return self.DeltaTimeAt(self.main_model_part.ProcessInfo[ca.TIME])

    def CountSteps(self, start_time: float, end_time: float) -> int:
        """Number of steps from start_time to end_time (InputError for a meaningless loop)."""
        stepping = self.settings["time_stepping"]
        return count_steps(
            start_time,
            end_time,
            self.DeltaTimeAt,
            stepping.Where(),
            constant=stepping.Has("time_step"),
        )

    def DeltaTimeAt(self, time: float) -> float:
        """Δt of a step that starts at ``time`` (time_step, time_step_table or the intervals)."""
        stepping = self.settings["time_stepping"]
        if stepping.Has("time_step"):
            return stepping["time_step"].GetDouble()
        if stepping.Has("time_step_table"):
            if self._time_step_table is None:
                self._time_step_table = ca.Table()
                for t, dt in stepping["time_step_table"].GetMatrix():
                    self._time_step_table.AddRow(t, dt)
            delta = self._time_step_table.GetValue(time)
            if delta <= 0.0:
                raise error(
                    stepping,
                    "time_step_table",
                    f"time_step_table gives Δt = {delta} at TIME = {time} (extrapolated)",
                    "a positive time step at every time of the analysis",
                    "add a row that covers this time",
                )
            return delta
        for interval in stepping["time_step_intervals"].values():
            begin, end = self._IntervalBounds(interval)
            eps = max(1.0e-14 * abs(begin), 1.0e-30)
            if begin - eps < time < end + eps:
                return interval["time_step"].GetDouble()
        raise error(
            stepping,
            "time_step_intervals",
            f"no interval of time_step_intervals contains TIME = {time}",
            "intervals that cover [start_time, end_time]",
        )

    def AdvanceInTime(self, current_time: float) -> float:
        """Clone the time step to ``current_time + Δt`` (STEP += 1, DELTA_TIME set); return it."""
        new_time = current_time + self.ComputeDeltaTime()
        self.main_model_part.CloneTimeStep(new_time)
        return new_time

    def InitializeSolutionStep(self) -> None:
        """Re-initialize after clearing (``clear_storage``), then initialize the step."""
        if self.settings["clear_storage"].GetBool():
            self.Clear()
            self.Initialize()
        self._GetSolutionStrategy().InitializeSolutionStep()

    def Predict(self) -> None:
        """Scheme prediction."""
        self._GetSolutionStrategy().Predict()

    def SolveSolutionStep(self) -> bool:
        """Solve the step; warn with the last norms when Newton did not converge.

        What happens next (step cutting, stop, or going on) is the analysis stage's decision and
        its message.
        """
        strategy = self._GetSolutionStrategy()
        self.last_failure = None
        try:
            converged = bool(strategy.SolveSolutionStep())
        except ca.InvertedElementError as failure:
            # The iterate, not the model, is unusable: the step did not converge (and may be cut).
            self.last_failure = failure
            info = self.main_model_part.ProcessInfo
            logger.warning(
                "step %d (TIME = %.6g) did not converge: Newton iteration %d failed: %s",
                info[ca.STEP],
                info[ca.TIME],
                strategy.GetIterationNumber(),
                str(failure).partition("\n")[0],
            )
            return False
        if not converged:
            info = self.main_model_part.ProcessInfo
            logger.warning(
                "step %d (TIME = %.6g) did not converge in %d iterations; last norms: %s",
                info[ca.STEP],
                info[ca.TIME],
                strategy.GetIterationNumber(),
                self.LastNorms() or "n/a",
            )
        return converged

    def NonConvergedStepPolicy(self) -> str:
        """``on_non_converged_step``: "stop" (default) or "continue"."""
        return self.settings["on_non_converged_step"].GetString()

    def InvertedElementCuttingSettings(self) -> tuple[float, int] | None:
        """(split_factor, max_number_splits) for a step that failed on an inverted element.

        None when ``cut_step_on_inverted_element`` is false. The contact solvers use their
        ``contact_settings`` values.
        """
        if not self.settings["cut_step_on_inverted_element"].GetBool():
            return None
        return INVERTED_ELEMENT_CUTTING

    def LastNorms(self) -> str:
        """The criterion norms of the last iteration, one line."""
        strategy = self._GetSolutionStrategy()
        if hasattr(strategy, "IterationHistory"):
            history = strategy.IterationHistory()
            if history:
                return str(history[-1])
        return ""

    def FinalizeSolutionStep(self) -> None:
        """Finalize the step (elements, conditions, criterion)."""
        self._GetSolutionStrategy().FinalizeSolutionStep()

    def Solve(self) -> bool:
        """InitializeSolutionStep, Predict, SolveSolutionStep, FinalizeSolutionStep."""
        self.InitializeSolutionStep()
        self.Predict()
        converged = self.SolveSolutionStep()
        self.FinalizeSolutionStep()
        return converged

    def Finalize(self) -> None:
        """Release the strategy storage."""
        if self._strategy is not None:
            self._strategy.Clear()
