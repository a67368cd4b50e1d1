"""``SearchBaseProcess``: what every contact process shares (Kratos ``search_base_process``).

The process turns the interface parts named in the settings into the ``Contact`` sub model part
(skin conditions generated from the elements when a part holds only nodes, SLAVE / MASTER flags,
one pair property per pair key), then drives one C++ search per pair key
(``ContactSearchProcess``), which creates the paired mortar conditions in ``ComputingContact``.
Overview: ``docs/input_layer.md`` §3.

Subclasses (ALM, penalty, mesh tying, MPC) name their settings keys, the condition stem and the
values they push into the ProcessInfo and the properties through the ``_initialize_*`` hooks.
"""

from __future__ import annotations

import logging
from typing import Any

import contact_app as ca
from contact_app import _core
from contact_app.model_part_lookup import get_model_part
from contact_app.parameters import Parameters
from contact_app.processes.interval import Interval
from contact_app.processes.process import Process

from ._pairs import PAIR_KEYS, fail, pair_block, string_lists

logger = logging.getLogger("contact_app.contact")

#: ``search_parameters`` defaults (docs/theory/contact_search.md §5).
SEARCH_PARAMETERS_DEFAULTS: dict[str, Any] = {
    "type_search": "in_radius_with_obb",
    "simple_search": False,
    "adapt_search": False,
    "search_factor": 3.5,
    "active_check_factor": 0.01,
    "max_number_results": 1000,
    "bucket_size": 4,
    "dynamic_search": False,
    "static_check_movement": False,
    "database_step_update": 1,
    "normal_orientation_threshold": 0.1,
    "consider_gap_threshold": False,
    "debug_mode": False,
    "predict_correct_lagrange_multiplier": False,
    "check_gap": "check_mapping",
    "octree_search_parameters": {
        "bounding_box_factor": 0.1,
        "debug_obb": False,
        "OBB_intersection_type": "SeparatingAxisTheorem",
        "build_from_bounding_box": True,
        "lower_bounding_box_coefficient": 0.0,
        "higher_bounding_box_coefficient": 1.0,
    },
}

#: ``search_parameters`` keys the process reads itself; every other key goes to the C++ search
#: (``ContactSearchSettings.from_dict``, which validates them: names, types, ranges, spellings).
PROCESS_SEARCH_KEYS = ("adapt_search", "active_check_factor", "database_step_update")


def base_defaults(interface_key: str, property_key: str) -> dict[str, Any]:
    """The keys every contact process accepts, with the interface and property keys it uses."""
    return {
        "help": "",
        "mesh_id": 0,
        "model_part_name": "Structure",
        "computing_model_part_name": "computing_domain",
        interface_key: pair_block([]),
        "assume_master_slave": pair_block([]),
        property_key: pair_block(0),
        "interval": [0.0, "End"],
        "zero_tolerance_factor": 1.0,
        "integration_order": 2,
        # True, unlike the reference: the cells fan around the overlap's area centroid,
        # continuous in the vertices (docs/theory/mortar.md section 1).
        "consider_tessellation": True,
        "normal_check_proportion": 0.1,
        "search_parameters": SEARCH_PARAMETERS_DEFAULTS,
    }


def _id_list(ids: list[int], limit: int = 20) -> str:
    """``"5, 6, 7"``; beyond ``limit`` ids the first ones and ``"... (n more)"``."""
    shown = ", ".join(str(i) for i in ids[:limit])
    return shown + (f", ... ({len(ids) - limit} more)" if len(ids) > limit else "")


class SearchBaseProcess(Process):
    """Interface preparation and pair search shared by the contact processes.

    Args:
        model: the model holding the main model part.
        settings: the process ``Parameters`` (validated by the subclass against its defaults).
        interface_key: the settings key listing the interface parts per pair key.
        property_key: the settings key with the pair property ids.

    Raises:
        InputError: a model part that does not exist, a slave part that does not touch its
            interface, a bad search option, or a formulation the solver's variables cannot hold.
    """

    #: What the processes call themselves in messages.
    process_name = "search_base_process"
    #: The "Contact" and "ComputingContact" sub model parts of the main one (ExecuteInitialize).
    contact_model_part: ca.ModelPart
    computing_model_part: ca.ModelPart

    def __init__(
        self,
        model: ca.Model,
        settings: Parameters,
        interface_key: str = "search_model_part",
        property_key: str = "search_property_ids",
    ) -> None:
        self.model = model
        self.settings = settings
        self.interface_key = interface_key
        self.main_model_part = get_model_part(
            model, settings["model_part_name"].GetString(), settings.Where("model_part_name")
        )
        self.interval = Interval.from_parameters(settings["interval"])
        self.search_settings = settings["search_parameters"]
        self._check_search_parameters()
        self.pairs = string_lists(settings, interface_key)
        self.slave_names = string_lists(settings, "assume_master_slave")
        self.property_ids = {key: settings[property_key][key].GetInt() for key in PAIR_KEYS}
        self.interface_parts = {
            key: [self._sub_model_part(settings[interface_key][key], name) for name in names]
            for key, names in self.pairs.items()
        }
        self.slave_parts = {
            key: [
                self._sub_model_part(settings["assume_master_slave"][key], name) for name in names
            ]
            for key, names in self.slave_names.items()
        }
        self._check_slave_parts()
        self._check_formulation()
        self.database_step = 0
        self.database_step_update = self.search_settings["database_step_update"].GetInt()
        self.searches: dict[str, Any] = {}
        self.pair_properties: dict[str, Any] = {}
        self.preprocess = False

    # -- construction-time checks --

    def _check_search_parameters(self) -> None:
        search = self.search_settings
        self.search_values = {
            key: value.GetValue() for key, value in search.items() if key not in PROCESS_SEARCH_KEYS
        }
        _core.ContactSearchSettings.from_dict(self.search_values, search.Where())
        if search["adapt_search"].GetBool():
            raise fail(
                search,
                "adapt_search",
                '"adapt_search": true is not supported',
                "false (the search factor is already relative to the element size)",
                "remove the key or set it to false",
            )
        if search["database_step_update"].GetInt() < 1:
            raise fail(search, "database_step_update", "database_step_update < 1", "an integer ≥ 1")

    def _sub_model_part(self, where: Parameters, name: str) -> ca.ModelPart:
        """The interface / slave part ``name``, relative to the main model part or dotted."""
        main = self.main_model_part
        if main.HasSubModelPart(name):
            return main.GetSubModelPart(name)
        part = get_model_part(self.model, name, where.Where())
        root = part.GetRootModelPart()
        if root.FullName() != main.GetRootModelPart().FullName():
            raise ca.InputError(
                f'model part "{name}" is not part of "{main.FullName()}"\n'
                f"  where:    {where.Where()}\n"
                f'  expected: a sub model part of "{main.FullName()}"'
            )
        return part

    def _check_slave_parts(self) -> None:
        for key, slaves in self.slave_parts.items():
            where = self.settings["assume_master_slave"][key]
            if key not in self.interface_parts:
                raise fail(
                    self.settings["assume_master_slave"],
                    key,
                    f'pair "{key}" names slave parts but no interface parts',
                    f'"{self.interface_key}"["{key}"] listing the parts of that interface',
                    f'add the interface parts to "{self.interface_key}" or remove pair "{key}"',
                )
            interface_nodes = {n.Id for p in self.interface_parts[key] for n in p.Nodes}
            for slave in slaves:
                if not any(node.Id in interface_nodes for node in slave.Nodes):
                    raise ca.InputError(
                        f'slave part "{slave.FullName()}" has no node on the interface of pair '
                        f'"{key}"\n  where:    {where.Where()}\n'
                        "  expected: a part (a body or a face set) that shares nodes with "
                        + ", ".join(f'"{p.FullName()}"' for p in self.interface_parts[key])
                        + "\n  fix:      name the part of the slave body that touches the interface"
                    )

    def _required_variables(self) -> list[tuple[Any, str]]:
        """Historical variables the formulation needs, with the mortar_type that adds them."""
        return []

    def _check_formulation(self) -> None:
        for variable, mortar_type in self._required_variables():
            if not self.main_model_part.HasNodalSolutionStepVariable(variable):
                raise ca.InputError(
                    f"{self.process_name}: the model part "
                    f'"{self.main_model_part.FullName()}" does not store {variable.Name()}, '
                    f"which this formulation needs\n  where:    {self.settings.Where()}\n"
                    f'  expected: solver_settings.contact_settings.mortar_type = "{mortar_type}"'
                    "\n  fix:      make the solver's mortar_type match the process' contact_type"
                )

    # -- life cycle --

    def ExecuteInitialize(self) -> None:
        """Build the Contact part, nodal sizes, properties and searches (docs/input_layer.md §3)."""
        main = self.main_model_part
        self.dimension = main.ProcessInfo[ca.DOMAIN_SIZE]
        if main.ProcessInfo[ca.IS_RESTARTED]:
            self._resume_from_restart()
            return
        if main.HasSubModelPart("Contact") and main.Is(ca.MODIFIED):
            main.RemoveSubModelPart("Contact")
        self.preprocess = not main.HasSubModelPart("Contact")
        if self.preprocess:
            main.CreateSubModelPart("Contact")
        self.contact_model_part = main.GetSubModelPart("Contact")
        if not main.HasSubModelPart("ComputingContact"):
            main.CreateSubModelPart("ComputingContact")
        self.computing_model_part = main.GetSubModelPart("ComputingContact")
        if self.preprocess:
            if not self.pairs:
                self._generate_skin_pair()
            for key in self.pairs:
                self._generate_pair(key)
        _core.FindNodalHProcess(main).Execute()
        self._check_normals()
        self._initialize_process_info()
        if not self.preprocess:
            _core.MasterSlaveProcess(self.contact_model_part).Execute()
        order = self.settings["integration_order"].GetInt()
        tessellation = self.settings["consider_tessellation"].GetBool()
        check_factor = self.search_settings["active_check_factor"].GetDouble()
        for properties in self._contact_properties():
            properties[ca.INTEGRATION_ORDER_CONTACT] = order
            properties[ca.CONSIDER_TESSELLATION] = tessellation
            properties[ca.ACTIVE_CHECK_FACTOR] = check_factor
        self._initialize_search_values()
        self._initialize_problem_parameters()
        for key in self.pairs:
            self.searches[key] = self._create_search(key)
        self._initialize_search_conditions()
        for search in self.searches.values():
            search.ExecuteInitialize()

    def _check_normals(self) -> None:
        """Flip the interface faces whose normal points into their own body, naming them.

        NormalCheckProcess rebuilds such a face with its node order reversed and marks it MARKER.
        The searches read MARKER on a face as "owned by another search" and would then work on a
        clone with a new id, leaving the flipped face twice in the Contact part: the mark is
        cleared again (a face marked before, by the search of another contact process, keeps it).
        """
        conditions = self.contact_model_part.Conditions
        marked = {condition.Id for condition in conditions if condition.Is(ca.MARKER)}
        check = _core.NormalCheckProcess(
            self.contact_model_part,
            length_proportion=self.settings["normal_check_proportion"].GetDouble(),
        )
        check.Execute()
        if check.NumberOfFlippedConditions() == 0:
            return
        flipped = []
        for condition in self.contact_model_part.Conditions:
            if condition.Is(ca.MARKER) and condition.Id not in marked:
                condition.Set(ca.MARKER, False)
                flipped.append(condition.Id)
        flipped_set = set(flipped)
        where = []
        for parts in self.interface_parts.values():
            for part in parts:
                ids = sorted(c.Id for c in part.Conditions if c.Id in flipped_set)
                if ids:
                    where.append(f"{part.FullName()}: {_id_list(ids)}")
        logger.warning(
            "%s: %d interface condition(s) had their normal pointing into their own body "
            "(inverted node order) and were flipped: %s",
            self.process_name,
            check.NumberOfFlippedConditions(),
            "; ".join(where) or _id_list(sorted(flipped)),
        )

    def _resume_from_restart(self) -> None:
        """After a restart: attach to the Contact parts, pairs and nodal values of the restart file.

        Nothing is recomputed (nodal sizes, normals, penalty, initial active set, flags and
        ProcessInfo values all come from the file, as the continuous run left them); only the C++
        searches are created again, on the restored pairs and INDEX_MAPs.
        """
        main = self.main_model_part
        for name in ("Contact", "ComputingContact"):
            if not main.HasSubModelPart(name):
                raise ca.InputError(
                    f'{self.process_name}: the restart file has no sub model part "{name}" in '
                    f"{main.FullName()}\n  fix: load a restart file written by a run with this "
                    "contact process"
                )
        self.preprocess = False
        self.contact_model_part = main.GetSubModelPart("Contact")
        self.computing_model_part = main.GetSubModelPart("ComputingContact")
        if not self.pairs:
            sub = self.contact_model_part.GetSubModelPart("ContactSub0")
            self.pairs = {"0": [sub.Name]}
            self.interface_parts = {"0": [sub]}
        root = main.GetRootModelPart()
        for key in self.pairs:
            self.pair_properties[key] = root.GetProperties(self.property_ids[key] or 100 + int(key))
            self.searches[key] = self._create_search(key, resume=True)
        # Without a saved state (SetRestartState): the counter of a run searching from step 1.
        step = int(main.ProcessInfo[ca.STEP])
        if step >= 1:
            self.database_step = (step - 1) % max(self.database_step_update, 1)
        # The searches mark the faces they own; the file holds the marks of the first run.
        ca.VariableUtils().SetFlag(ca.MARKER, False, self.contact_model_part.Conditions)
        for search in self.searches.values():
            search.ExecuteInitialize()
            search.penetration_checked = step >= 1

    def GetRestartState(self) -> dict[str, Any]:
        """The search counter and whether each search made its first-search penetration check."""
        return {
            "database_step": self.database_step,
            "penetration_checked": {k: s.penetration_checked for k, s in self.searches.items()},
        }

    def SetRestartState(self, state: dict[str, Any]) -> None:
        """Resume the counter and the checks of the saving run (after ``ExecuteInitialize``)."""
        self.database_step = int(state["database_step"])
        for key, checked in state["penetration_checked"].items():
            if key in self.searches:
                self.searches[key].penetration_checked = bool(checked)

    def ExecuteInitializeSolutionStep(self) -> None:
        """Search (or keep) the pairs of this step; outside the interval every pair is inactive."""
        if self._compute_search():
            contact_nodes = self.contact_model_part.Nodes
            ca.VariableUtils().SetFlag(ca.MARKER, False, contact_nodes)
            for search in self.searches.values():
                search.ExecuteInitializeSolutionStep()
            ca.VariableUtils().SetFlag(ca.MARKER, False, contact_nodes)
        elif not self._in_interval():
            utils = ca.VariableUtils()
            utils.SetFlag(ca.ACTIVE, False, self.contact_model_part.Nodes)
            utils.SetFlag(ca.ACTIVE, False, self.contact_model_part.Conditions)
            utils.SetFlag(ca.ACTIVE, False, self.computing_model_part.Conditions)

    def ExecuteFinalizeSolutionStep(self) -> None:
        """Let the searches release what they keep per step (pairs are reused when possible)."""
        if not self._in_interval() or self.main_model_part.Is(ca.MODIFIED):
            return
        step = self.main_model_part.ProcessInfo[ca.STEP]
        if self.database_step >= self.database_step_update or step == 1:
            for search in self.searches.values():
                search.ExecuteFinalizeSolutionStep()
            self.database_step = 0

    # -- hooks of the subclasses --

    def _initialize_process_info(self) -> None:
        info = self.main_model_part.ProcessInfo
        info[ca.ZERO_TOLERANCE_FACTOR] = self.settings["zero_tolerance_factor"].GetDouble()
        info[ca.ACTIVE_CHECK_FACTOR] = self.search_settings["active_check_factor"].GetDouble()

    def _initialize_search_values(self) -> None:
        self.main_model_part.ProcessInfo[ca.DISTANCE_THRESHOLD] = 1.0e24

    def _assign_friction_coefficients(self) -> None:
        """Set FRICTION_COEFFICIENT of each pair's properties (docs/running.md, Friction).

        ``friction_coefficients`` when positive, else the materials' value.
        """
        for key, properties in self.pair_properties.items():
            mu = self.settings["friction_coefficients"][key].GetDouble()
            if mu > 0.0 or not properties.Has(ca.FRICTION_COEFFICIENT):
                properties[ca.FRICTION_COEFFICIENT] = mu

    def _initialize_problem_parameters(self) -> None:
        """Penalty / scale factor and the like (ALM and penalty processes)."""

    def _initialize_search_conditions(self) -> None:
        """Nodal initial values before the first search (ALM: ALMFastInit)."""

    def _get_condition_name(self) -> str:
        """The condition stem, e.g. ``ALMFrictionlessMortarContact``."""
        return ""

    def _set_additional_parameters(self, settings: dict[str, Any]) -> None:
        """Extra search settings of a subclass (``pure_slip``)."""

    def _create_search_process(self, settings: Any, properties: Any, resume: bool) -> Any:
        return _core.ContactSearchProcess(self.main_model_part, settings, properties, resume)

    # -- helpers --

    def _in_interval(self) -> bool:
        return self.interval.IsInInterval(self.main_model_part.ProcessInfo[ca.TIME])

    def _compute_search(self) -> bool:
        if not self._in_interval():
            return False
        self.database_step += 1
        step = self.main_model_part.ProcessInfo[ca.STEP]
        return self.database_step >= self.database_step_update or step == 1

    def _contact_properties(self) -> list[Any]:
        return list(self.pair_properties.values())

    def _pair_property(self, key: str, sub: ca.ModelPart) -> Any:
        """Property of pair ``key``: the given id, or 100 + key copied from the body's material."""
        main = self.main_model_part
        given = self.property_ids[key]
        if given != 0:
            if not main.HasProperties(given):
                raise fail(
                    self.settings,
                    "search_property_ids",
                    f'pair "{key}" uses properties {given}, which do not exist',
                    "the id of properties of the main model part",
                )
            properties = main.GetProperties(given)
        else:
            properties = main.GetRootModelPart().CreateNewProperties(100 + int(key))
            source = None
            for part in self.interface_parts[key]:
                for condition in part.Conditions:
                    source = condition.Properties
                    break
                if source is not None:
                    break
            if source is None:
                for element in main.Elements:
                    source = element.Properties
                    break
            if source is not None:
                properties.CopyValuesFrom(source)
        sub.AddProperties(properties)
        return properties

    def _generate_pair(self, key: str) -> None:
        """ContactSub<key>: interface conditions, SLAVE / MASTER / INTERFACE flags, property."""
        utils = ca.VariableUtils()
        sub = self.contact_model_part.CreateSubModelPart(f"ContactSub{key}")
        parts = self.interface_parts[key]
        slaves = self.slave_parts.get(key, [])
        properties = self._pair_property(key, sub)
        self.pair_properties[key] = properties
        preprocess = _core.InterfacePreprocessCondition(self.main_model_part)
        for part in parts:
            if part.NumberOfConditions() == 0:
                logger.info(
                    "%s: generating the interface conditions of %s from its elements",
                    self.process_name,
                    part.FullName(),
                )
            preprocess.GenerateInterfacePart(
                part, simplify_geometry=False, contact_property_id=properties.Id
            )
            utils.SetFlag(ca.INTERFACE, True, part.Nodes)
            utils.SetFlag(ca.INTERFACE, True, part.Conditions)
        if slaves:
            for part in parts:
                for container in (part.Nodes, part.Conditions):
                    utils.SetFlag(ca.MASTER, True, container)
                    utils.SetFlag(ca.SLAVE, False, container)
            for slave in slaves:
                for container in (slave.Nodes, slave.Conditions):
                    utils.SetFlag(ca.SLAVE, True, container)
                    utils.SetFlag(ca.MASTER, False, container)
            # A generated face is slave when all its nodes are (the slave list names bodies).
            for part in parts:
                for condition in part.Conditions:
                    is_slave = all(node.Is(ca.SLAVE) for node in condition.GetGeometry())
                    condition.Set(ca.SLAVE, is_slave)
                    condition.Set(ca.MASTER, not is_slave)
        for part in parts:
            sub.AddNodes([node.Id for node in part.Nodes])
            sub.AddConditions([condition.Id for condition in part.Conditions])

    def _generate_skin_pair(self) -> None:
        """No interface given: the skin of the whole main model part is a self-contact interface."""
        sub = self.contact_model_part.CreateSubModelPart("ContactSub0")
        _core.InterfacePreprocessCondition(self.main_model_part).GenerateSkin(sub)
        self.pairs = {"0": [sub.Name]}
        self.interface_parts = {"0": [sub]}
        self.pair_properties["0"] = self._pair_property("0", sub)
        ca.VariableUtils().SetFlag(ca.INTERFACE, True, sub.Nodes)

    def _predefined(self, key: str) -> bool:
        return bool(self.slave_parts.get(key))

    def _get_final_string(self, key: str) -> str:
        """``"<n>N"`` when the master faces have another node count than the slave faces (3D)."""
        if self.dimension != 3:
            return ""
        sub = self.contact_model_part.GetSubModelPart(f"ContactSub{key}")
        slave_nodes = master_nodes = 0
        for condition in sub.Conditions:
            count = len(condition.GetGeometry())
            if not self._predefined(key):
                slave_nodes = master_nodes = count
                break
            if condition.Is(ca.SLAVE) and not slave_nodes:
                slave_nodes = count
            if condition.Is(ca.MASTER) and not master_nodes:
                master_nodes = count
            if slave_nodes and master_nodes:
                break
        return f"{master_nodes}N" if master_nodes and slave_nodes != master_nodes else ""

    def _search_settings_for(self, key: str) -> dict[str, Any]:
        values: dict[str, Any] = {
            **self.search_values,
            "condition_name": self._get_condition_name(),
            "final_string": self._get_final_string(key),
            "predefined_master_slave": self._predefined(key),
            "id_name": key,
        }
        self._set_additional_parameters(values)
        return values

    def _create_search(self, key: str, resume: bool = False) -> Any:
        settings = _core.ContactSearchSettings.from_dict(
            self._search_settings_for(key), self.search_settings.Where()
        )
        return self._create_search_process(settings, self.pair_properties[key], resume)
