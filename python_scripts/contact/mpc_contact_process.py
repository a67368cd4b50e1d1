"""``mpc_contact_process``: contact through multipoint constraints (Kratos ``MPCContactProcess``).

Overview: ``docs/input_layer.md`` §4. Each pair gets an ``MPCMortarContactCondition``
and a ``ContactMasterSlaveConstraint`` (created by the MPC search); the condition refreshes the
constraint in its life-cycle hooks. ``contact_type`` Frictionless, Frictional (SLIP flag) or
MeshTying (RIGID flag).
"""

from __future__ import annotations

from typing import Any

import contact_app as ca
from contact_app import _core
from contact_app.parameters import Parameters

from ._pairs import pair_block, unknown_choice
from .search_base_process import SearchBaseProcess, base_defaults

CONTACT_TYPES = ("Frictionless", "Frictional", "MeshTying")


def mpc_defaults() -> dict[str, Any]:
    """Every key of the MPC process with its default."""
    defaults = base_defaults("contact_model_part", "contact_property_ids")
    defaults.update(
        {
            "friction_coefficients": pair_block(0.0),
            "contact_type": "Frictionless",
            "tangent_factor": 1.0e-1,
            "zero_tolerance_factor": 1.0e2,
            "reaction_check_stiffness_factor": 1.0e-10,
            "update_condition_relation_step": False,
            "clear_inactive_for_post": True,
            "slip_step_reset_frequency": 1,
        }
    )
    return defaults


def Factory(settings: Parameters, model: ca.Model) -> MPCContactProcess:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return MPCContactProcess(model, settings["Parameters"])


class MPCContactProcess(SearchBaseProcess):
    """Multipoint-constraint mortar contact between the pairs of interface parts."""

    process_name = "mpc_contact_process"

    def __init__(self, model: ca.Model, settings: Parameters) -> None:
        settings.RecursivelyValidateAndAssignDefaults(mpc_defaults())
        self.settings = settings
        contact_type = settings["contact_type"].GetString()
        if contact_type not in CONTACT_TYPES:
            raise unknown_choice(
                settings, "contact_type", contact_type, contact_type, CONTACT_TYPES
            )
        self.contact_type = contact_type
        self.is_frictional = contact_type == "Frictional"
        self.is_rigid = contact_type == "MeshTying"
        super().__init__(model, settings, "contact_model_part", "contact_property_ids")

    def _required_variables(self) -> list[tuple[Any, str]]:
        required = [(ca.WEIGHTED_GAP, "mpc_contact_settings"), (ca.NORMAL, "mpc_contact_settings")]
        if self.is_frictional:
            required.append((ca.WEIGHTED_SLIP, "mpc_contact_settings (contact_type Frictional)"))
        return required

    def _get_condition_name(self) -> str:
        return "MPCMortarContact"

    def _set_additional_parameters(self, settings: dict[str, Any]) -> None:
        settings["pure_slip"] = False

    def _create_search_process(self, settings: Any, properties: Any, resume: bool) -> Any:
        return _core.MPCContactSearchProcess(self.main_model_part, settings, properties, resume)

    def _initialize_search_values(self) -> None:
        super()._initialize_search_values()
        info = self.main_model_part.ProcessInfo
        info[ca.TANGENT_FACTOR] = self.settings["tangent_factor"].GetDouble()
        info[ca.REACTION_CHECK_STIFFNESS_FACTOR] = self.settings[
            "reaction_check_stiffness_factor"
        ].GetDouble()
        for part in (self.computing_model_part, self.contact_model_part):
            part.Set(ca.CONTACT, True)
            part.Set(ca.SLIP, self.is_frictional)
            part.Set(ca.RIGID, self.is_rigid)
        self._assign_friction_coefficients()

    def _initialize_search_conditions(self) -> None:
        _core.ALMFastInit(self.contact_model_part).Execute()
        self._compute_nodal_weights()

    def _compute_nodal_weights(self) -> None:
        """NODAL_PAUX = number of slave interface conditions holding the node (the weights)."""
        counts: dict[int, int] = {}
        for condition in self.contact_model_part.Conditions:
            if condition.Is(ca.SLAVE):
                for node in condition.GetGeometry():
                    counts[node.Id] = counts.get(node.Id, 0) + 1
        for node in self.contact_model_part.Nodes:
            node.SetValue(ca.NODAL_PAUX, float(counts.get(node.Id, 0)))

    def ExecuteInitializeSolutionStep(self) -> None:
        """Search; frictional pairs are flagged SLIP every step (the reference's rule)."""
        super().ExecuteInitializeSolutionStep()
        if self.is_frictional:
            ca.VariableUtils().SetFlag(ca.SLIP, True, self.computing_model_part.Conditions)

    def ExecuteFinalizeSolutionStep(self) -> None:
        """Freeze the constraints (BLOCKED) unless ``update_condition_relation_step``."""
        super().ExecuteFinalizeSolutionStep()
        if not self.settings["update_condition_relation_step"].GetBool():
            ca.VariableUtils().SetFlag(ca.BLOCKED, True, self.computing_model_part.Conditions)
