"""What the contact solvers add to the structural ones (Kratos ``auxiliary_methods_solvers``).

``contact_settings`` defaults and checks, the historical variables and DoFs of each
``mortar_type`` (``docs/input_layer.md`` §2) and the mixin the static and implicit
dynamic contact solvers share.
"""

from __future__ import annotations

import logging
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np
from numpy.typing import NDArray

import contact_app as ca
from contact_app import _core
from contact_app._core import MortarType
from contact_app.analysis.paths import PathResolver
from contact_app.analysis.solvers.convergence_criteria_factory import (
    CONTACT_CRITERIA,
    STRUCTURAL_CRITERIA,
    ConvergenceCriterion,
    check_criterion_name,
)
from contact_app.analysis.solvers.mechanical_solver import bulk_not_linear
from contact_app.analysis.solvers.settings_validation import (
    is_iterative,
    static_condensation_mode,
)
from contact_app.analysis.validation import error, not_supported
from contact_app.legacy_keys import convert_legacy_keys
from contact_app.parameters import Parameters, suggest

from ._pairs import MORTAR_TYPES
from .contact_convergence_criteria_factory import CreateContactConvergenceCriterion

if TYPE_CHECKING:
    from contact_app.analysis.solvers.mechanical_solver import MechanicalSolver

    # For the type checker the contact mixins are structural solvers (their super() calls reach
    # one); at run time their base is object, and the concrete solvers put them first in the MRO.
    SolverMixinBase = MechanicalSolver
else:
    SolverMixinBase = object

logger = logging.getLogger("contact_app.contact")

MIXED_ULM_DEFAULTS = {
    "solver_type": "mixed_ulm_linear_solver",
    "tolerance": 1.0e-6,
    "max_iteration_number": 200,
    "echo_level": 0,
}

CONTACT_SETTINGS_DEFAULTS: dict[str, Any] = {
    "mortar_type": "",
    "condn_convergence_criterion": False,
    "fancy_convergence_criterion": True,
    "print_convergence_criterion": False,
    "ensure_contact": False,
    "frictional_decomposed": True,
    "compute_dynamic_factor": False,
    "gidio_debug": False,
    "adaptative_strategy": False,
    "split_factor": 10.0,
    "max_number_splits": 3,
    "inner_loop_iterations": 5,
    "inner_loop_adaptive": False,
    "rotation_relative_tolerance": 1.0e-4,
    "rotation_absolute_tolerance": 1.0e-9,
    "rotation_residual_relative_tolerance": 1.0e-4,
    "rotation_residual_absolute_tolerance": 1.0e-9,
    "contact_displacement_relative_tolerance": 1.0e-4,
    "contact_displacement_absolute_tolerance": 1.0e-9,
    "contact_residual_relative_tolerance": 1.0e-4,
    "contact_residual_absolute_tolerance": 1.0e-9,
    "frictional_stick_contact_displacement_relative_tolerance": 1.0e-4,
    "frictional_stick_contact_displacement_absolute_tolerance": 1.0e-9,
    "frictional_stick_contact_residual_relative_tolerance": 1.0e-4,
    "frictional_stick_contact_residual_absolute_tolerance": 1.0e-9,
    "frictional_slip_contact_displacement_relative_tolerance": 1.0e-4,
    "frictional_slip_contact_displacement_absolute_tolerance": 1.0e-9,
    "frictional_slip_contact_residual_relative_tolerance": 1.0e-4,
    "frictional_slip_contact_residual_absolute_tolerance": 1.0e-9,
    "ratio_normal_tangent_threshold": 1.0e-4,
    "silent_strategy": True,
    "simplified_semi_smooth_newton": False,
    "rescale_linear_solver": False,
    "use_mixed_ulm_solver": True,
    "mixed_ulm_solver_parameters": MIXED_ULM_DEFAULTS,
}


#: ``solver_settings`` the contact solvers set to true whatever the file says. The contact search
#: creates and removes pairs between steps, and with them the multiplier DoFs of the slave nodes, so
#: the builder must rebuild the DoF set every step (``reform_dofs_at_each_step``) and the strategy
#: must drop the system it stored for the previous DoF set (``clear_storage``).
FORCED_SOLVER_SETTINGS = ("reform_dofs_at_each_step", "clear_storage")


class ForcedSettings:
    """``solver_settings`` booleans a contact solver sets to true whatever the file says.

    The file's values are read when the solver is created, before the defaults fill in the missing
    keys: a key left out, or set true, is forced without a word; the keys set false get one warning
    naming them and why.

    Args:
        custom_settings: the ``solver_settings`` as the file gave them.
        keys: the keys forced to true.
        reason: why, completing "false overridden with true, as ...".

    """

    def __init__(self, custom_settings: Parameters, keys: Sequence[str], reason: str) -> None:
        self.keys = tuple(keys)
        self.reason = reason
        self.false_keys = [
            key
            for key in self.keys
            if custom_settings.Has(key)
            and custom_settings[key].IsBool()
            and not custom_settings[key].GetBool()
        ]

    def Apply(self, settings: Parameters) -> None:
        """Warn once about the keys the file set false, then set every key to true."""
        if self.false_keys:
            logger.warning(
                "%s › %s: false overridden with true, as %s",
                settings.Where(),
                " and ".join(self.false_keys),
                self.reason,
            )
        for key in self.keys:
            settings[key].SetBool(True)


def check_mortar_type(contact: Parameters) -> MortarType:
    """The ``mortar_type`` decoded from the condition table.

    Raises:
        InputError: an unknown or empty value (the accepted ones come from the table).
    """
    mortar_type = contact["mortar_type"].GetString()
    if mortar_type not in MORTAR_TYPES:
        raise error(
            contact,
            "mortar_type",
            f'unknown mortar_type "{mortar_type}"' if mortar_type else "mortar_type is empty",
            "one of " + ", ".join(f'"{t}"' for t in MORTAR_TYPES),
            suggest(mortar_type, list(MORTAR_TYPES)) or "name the contact formulation",
        )
    return MORTAR_TYPES[mortar_type]


def contact_status(
    main: ca.ModelPart,
    frictional: bool,
    area: Callable[[ca.ModelPart, NDArray[np.int64]], NDArray[np.float64]],
) -> tuple[int, int, int, float]:
    """(active slave nodes, slipping ones, live pairs, max penetration) of the "Contact" part.

    Read with the bulk accessors of ``_core`` (one call per flag or variable): a Python loop over
    the contact nodes cost ~1 ms per step, 6 % of a small 2D model's run.

    Args:
        main: the main model part (with "Contact" and "ComputingContact" children).
        frictional: count the SLIP nodes (frictionless runs leave SLIP set without meaning).
        area: the nodal areas A of the given node ids of the "Contact" part, each node's
            WEIGHTED_GAP is divided by (penetration = -g / A).
    """
    if not main.HasSubModelPart("Contact"):
        return (0, 0, 0, 0.0)
    part = main.GetSubModelPart("Contact")
    ids = _core.BulkNodeIds(part)
    in_contact = (_core.BulkNodalFlags(part, ids, ca.SLAVE) > 0.0) & (
        _core.BulkNodalFlags(part, ids, ca.ACTIVE) > 0.0
    )
    active_ids = ids[in_contact]
    slip = 0
    if frictional:
        slip = int(np.count_nonzero(_core.BulkNodalFlags(part, active_ids, ca.SLIP)))
    penetration = 0.0
    if main.HasNodalSolutionStepVariable(ca.WEIGHTED_GAP) and active_ids.size > 0:
        gaps = _core.BulkNodalValues(part, active_ids, ca.WEIGHTED_GAP, True)[0][:, 0]
        areas = area(part, active_ids)
        covered = areas > 0.0
        if np.any(covered):
            penetration = max(0.0, float(np.max(-gaps[covered] / areas[covered])))
    pairs = 0
    if main.HasSubModelPart("ComputingContact"):
        computing = main.GetSubModelPart("ComputingContact")
        live = (_core.BulkEntityFlags(computing, False, ca.ACTIVE) > 0.0) & ~(
            _core.BulkEntityFlags(computing, False, ca.ISOLATED) > 0.0
        )
        pairs = int(np.count_nonzero(live))
    return (int(active_ids.size), slip, pairs, penetration)


class ForcingSolverMixin(SolverMixinBase):
    """A structural solver with one more settings block that forces some ``solver_settings``.

    What the contact and the MPC contact mixins share; each names its block and forced keys.
    """

    #: The ``solver_settings`` key of the added block, and the block's defaults.
    SETTINGS_BLOCK: ClassVar[str]
    SETTINGS_BLOCK_DEFAULTS: ClassVar[dict[str, Any]]
    #: The keys :class:`ForcedSettings` sets to true, and why (its ``reason``).
    FORCED_KEYS: ClassVar[Sequence[str]]
    FORCED_REASON: ClassVar[str]

    def __init__(
        self, model: ca.Model, custom_settings: Parameters, paths: PathResolver | None = None
    ) -> None:
        self._forced = ForcedSettings(custom_settings, self.FORCED_KEYS, self.FORCED_REASON)
        super().__init__(model, custom_settings, paths)

    @classmethod
    def GetDefaultParameters(cls) -> dict[str, Any]:
        """The structural defaults plus the ``SETTINGS_BLOCK`` block."""
        defaults = super().GetDefaultParameters()
        defaults[cls.SETTINGS_BLOCK] = cls.SETTINGS_BLOCK_DEFAULTS
        return defaults


class ContactSolverMixin(ForcingSolverMixin):
    """Contact additions to a structural solver (used before the structural base in the MRO)."""

    SETTINGS_BLOCK = "contact_settings"
    SETTINGS_BLOCK_DEFAULTS = CONTACT_SETTINGS_DEFAULTS
    FORCED_KEYS = FORCED_SOLVER_SETTINGS
    FORCED_REASON = (
        "the contact solvers require: the contact pairs, and with them the Lagrange multiplier "
        "DoFs, change between steps, so the DoF set is rebuilt and the stored system cleared "
        "at every step"
    )

    def ValidateSettings(self) -> None:
        """Structural checks, then ``contact_settings`` (unknown keys are errors)."""
        contact = self.settings["contact_settings"]
        convert_legacy_keys(contact, "contact_settings")  # frictional_contact_*_tolerance
        contact.RecursivelyValidateAndAssignDefaults(CONTACT_SETTINGS_DEFAULTS)
        self.mortar = check_mortar_type(contact)
        # split_factor, max_number_splits, ... were range-checked by the defaults validation.
        # Pairs appear and disappear between steps: the DoF set is rebuilt every step.
        self._forced.Apply(self.settings)
        super().ValidateSettings()

    def StepCuttingSettings(self) -> tuple[float, int] | None:
        """(split_factor, max_number_splits) with ``adaptative_strategy``, else None.

        The analysis then redoes a step that did not converge in sub-steps.
        """
        contact = self.settings["contact_settings"]
        if not contact["adaptative_strategy"].GetBool():
            return None
        return contact["split_factor"].GetDouble(), contact["max_number_splits"].GetInt()

    def InvertedElementCuttingSettings(self) -> tuple[float, int] | None:
        """(split_factor, max_number_splits) of contact_settings, for an inverted element.

        None when ``solver_settings.cut_step_on_inverted_element`` is false.
        """
        if not self.settings["cut_step_on_inverted_element"].GetBool():
            return None
        contact = self.settings["contact_settings"]
        return contact["split_factor"].GetDouble(), contact["max_number_splits"].GetInt()

    def _CheckCriterionName(self) -> None:
        """Structural and contact criterion names are both valid here."""
        check_criterion_name(self.settings, STRUCTURAL_CRITERIA + CONTACT_CRITERIA)

    def AddVariables(self) -> None:
        """Structural variables plus those of the mortar_type."""
        super().AddVariables()
        for variable in self.mortar.nodal_variables:
            self.main_model_part.AddNodalSolutionStepVariable(variable)

    def _DofsWithReactions(self) -> list[tuple[Any, Any]]:
        return super()._DofsWithReactions() + self.mortar.dofs

    def _CreateLinearSolver(self) -> Any:
        """The multiplier solver in the static condensation of a linear bulk.

        ``linear_solver_settings.static_condensation`` (docs/theory/static_condensation.md): "auto"
        condenses when the bodies are linear and the system is large, true whenever there is an
        interface, false never; the solver reports which ran and why in the run summary.
        """
        solver = self._CreateMultiplierSolver()
        linear = self.settings["linear_solver_settings"]
        mode = static_condensation_mode(linear)
        if mode == "auto" and is_iterative(linear):
            # The iterative route is for systems no factorisation fits: the bulk is not factorised.
            return ca.StaticCondensationSolver(
                solver,
                "auto",
                "the linear solver is iterative (amgcl/gmres: PETSc), nothing is factorised",
            )
        reason = "" if mode == "off" else bulk_not_linear(self.GetComputingModelPart())
        if mode == "on" and reason:
            logger.warning(
                "%s: true, but %s: the bulk is condensed again whenever it changes, and the "
                "condensation ends when it changes on two consecutive solves",
                self.settings["linear_solver_settings"].Where("static_condensation"),
                reason,
            )
        return ca.StaticCondensationSolver(solver, mode, reason)

    def _CreateMultiplierSolver(self) -> Any:
        """The structural linear solver, wrapped in the condensing solver for vector multipliers."""
        solver = super()._CreateLinearSolver()
        contact = self.settings["contact_settings"]
        alm = self.mortar.method == "ALM"
        vector_lm = alm and len(self.mortar.dofs) > 1  # the multipliers by components
        # The iterative route condenses every ALM family (scalar normal multipliers too): an AMG
        # needs a displacement-sized system (docs/theory/condensation.md).
        iterative = is_iterative(self.settings["linear_solver_settings"])
        condensed = vector_lm or (alm and iterative)
        if not (condensed and contact["use_mixed_ulm_solver"].GetBool()):
            return solver
        mixed = contact["mixed_ulm_solver_parameters"]
        mixed.ValidateAndAssignDefaults(MIXED_ULM_DEFAULTS)
        if mixed["solver_type"].GetString() != "mixed_ulm_linear_solver":
            raise error(
                mixed,
                "solver_type",
                f'unknown condensing solver "{mixed["solver_type"].GetString()}"',
                '"mixed_ulm_linear_solver"',
            )
        return ca.MixedULMLinearSolver(solver)

    def _CreateConvergenceCriterion(self) -> ConvergenceCriterion:
        return CreateContactConvergenceCriterion(self.settings, self.mortar)

    def _CreateSolutionStrategy(self) -> Any:
        settings = self.settings
        if settings["analysis_type"].GetString() == "linear":
            return super()._CreateSolutionStrategy()
        strategy_settings = settings["solving_strategy_settings"]
        kind = strategy_settings["type"].GetString()
        if kind not in ("newton_raphson", "line_search"):
            raise not_supported(
                strategy_settings,
                "type",
                f'the contact strategy "{kind}"',
                'use "newton_raphson" or "line_search"',
            )
        contact = settings["contact_settings"]
        max_iteration = settings["max_iteration"].GetInt()
        compute_reactions = settings["compute_reactions"].GetBool()
        move_mesh_flag = settings["move_mesh_flag"].GetBool()
        inner_loop_iterations = contact["inner_loop_iterations"].GetInt()
        strategy = (
            ca.LineSearchContactStrategy
            if kind == "line_search"
            else ca.ResidualBasedNewtonRaphsonContactStrategy
        )
        return strategy(
            self.GetComputingModelPart(),
            self._GetScheme(),
            self._GetConvergenceCriterion().criterion,
            self._GetBuilderAndSolver(),
            max_iteration=max_iteration,
            compute_reactions=compute_reactions,
            reform_step_dofs=True,
            move_mesh_flag=move_mesh_flag,
            inner_loop_iterations=inner_loop_iterations,
        )

    def Initialize(self) -> None:
        """Structural initialisation; INTERACTION selects the full semi-smooth Newton.

        Raises:
            InputError: no contact process created the "Contact" part (the processes run first).
        """
        if not self.main_model_part.HasSubModelPart("Contact"):
            raise ca.InputError(
                f'the contact solver found no "Contact" sub model part in '
                f'"{self.main_model_part.Name}"\n'
                f"  where:    {self.settings.Where('contact_settings')}\n"
                "  expected: a contact process (alm_contact_process, penalty_contact_process, "
                "mesh_tying_process) in processes.contact_process_list\n"
                "  fix:      add the contact process, or remove contact_settings (structural run)"
            )
        simplified = self.settings["contact_settings"]["simplified_semi_smooth_newton"].GetBool()
        for part in (self.main_model_part, self.GetComputingModelPart()):
            part.Set(ca.INTERACTION, not simplified)
        super().Initialize()
        if self.settings["contact_settings"]["silent_strategy"].GetBool():
            self._GetSolutionStrategy().SetEchoLevel(0)

    def ContactStatus(self) -> tuple[int, int, int, float]:
        """(active slave nodes, slipping ones, live pairs, max penetration) for the step table.

        The penetration of a node is −WEIGHTED_GAP / A with A its lumped slave area in the
        initial configuration (computed once); 0 when no node penetrates.
        """
        main = self.main_model_part
        if not main.HasSubModelPart("Contact"):
            return (0, 0, 0, 0.0)
        contact = main.GetSubModelPart("Contact")
        if getattr(self, "_slave_areas", None) is None:
            areas: dict[int, float] = {}
            for condition in contact.Conditions:
                if condition.Is(ca.SLAVE):
                    geometry = condition.GetGeometry()
                    share = abs(geometry.DomainSize()) / len(geometry)
                    for node in geometry:
                        areas[node.Id] = areas.get(node.Id, 0.0) + share
            self._slave_areas = areas
        areas = self._slave_areas
        return contact_status(
            main,
            contact.Is(ca.SLIP),
            lambda _, ids: np.array([areas.get(int(i), 0.0) for i in ids], dtype=float),
        )

    def FinalizeSolutionStep(self) -> None:
        """Finalize the step; with ``ensure_contact`` a step without contact is an error."""
        super().FinalizeSolutionStep()
        if self.settings["contact_settings"]["ensure_contact"].GetBool():
            ca.ContactUtilities.CheckActivity(self.GetComputingModelPart(), True)
