"""Base structural solver (Kratos ``structural_mechanics_solver.MechanicalSolver``).

It owns the main model part, validates ``solver_settings`` against :meth:`GetDefaultParameters`
(after converting the deprecated keys old files use, with a warning each; the key tables and the
checks are in :mod:`.settings_validation`), imports the mdpa and the materials, adds variables and
DoFs, and builds linear solver, builder and solver, convergence criterion and strategy on demand.
Derived solvers provide the scheme (:meth:`_CreateScheme`) and may extend the defaults, variables
and DoFs; the contact solvers derive from this class the same way.
"""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Any

import contact_app as ca

from ...parameters import Parameters, suggest
from ..materials import CheckMeshProperties, MaterialsReader
from ..paths import PathResolver
from ..time_loop import count_steps
from ..validation import error
from .convergence_criteria_factory import (
    ConvergenceCriterion,
    CreateConvergenceCriterion,
    check_criterion_name,
)
from .settings_validation import (
    KRYLOV_KEYS,
    ModelInput,
    convert_deprecated_settings,
    interval_bounds,
    validate_auxiliary_lists,
    validate_builder_settings,
    validate_linear_solver_settings,
    validate_material_import,
    validate_model_import,
    validate_strategy_settings,
    validate_time_stepping,
    validate_top_level_keys,
)

logger = logging.getLogger("contact_app.analysis")

#: Why ``on_non_converged_step`` "stop" is the default, for the log, the summary and the error
#: message.
STOP_DEFAULT_REASON = (
    "a step that did not converge is not an equilibrium, and every later step would start from it "
    "with results that look valid (Kratos goes on by default)"
)
#: Step cutting of an inverted element when the solver has no settings of its own (no
#: contact_settings): Kratos' adaptative_strategy defaults, split_factor 10, max_number_splits 3.
INVERTED_ELEMENT_CUTTING = (10.0, 3)


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
        #: The mesh or restart file of model_import_settings, resolved by ValidateSettings.
        self._model_input = ModelInput()
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
        convert_deprecated_settings(self.settings)

    def ValidateSettings(self) -> None:
        """Check values, enumerations, sub-blocks and referenced files (before anything runs).

        The checks are :mod:`.settings_validation`'s; the files named are resolved here (the mesh
        or restart file, the materials), to be read by :meth:`ImportModelPart` and
        :meth:`PrepareModelPart`.
        """
        settings = self.settings
        validate_top_level_keys(settings)
        self._CheckCriterionName()
        validate_strategy_settings(settings["solving_strategy_settings"])
        validate_builder_settings(settings["builder_and_solver_settings"])
        validate_linear_solver_settings(settings["linear_solver_settings"])
        validate_time_stepping(settings["time_stepping"])
        self._model_input = validate_model_import(
            settings["model_import_settings"], settings["model_part_name"].GetString(), self.paths
        )
        self._materials = validate_material_import(settings["material_import_settings"], self.paths)
        validate_auxiliary_lists(settings)

    def _CheckCriterionName(self) -> None:
        """Refuse unknown criterion names (the contact solvers also accept the contact ones)."""
        check_criterion_name(self.settings)

    def InputFiles(self) -> list[tuple[str, str]]:
        """(path, where it is named) of the files the solver reads: mesh and materials."""
        import_settings = self.settings["model_import_settings"]
        files = [
            (path, import_settings.Where("input_filename"))
            for path in (
                self._model_input.mdpa_path,
                self._model_input.meshio_path,
                self._model_input.restart_path,
            )
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
        source = self._model_input
        if source.restart_path:
            from ...io.restart_utility import Load

            Load(self.main_model_part, source.restart_path)
            self.main_model_part.ProcessInfo[ca.IS_RESTARTED] = True
            return
        if source.mdpa_path:
            ca.ModelPartIO(source.mdpa_path).ReadModelPart(self.main_model_part)
        elif source.meshio_path:
            from ...io import ImportMeshioModelPart

            ImportMeshioModelPart(
                self.main_model_part, source.meshio_path, source.meshio_mapping, source.meshio_where
            )
        mesh = source.mdpa_path or source.meshio_path
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
        mesh = self._model_input.mdpa_path or self._model_input.meshio_path
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
            begin, end = interval_bounds(interval)
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
