"""``alm_contact_process``: augmented-Lagrangian mortar contact (Kratos ``ALMContactProcess``).

Overview: ``docs/input_layer.md`` §4. On top of the search base it chooses the
condition stem from ``contact_type``, ``normal_variation`` and ``alternative_formulations``, writes
the ALM constants into the ProcessInfo (penalty ε and scale factor k, automatic from Young's modulus
and the nodal size unless ``manual_ALM``), the per-pair friction coefficients into the pair
properties, initialises the nodal contact values (ALMFastInit) and, before output, clears the
augmented pressures of inactive nodes.
"""

from __future__ import annotations

import logging
import sys
from typing import Any

import contact_app as ca
from contact_app import _core
from contact_app.parameters import Parameters

from ._pairs import (
    PAIR_KEYS,
    fail,
    pair_block,
    process_contact_types,
    process_mortar_type,
    unknown_choice,
)
from .search_base_process import SearchBaseProcess, base_defaults

logger = logging.getLogger("contact_app.contact")

#: ``normal_variation`` values → NormalDerivativesComputation (stored in CONSIDER_NORMAL_VARIATION).
NORMAL_VARIATION = {
    "no_derivatives_computation": 0,
    "elemental_derivatives": 1,
    "nodal_elemental_derivatives": 2,
    "no_derivatives_computation_with_normal_update": 3,
}
NORMAL_UPDATE_SUFFIX = "WithNormalUpdate"


def alm_defaults() -> dict[str, Any]:
    """Every key of the ALM process with its default."""
    defaults = base_defaults("contact_model_part", "contact_property_ids")
    defaults.update(
        {
            "friction_coefficients": pair_block(0.0),
            "contact_type": "Frictionless",
            "not_normal_update_frictional": False,
            "normal_variation": "no_derivatives_computation",
            "frictional_law": "Coulomb",
            "tangent_factor": 1.0,
            "operator_threshold": 1.0e-3,
            "slip_augmentation_coefficient": 0.0,
            "slip_threshold": 2.0e-2,
            "clear_inactive_for_post": True,
            "slip_step_reset_frequency": 1,
            "advance_explicit_parameters": {
                "manual_max_gap_theshold": False,
                "automatic_gap_factor": 1.0e-1,
                "max_gap_threshold": 5.0e-2,
                "max_gap_factor": 1.0e2,
                "logistic_exponent_factor": 6.0,
            },
            "advance_ALM_parameters": {
                "manual_ALM": False,
                "stiffness_factor": 1.0,
                "penalty_scale_factor": 1.0,
                "use_scale_factor": True,
                "penalty": 1.0e-12,
                "scale_factor": 1.0,
                "adapt_penalty": False,
                "max_gap_factor": 1.0e-3,
            },
            "alternative_formulations": {"axisymmetric": False},
        }
    )
    return defaults


def Factory(settings: Parameters, model: ca.Model) -> ALMContactProcess:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return ALMContactProcess(model, settings["Parameters"])


class ALMContactProcess(SearchBaseProcess):
    """Augmented-Lagrangian mortar contact between the pairs of interface parts.

    Args:
        model: the model holding the main model part.
        settings: the process ``Parameters``; missing keys get their defaults.

    Raises:
        InputError: unknown key, unknown contact type or normal variation, axisymmetry in 3D, a
            model part that does not exist, or a contact type the solver's mortar_type cannot hold.
    """

    process_name = "alm_contact_process"
    #: Family prefix of the condition names ("ALM" / "Penalty").
    method = "ALM"

    def __init__(self, model: ca.Model, settings: Parameters) -> None:
        settings.RecursivelyValidateAndAssignDefaults(self._defaults())
        self.settings = settings
        self._read_contact_type(settings)
        super().__init__(model, settings, "contact_model_part", "contact_property_ids")
        self.slip_reset_counter = 0

    @classmethod
    def _defaults(cls) -> dict[str, Any]:
        return alm_defaults()

    def _read_contact_type(self, settings: Parameters) -> None:
        written = settings["contact_type"].GetString()
        base = written.removesuffix(NORMAL_UPDATE_SUFFIX)
        if base not in self._contact_types():
            raise unknown_choice(settings, "contact_type", written, base, self._contact_types())
        variation = settings["normal_variation"].GetString().lower()
        if variation not in NORMAL_VARIATION:
            written = settings["normal_variation"].GetString()
            raise unknown_choice(settings, "normal_variation", written, variation, NORMAL_VARIATION)
        self.contact_type = base
        self.mortar = process_mortar_type(self.method, base)
        self.is_frictional = self.mortar.frictional
        self.pure_slip = self.mortar.pure_slip
        normal_update = written.endswith(NORMAL_UPDATE_SUFFIX) or (
            self.is_frictional and not settings["not_normal_update_frictional"].GetBool()
        )
        self.normal_variation = NORMAL_VARIATION[variation]
        if normal_update and self.normal_variation == 0:
            self.normal_variation = 3
        self.axisymmetric = settings["alternative_formulations"]["axisymmetric"].GetBool()

    def _contact_types(self) -> tuple[str, ...]:
        return process_contact_types(self.method)

    def _required_variables(self) -> list[tuple[Any, str]]:
        mortar = self.mortar
        required = [ca.WEIGHTED_GAP, ca.NORMAL]
        if mortar.multiplier is not None:
            required.append(mortar.multiplier)
        if mortar.frictional:
            required.append(ca.WEIGHTED_SLIP)
        return [(variable, mortar.name) for variable in required]

    # -- hooks --

    def ExecuteInitialize(self) -> None:
        """Check the dimension, then the base initialisation (which calls the hooks below)."""
        dimension = self.main_model_part.ProcessInfo[ca.DOMAIN_SIZE]
        if self.axisymmetric and dimension != 2:
            raise fail(
                self.settings["alternative_formulations"],
                "axisymmetric",
                f"axisymmetric contact in a {dimension}D model",
                "a 2D model (DOMAIN_SIZE = 2)",
                'set "axisymmetric": false',
            )
        if self.is_frictional and not self.pure_slip:
            total = sum(
                p.GetValue(ca.FRICTION_COEFFICIENT)
                for p in self.main_model_part.Properties
                if p.Has(ca.FRICTION_COEFFICIENT)
            )
            total += sum(
                self.settings["friction_coefficients"][key].GetDouble() for key in PAIR_KEYS
            )
            if total < sys.float_info.epsilon:  # as the reference: nothing can stick
                self.pure_slip = True
                logger.warning(
                    "%s: every friction coefficient is zero; the frictional run is pure slip",
                    self.process_name,
                )
        super().ExecuteInitialize()
        frequency = self.settings["slip_step_reset_frequency"].GetInt()
        if self.main_model_part.ProcessInfo[ca.IS_RESTARTED] and frequency > 0:
            self.slip_reset_counter = int(self.main_model_part.ProcessInfo[ca.STEP]) % frequency

    def _initialize_process_info(self) -> None:
        super()._initialize_process_info()
        info = self.main_model_part.ProcessInfo
        alm = self.settings["advance_ALM_parameters"]
        info[ca.CONSIDER_NORMAL_VARIATION] = self.normal_variation
        info[ca.ACTIVE_SET_CONVERGED] = True
        info[ca.ADAPT_PENALTY] = alm["adapt_penalty"].GetBool()
        info[ca.MAX_GAP_FACTOR] = alm["max_gap_factor"].GetDouble()

    def _initialize_search_values(self) -> None:
        super()._initialize_search_values()
        for part in (self.computing_model_part, self.contact_model_part):
            part.Set(ca.CONTACT, True)
            part.Set(ca.SLIP, self.is_frictional)
        info = self.main_model_part.ProcessInfo
        if self.is_frictional:
            info[ca.TANGENT_FACTOR] = self.settings["tangent_factor"].GetDouble()
            info[ca.OPERATOR_THRESHOLD] = self.settings["operator_threshold"].GetDouble()
            info[ca.SLIP_AUGMENTATION_COEFFICIENT] = self.settings[
                "slip_augmentation_coefficient"
            ].GetDouble()
            info[ca.SLIP_THRESHOLD] = self.settings["slip_threshold"].GetDouble()
        self._assign_friction_coefficients()
        for properties in self.pair_properties.values():
            if self.axisymmetric and not properties.Has(ca.THICKNESS):
                properties[ca.THICKNESS] = 1.0

    def _estimate_penalty(self, alm: Parameters) -> None:
        """Compute INITIAL_PENALTY and SCALE_FACTOR from the stiffness of the contact part."""
        _core.ALMVariablesCalculationProcess(
            self.contact_model_part,
            stiffness_factor=alm["stiffness_factor"].GetDouble(),
            penalty_scale_factor=alm["penalty_scale_factor"].GetDouble(),
        ).Execute()

    def _initialize_problem_parameters(self) -> None:
        info = self.main_model_part.ProcessInfo
        alm = self.settings["advance_ALM_parameters"]
        if alm["manual_ALM"].GetBool():
            info[ca.INITIAL_PENALTY] = alm["penalty"].GetDouble()
            info[ca.SCALE_FACTOR] = alm["scale_factor"].GetDouble()
        else:
            self._estimate_penalty(alm)
            if not alm["use_scale_factor"].GetBool():
                info[ca.SCALE_FACTOR] = 1.0
        for variable in (ca.INITIAL_PENALTY, ca.SCALE_FACTOR):
            if info[variable] < sys.float_info.epsilon:
                info[variable] = 1.0
        logger.info(
            "%s: penalty %.6g, scale factor %.6g",
            self.process_name,
            info[ca.INITIAL_PENALTY],
            info[ca.SCALE_FACTOR],
        )

    def _initialize_search_conditions(self) -> None:
        _core.ALMFastInit(self.contact_model_part).Execute()

    def _set_additional_parameters(self, settings: dict[str, Any]) -> None:
        settings["pure_slip"] = self.pure_slip

    def _get_condition_name(self) -> str:
        nodal = NORMAL_VARIATION["nodal_elemental_derivatives"]
        nv = self.normal_variation == nodal
        if self.axisymmetric and not self.mortar.has_axisym:
            raise fail(
                self.settings["alternative_formulations"],
                "axisymmetric",
                f"there is no axisymmetric {self.mortar.family} formulation",
                'contact_type "Frictionless" or "Frictional" with axisymmetry',
            )
        return self.mortar.ConditionName(nv, self.axisymmetric)

    def ExecuteInitializeSolutionStep(self) -> None:
        """Search, then reset the SLIP flags every ``slip_step_reset_frequency`` steps."""
        super().ExecuteInitializeSolutionStep()
        frequency = self.settings["slip_step_reset_frequency"].GetInt()
        if self.is_frictional and not self.pure_slip and frequency > 0:
            self.slip_reset_counter += 1
            if self.slip_reset_counter >= frequency:
                ca.VariableUtils().SetFlag(ca.SLIP, False, self.contact_model_part.Nodes)
                self.slip_reset_counter = 0

    def GetRestartState(self) -> dict[str, Any]:
        """The search state and the SLIP reset counter."""
        return {**super().GetRestartState(), "slip_reset_counter": self.slip_reset_counter}

    def SetRestartState(self, state: dict[str, Any]) -> None:
        """Resume the search state and the SLIP reset counter of the saving run."""
        super().SetRestartState(state)
        self.slip_reset_counter = int(state["slip_reset_counter"])

    def ExecuteBeforeOutputStep(self) -> None:
        """Zero the augmented pressures of inactive nodes (``clear_inactive_for_post``)."""
        if not self.settings["clear_inactive_for_post"].GetBool():
            return
        zero = [0.0, 0.0, 0.0]
        for node in self.contact_model_part.Nodes:
            if not node.Is(ca.ACTIVE):
                node.SetValue(ca.AUGMENTED_NORMAL_CONTACT_PRESSURE, 0.0)
                node.SetValue(ca.AUGMENTED_TANGENT_CONTACT_PRESSURE, zero)
