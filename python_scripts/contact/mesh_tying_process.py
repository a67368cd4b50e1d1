"""``mesh_tying_process``: mortar mesh tying of non-matching meshes (Kratos ``MeshTyingProcess``).

Overview: ``docs/input_layer.md`` §4. The pairs are searched once (the default
``database_step_update`` is 999999999) and the tied variable, ``variable_name`` (a double →
scalar multiplier, a 3-vector → vector multiplier), goes into the pair property TYING_VARIABLE.
"""

from __future__ import annotations

from typing import Any

import contact_app as ca
from contact_app.parameters import Parameters

from ._pairs import MORTAR_TYPES, fail, pair_block
from .search_base_process import SEARCH_PARAMETERS_DEFAULTS, SearchBaseProcess, base_defaults


def mesh_tying_defaults() -> dict[str, Any]:
    """Every key of the mesh-tying process with its default."""
    defaults = base_defaults("mesh_tying_model_part", "mesh_tying_property_ids")
    search = dict(SEARCH_PARAMETERS_DEFAULTS)
    search["database_step_update"] = 999999999
    defaults["search_parameters"] = search
    defaults["variable_name"] = "DISPLACEMENT"
    defaults["consider_static_condensation"] = False
    defaults["scale_factor_parameters"] = {
        "manual_scale_factor": False,
        "stiffness_factor": 1.0,
        "scale_factor": 1.0,
    }
    defaults["mesh_tying_property_ids"] = pair_block(0)
    return defaults


def Factory(settings: Parameters, model: ca.Model) -> MeshTyingProcess:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return MeshTyingProcess(model, settings["Parameters"])


class MeshTyingProcess(SearchBaseProcess):
    """Tie the variable ``variable_name`` across the pairs of interface parts.

    Raises:
        InputError: unknown key, a variable that is neither a double nor a 3-vector, static
            condensation (not available), or the solver's mortar_type not storing the multiplier.
    """

    process_name = "mesh_tying_process"

    def __init__(self, model: ca.Model, settings: Parameters) -> None:
        settings.RecursivelyValidateAndAssignDefaults(mesh_tying_defaults())
        self.settings = settings
        name = settings["variable_name"].GetString()
        try:
            variable = ca.get_variable(name)
        except KeyError:
            raise fail(
                settings, "variable_name", f'unknown variable "{name}"', "a registered variable"
            ) from None
        if variable.Type() not in ("Double", "Array"):
            raise fail(
                settings,
                "variable_name",
                f'"{name}" is a {variable.Type()} variable',
                "a double (scalar tying) or a 3-vector variable such as DISPLACEMENT",
            )
        if settings["consider_static_condensation"].GetBool():
            raise fail(
                settings,
                "consider_static_condensation",
                "static condensation of the tying multipliers is not available",
                "false",
            )
        self.variable_name = name
        self.scalar = variable.Type() == "Double"
        self.mortar = MORTAR_TYPES["ScalarMeshTying" if self.scalar else "ComponentsMeshTying"]
        super().__init__(model, settings, "mesh_tying_model_part", "mesh_tying_property_ids")

    def _required_variables(self) -> list[tuple[Any, str]]:
        return [(self.mortar.multiplier, self.mortar.name)]

    def _get_condition_name(self) -> str:
        return self.mortar.ConditionName(False, False)

    def _initialize_search_conditions(self) -> None:
        for properties in self.pair_properties.values():
            properties[ca.TYING_VARIABLE] = self.variable_name
        residual = ca.WEIGHTED_SCALAR_RESIDUAL if self.scalar else ca.WEIGHTED_VECTOR_RESIDUAL
        zero: Any = 0.0 if self.scalar else [0.0, 0.0, 0.0]
        if self.main_model_part.HasNodalSolutionStepVariable(residual):
            for node in self.contact_model_part.Nodes:
                node.SetSolutionStepValue(residual, 0, zero)
        for condition in self.contact_model_part.Conditions:
            condition.SetValue(ca.NORMAL, [0.0, 0.0, 0.0])
        self.main_model_part.Set(ca.RIGID, True)
        scale = self.settings["scale_factor_parameters"]
        if scale["manual_scale_factor"].GetBool():
            self.main_model_part.ProcessInfo[ca.SCALE_FACTOR] = scale["scale_factor"].GetDouble()
