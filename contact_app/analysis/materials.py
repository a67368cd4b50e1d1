"""Materials JSON (``*_materials.json``, Kratos ``ReadMaterialsUtility``).

::

    {"properties": [{
        "model_part_name": "Structure.Parts_plate",      # or the bare "Parts_plate" of old files
        "properties_id": 1,
        "Material": {
            "name": "steel",                              # informative
            "constitutive_law": {"name": "KratosMultiphysics.LinearElasticPlaneStrain2DLaw"},
            "Variables": {"YOUNG_MODULUS": 2.1e11, "KratosMultiphysics.POISSON_RATIO": 0.3},
            "Tables": {"t1": {"input_variable": "TEMPERATURE", "output_variable": "YOUNG_MODULUS",
                              "data": [[0.0, 2.1e11], [500.0, 1.5e11]]}}}}]}

Module prefixes before the last ``.`` of law and variable names are stripped. The value kind
follows the registered variable (number, integer, bool, 3-vector, vector, matrix, string). The
properties are set on every element **and** condition of the model part. The whole file is
validated by :class:`MaterialsReader` before the mesh is read; model part names are resolved when
:meth:`MaterialsReader.Apply` runs.

Every number must be finite and at most :data:`MAX_MAGNITUDE` in size, and the properties that a
law, element, load or contact process reads must lie in their physical range
(:data:`PROPERTY_RANGES`): a negative THICKNESS flips the sign of the response, a negative
FRICTION_COEFFICIENT turns friction off. :func:`CheckMeshProperties` applies the same table to the
properties the mesh file defined.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass, field
from typing import Any

import numpy as np

import contact_app as ca

from ..json_input import quote
from ..model_part_lookup import get_model_part
from ..parameters import Parameters, suggest
from ..setting_ranges import Range
from .validation import error, not_supported

logger = logging.getLogger("contact_app.analysis")

#: Largest magnitude of a material number: products of two such values (stiffness times
#: displacement, E·t·area) stay far inside the double range, and the pivots of the linear solver
#: are not lost in round-off (E = 1e300 ends as a singular factorisation).
MAX_MAGNITUDE = 1.0e30

#: Physical ranges of the properties read by laws, elements, loads and contact (bare names).
PROPERTY_RANGES: dict[str, Range] = {
    "YOUNG_MODULUS": Range(0.0, low_open=True, meaning="Young's modulus"),
    "POISSON_RATIO": Range(-1.0, 0.5, True, True, "Poisson's ratio"),
    "DENSITY": Range(0.0, meaning="a mass density"),
    "THICKNESS": Range(0.0, low_open=True, meaning="the thickness of plane or axisymmetric parts"),
    "FRICTION_COEFFICIENT": Range(0.0, meaning="a Coulomb friction coefficient μ"),
    "MASS_FACTOR": Range(0.0, meaning="a factor on the mass matrix"),
    "INTEGRATION_ORDER": Range(1.0, 5.0, meaning="a Gauss rule order"),
    "RAYLEIGH_ALPHA": Range(0.0, meaning="a damping coefficient"),
    "RAYLEIGH_BETA": Range(0.0, meaning="a damping coefficient"),
    "INITIAL_PENALTY": Range(0.0, meaning="a contact penalty"),
    "PENALTY_PARAMETER": Range(0.0, meaning="a contact penalty"),
    "SCALE_FACTOR": Range(0.0, low_open=True, meaning="a multiplier scale factor"),
    "TANGENT_FACTOR": Range(0.0, low_open=True, meaning="the stick penalty factor"),
}

_BLOCK_KEYS = {"model_part_name": "", "properties_id": 0, "Material": {}, "sub_properties": []}
_MATERIAL_KEYS = {"name": "", "constitutive_law": {}, "Variables": {}, "Tables": {}}
_TABLE_KEYS = {"input_variable": "", "output_variable": "", "data": []}


def strip_module_prefix(name: str) -> str:
    """``"KratosMultiphysics.YOUNG_MODULUS"`` → ``"YOUNG_MODULUS"``."""
    return name.rsplit(".", 1)[-1]


@dataclass
class _Table:
    input_variable: Any
    output_variable: Any
    rows: list[list[float]]


@dataclass
class _Block:
    """One validated entry of ``properties``."""

    settings: Parameters
    model_part_name: str
    properties_id: int
    law_name: str | None
    variables: list[tuple[Any, Any]] = field(default_factory=list)
    tables: list[_Table] = field(default_factory=list)


def _variable(settings: Parameters, key: str | None, name: str) -> Any:
    """Return the registered variable ``name`` (prefix stripped); InputError with a suggestion."""
    bare = strip_module_prefix(name)
    if bare not in ca.registered_variables():
        raise error(
            settings,
            key,
            f'unknown variable "{quote(name)}"',
            "a registered variable name (e.g. YOUNG_MODULUS, POISSON_RATIO, DENSITY, THICKNESS)",
            suggest(bare, ca.registered_variables()) or "check the spelling",
        )
    return ca.get_variable(bare)


def property_problem(name: str, values: Any) -> str | None:
    """Say what is wrong with the value(s) of the property ``name``, or None if they are valid."""
    numbers = np.asarray(values, dtype=float).ravel()
    if not np.all(np.isfinite(numbers)):
        return f"{name} is not finite; expected: a finite number"
    if numbers.size and np.max(np.abs(numbers)) > MAX_MAGNITUDE:
        return (
            f"{name} = {np.max(np.abs(numbers)):g} is beyond any physical value; expected: a "
            f"magnitude ≤ {MAX_MAGNITUDE:g} (check the units)"
        )
    allowed = PROPERTY_RANGES.get(name)
    if allowed is not None:
        bad = [v for v in numbers if not allowed.contains(float(v))]
        if bad:
            expected = f"{allowed.text()} ({allowed.meaning})"
            return f"{name} = {bad[0]:g} is out of range; expected: {expected}"
    return None


def _checked(settings: Parameters, key: str, variable: Any, value: Any) -> Any:
    """Return ``value`` after checking it against the range of its variable (located error)."""
    if isinstance(value, bool | str):
        return value
    problem = property_problem(variable.Name(), value)
    if problem is not None:
        what, _, expected = problem.partition("; expected: ")
        raise error(settings, key, what, expected, "correct the value in the materials file")
    return value


def _value(settings: Parameters, key: str, variable: Any) -> Any:
    """Convert the JSON value ``settings[key]`` to the kind of ``variable`` and check its range."""
    return _checked(settings, key, variable, _converted(settings, key, variable))


def _converted(settings: Parameters, key: str, variable: Any) -> Any:
    """Convert the JSON value ``settings[key]`` to the kind of ``variable``."""
    node = settings[key]
    if isinstance(variable, ca.BoolVariable):
        return node.GetBool()
    if isinstance(variable, ca.IntegerVariable):
        return node.GetInt()
    if isinstance(variable, ca.DoubleVariable):
        return node.GetDouble()
    if isinstance(variable, ca.StringVariable):
        return node.GetString()
    if isinstance(variable, ca.Array1DVariable3):
        values = node.GetVector()
        if len(values) != 3:
            raise error(settings, key, f"{key} has {len(values)} components", "3 numbers [x, y, z]")
        return np.array(values)
    if isinstance(variable, ca.VectorVariable):
        return np.array(node.GetVector())
    if isinstance(variable, ca.MatrixVariable):
        rows = node.GetMatrix()
        if len({len(row) for row in rows}) > 1:
            raise error(
                settings, key, f"{key} has rows of different lengths", "a rectangular matrix"
            )
        return np.array(rows)
    if isinstance(variable, ca.ConstitutiveLawVariable):
        raise error(
            settings,
            key,
            "CONSTITUTIVE_LAW is not a value",
            'the law in "Material" › "constitutive_law" › "name"',
            'move it to "constitutive_law": {"name": "..."}',
        )
    raise error(settings, key, f"{key} cannot be set from a materials file", "a value variable")


class MaterialsReader:
    """Validate a materials file, then assign its properties to a model.

    Args:
        filename: path of the materials JSON (already resolved).

    Raises:
        InputError: unreadable/malformed file, unknown key, law or variable, wrong value kind.
        ConfigurationError: ``sub_properties`` (not supported yet).

    """

    def __init__(self, filename: str):
        self.filename = filename
        self.parameters = Parameters.from_file(filename)
        self.blocks = self._ValidateFile()

    def _ValidateFile(self) -> list[_Block]:
        root = self.parameters
        if not root.IsSubParameter():
            raise error(
                root, None, "the materials file is not a JSON object", '{"properties": [ ... ]}'
            )
        root.ValidateAndAssignDefaults({"properties": []})
        return [self._ValidateBlock(block) for block in root["properties"]]

    def _ValidateBlock(self, block: Parameters) -> _Block:
        for key in ("model_part_name", "properties_id"):
            if not block.Has(key):
                raise error(block, key, f'missing required key "{key}"', f'"{key}" in every block')
        block.ValidateAndAssignDefaults(_BLOCK_KEYS)
        if block["sub_properties"].size():
            raise not_supported(
                block, "sub_properties", "sub_properties", "give each property its own block"
            )
        properties_id = block["properties_id"].GetInt()  # range: setting_ranges.py
        result = _Block(block, block["model_part_name"].GetString(), properties_id, None)
        material = block["Material"]
        material.ValidateAndAssignDefaults(_MATERIAL_KEYS)
        law = material["constitutive_law"]
        if law.size():
            law.ValidateAndAssignDefaults({"name": ""})
            result.law_name = self._LawName(law)
        variables = material["Variables"]
        for key in variables.keys():
            variable = _variable(variables, key, key)
            result.variables.append((variable, _value(variables, key, variable)))
        tables = material["Tables"]
        for key in tables.keys():
            result.tables.append(self._ValidateTable(tables[key]))
        return result

    @staticmethod
    def _LawName(law: Parameters) -> str:
        written = law["name"].GetString()
        name = strip_module_prefix(written)
        known = ca.registered_constitutive_laws()
        if name not in known:
            raise error(
                law,
                "name",
                f'unknown constitutive law "{quote(written)}"',
                "one of " + ", ".join(known),
                suggest(name, known) or "use one of the registered laws above",
            )
        return name

    @staticmethod
    def _ValidateTable(table: Parameters) -> _Table:
        table.ValidateAndAssignDefaults(_TABLE_KEYS)
        variables = []
        for key in ("input_variable", "output_variable"):
            variable = _variable(table, key, table[key].GetString())
            if not isinstance(variable, ca.DoubleVariable):
                raise error(
                    table,
                    key,
                    f"{table[key].GetString()} is not a scalar variable",
                    "a double variable",
                )
            variables.append(variable)
        rows = table["data"].GetMatrix()
        if not rows or any(len(row) != 2 for row in rows):
            raise error(
                table, "data", "table data must be rows of two numbers", "[[x0, y0], [x1, y1], ...]"
            )
        _checked(table, "data", variables[0], [row[0] for row in rows])
        _checked(table, "data", variables[1], [row[1] for row in rows])
        return _Table(variables[0], variables[1], rows)

    def Apply(self, model: ca.Model) -> None:
        """Create every properties (first pass), then assign them to elements and conditions.

        Raises:
            InputError: a model part name that does not resolve (with a suggestion).

        """
        created = []
        for block in self.blocks:
            where = block.settings.Where("model_part_name")
            part = get_model_part(model, block.model_part_name, where)
            created.append((part, self._CreateProperties(part, block)))
        owner: dict[tuple[str, int], int] = {}
        for part, properties in created:
            self._Assign(part, properties, owner)

    @staticmethod
    def _CreateProperties(part: ca.ModelPart, block: _Block) -> ca.Properties:
        root = part.GetRootModelPart()
        if root.HasProperties(block.properties_id):
            properties = root.GetProperties(block.properties_id)
            if not part.HasProperties(block.properties_id):
                part.AddProperties(properties)
        else:
            properties = part.CreateNewProperties(block.properties_id)
        overwritten = [v.Name() for v, _ in block.variables if properties.Has(v)]
        if overwritten:
            logger.warning(
                "properties %d: %s already set (mdpa or an earlier block); overwritten by %s",
                block.properties_id,
                ", ".join(overwritten),
                block.settings.Where(),
            )
        for variable, value in block.variables:
            properties.SetValue(variable, value)
        for table in block.tables:
            values = ca.Table()
            for x, y in table.rows:
                values.AddRow(x, y)
            properties.SetTable(table.input_variable, table.output_variable, values)
        if block.law_name is not None:
            properties.SetValue(ca.CONSTITUTIVE_LAW, ca.create_constitutive_law(block.law_name))
        return properties

    @staticmethod
    def _Assign(
        part: ca.ModelPart, properties: ca.Properties, owner: dict[tuple[str, int], int]
    ) -> None:
        reassigned = 0
        for kind, entities in (("element", part.Elements), ("condition", part.Conditions)):
            for entity in entities:
                previous = owner.setdefault((kind, entity.Id), properties.Id)
                if previous != properties.Id:
                    reassigned += 1
                    owner[(kind, entity.Id)] = properties.Id
                entity.Properties = properties
        if reassigned:
            logger.warning(
                "%d entities of %s received properties %d after another materials block had set "
                "theirs; the last block wins",
                reassigned,
                part.FullName(),
                properties.Id,
            )


def CheckMeshProperties(model_part: ca.ModelPart, mesh: str) -> None:
    """Check the properties of ``model_part`` (those of the mesh file) against the same ranges.

    Raises:
        InputError: a property out of range, naming the properties id and the mesh file.

    """
    for properties in model_part.GetRootModelPart().Properties:
        for name in PROPERTY_RANGES:
            variable = ca.get_variable(name) if name in ca.registered_variables() else None
            if variable is None or not properties.Has(variable):
                continue
            problem = property_problem(name, properties.GetValue(variable))
            if problem is not None:
                what, _, expected = problem.partition("; expected: ")
                raise ca.InputError(
                    f"{what}\n  where:    properties {properties.Id} of the mesh {mesh}\n"
                    f"  expected: {expected}\n"
                    "  fix:      correct it in the Begin Properties block of the mesh, or set it "
                    "in the materials file"
                )


def ReadMaterials(model: ca.Model, filename: str) -> MaterialsReader:
    """Validate ``filename`` and apply it to ``model`` (Kratos ``ReadMaterialsUtility``)."""
    reader = MaterialsReader(filename)
    reader.Apply(model)
    return reader
