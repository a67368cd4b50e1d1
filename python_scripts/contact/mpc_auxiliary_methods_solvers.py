"""What the MPC contact solvers add to the structural ones (Kratos ``mpc_contact_structural_*``).

``mpc_contact_settings`` defaults and checks (``docs/input_layer.md`` §2), the historical
variables of the MPC route, the elimination builder (which honours the contact constraints and
writes the reactions the active-set criterion reads), ``And(structural, MPCContactCriteria)`` and
the MPC contact Newton strategy (``docs/theory/contact_strategies.md`` §3). Shared by the static and
implicit dynamic MPC solvers.
"""

from __future__ import annotations

import logging
from typing import Any

import contact_app as ca
from contact_app import _core
from contact_app.analysis.solvers.convergence_criteria_factory import (
    ConvergenceCriterion,
    CreateConvergenceCriterion,
)
from contact_app.analysis.validation import error, not_supported
from contact_app.parameters import suggest

from .auxiliary_methods_solvers import ForcingSolverMixin, contact_status

logger = logging.getLogger("contact_app.contact")

MPC_CONTACT_TYPES = ("Frictionless", "Frictional", "MeshTying")

MPC_CONTACT_SETTINGS_DEFAULTS: dict[str, Any] = {
    "contact_type": "Frictionless",
    "simplified_semi_smooth_newton": False,
    "inner_loop_iterations": 10,
    "update_each_nl_iteration": False,
    "enforce_ntn": False,
}

#: ``solver_settings`` the MPC contact solvers set to true whatever the file says: the MPC criterion
#: reads the contact forces from the reactions, and the contact constraints change between steps.
MPC_FORCED_SOLVER_SETTINGS = ("compute_reactions", "reform_dofs_at_each_step", "clear_storage")


def mpc_variables(contact_type: str) -> list[Any]:
    """Historical variables of the MPC route besides the structural ones (docs/input_layer.md)."""
    variables = [ca.NORMAL, ca.NODAL_H, ca.WEIGHTED_GAP]
    if contact_type == "Frictional":
        variables.append(ca.WEIGHTED_SLIP)
    return variables


class MPCContactSolverMixin(ForcingSolverMixin):
    """MPC contact additions to a structural solver (used before the structural base in the MRO)."""

    SETTINGS_BLOCK = "mpc_contact_settings"
    SETTINGS_BLOCK_DEFAULTS = MPC_CONTACT_SETTINGS_DEFAULTS
    FORCED_KEYS = MPC_FORCED_SOLVER_SETTINGS
    FORCED_REASON = (
        "the MPC contact solvers require: the MPC criterion reads the contact forces from the "
        "reactions, and the contact constraints change between steps, so the DoF set is "
        "rebuilt and the stored system cleared at every step"
    )

    def ValidateSettings(self) -> None:
        """Structural checks, then ``mpc_contact_settings`` (unknown keys are errors).

        Raises:
            InputError: unknown key, unknown ``contact_type``, ``inner_loop_iterations`` < 1.
            ConfigurationError: ``enforce_ntn`` (not implemented, as in Kratos).
        """
        mpc = self.settings["mpc_contact_settings"]
        mpc.RecursivelyValidateAndAssignDefaults(MPC_CONTACT_SETTINGS_DEFAULTS)
        contact_type = mpc["contact_type"].GetString()
        if contact_type not in MPC_CONTACT_TYPES:
            raise error(
                mpc,
                "contact_type",
                f'unknown contact_type "{contact_type}"',
                "one of " + ", ".join(f'"{t}"' for t in MPC_CONTACT_TYPES),
                suggest(contact_type, list(MPC_CONTACT_TYPES)),
            )
        self.contact_type = contact_type
        if mpc["inner_loop_iterations"].GetInt() < 1:
            raise error(mpc, "inner_loop_iterations", "inner_loop_iterations < 1", "≥ 1")
        if mpc["enforce_ntn"].GetBool():
            raise not_supported(
                mpc,
                "enforce_ntn",
                "node-to-node enforcement of the MPC contact",
                'set "enforce_ntn": false (Kratos accepts it but does not implement it either)',
            )
        self._forced.Apply(self.settings)
        super().ValidateSettings()

    def AddVariables(self) -> None:
        """Structural variables plus NORMAL, NODAL_H, WEIGHTED_GAP (+ WEIGHTED_SLIP, frictional)."""
        super().AddVariables()
        for variable in mpc_variables(self.contact_type):
            self.main_model_part.AddNodalSolutionStepVariable(variable)

    def _CreateBuilderAndSolver(self) -> Any:
        """The elimination builder: it applies the constraints and writes the slaves' reactions."""
        kind = self.settings["builder_and_solver_settings"]["type"].GetString()
        if kind != "elimination":
            logger.info(
                'mpc_contact_settings: builder_and_solver_settings.type "%s" replaced by the '
                "elimination builder with constraints (the MPC route needs it)",
                kind,
            )
        return ca.ResidualBasedEliminationBuilderAndSolver(self._GetLinearSolver())

    def _CreateConvergenceCriterion(self) -> ConvergenceCriterion:
        """And(structural criterion, MPCContactCriteria)."""
        base = CreateConvergenceCriterion(self.settings)
        self._mpc_criteria = ca.MPCContactCriteria()
        combined = ca.AndCriteria(base.criterion, self._mpc_criteria)
        combined.SetEchoLevel(self.settings["echo_level"].GetInt())
        return ConvergenceCriterion(
            combined, residual=base.residual, displacement=base.displacement
        )

    def _CreateSolutionStrategy(self) -> Any:
        settings = self.settings
        if settings["analysis_type"].GetString() == "linear":
            raise not_supported(
                settings,
                "analysis_type",
                'the MPC contact solver with "analysis_type": "linear"',
                'use "non_linear" (the active set needs the Newton loop)',
            )
        kind = settings["solving_strategy_settings"]["type"].GetString()
        if kind != "newton_raphson":
            raise not_supported(
                settings["solving_strategy_settings"],
                "type",
                f'the MPC contact strategy "{kind}"',
                'use "newton_raphson"',
            )
        mpc = settings["mpc_contact_settings"]
        return ca.ResidualBasedNewtonRaphsonMPCContactStrategy(
            self.GetComputingModelPart(),
            self._GetScheme(),
            self._GetConvergenceCriterion().criterion,
            self._GetBuilderAndSolver(),
            max_iteration=settings["max_iteration"].GetInt(),
            compute_reactions=True,
            reform_step_dofs=True,
            move_mesh_flag=settings["move_mesh_flag"].GetBool(),
            inner_loop_iterations=mpc["inner_loop_iterations"].GetInt(),
            update_each_nl_iteration=mpc["update_each_nl_iteration"].GetBool(),
            enforce_ntn=mpc["enforce_ntn"].GetBool(),
        )

    def Initialize(self) -> None:
        """Structural initialisation; ProcessInfo INTERACTION = simplified_semi_smooth_newton.

        Raises:
            InputError: no MPC contact process created the "Contact" part.
        """
        if not self.main_model_part.HasSubModelPart("Contact"):
            raise ca.InputError(
                f'the MPC contact solver found no "Contact" sub model part in '
                f'"{self.main_model_part.Name}"\n'
                f"  where:    {self.settings.Where('mpc_contact_settings')}\n"
                "  expected: mpc_contact_process in processes.contact_process_list\n"
                "  fix:      add the process, or remove mpc_contact_settings (structural run)"
            )
        simplified = self.settings["mpc_contact_settings"]["simplified_semi_smooth_newton"]
        # The MPC route uses the opposite convention of the mortar solvers: INTERACTION on the
        # ProcessInfo selects the outer active-set loop (docs/theory/contact_strategies.md §3).
        self.main_model_part.ProcessInfo.Set(ca.INTERACTION, simplified.GetBool())
        super().Initialize()

    def ContactStatus(self) -> tuple[int, int, int, float]:
        """(active slave nodes, slipping ones, live pairs, max penetration) for the step table.

        The penetration divides WEIGHTED_GAP by the lumped slave area NODAL_MAUX of the criterion.
        """
        return contact_status(
            self.main_model_part,
            self.contact_type == "Frictional",
            lambda part, ids: _core.BulkNodalValues(part, ids, ca.NODAL_MAUX, False)[0][:, 0],
        )
