"""Read any mesh meshio reads (gmsh ``.msh`` first) into a model part.

Selected by ``model_import_settings.input_type: "meshio"`` (or by an ``input_filename`` whose
extension is not ``.mdpa``). The ``mesh_mapping`` block says what the cells become::

    "model_import_settings": {
        "input_type": "meshio",
        "input_filename": "hertz_2d.msh",
        "mesh_mapping": {
            "elements":   {"triangle": "SmallDisplacementElement2D3N"},
            "conditions": {"line": "LineCondition2D2N"},
            "sub_model_parts": {"cylinder": "Cylinder", "contact_top": "Contact_Top"},
            "ignore_cell_types": ["vertex"],
            "properties_id": 0
        }
    }

* ``elements`` / ``conditions``: meshio cell type (``line``, ``triangle``, ``quad``, ``tetra``,
  ``hexahedron``, …) → registered element / condition name. Every cell of a mapped type becomes
  one entity; ids follow the file order, elements and conditions numbered separately from 1.
* ``sub_model_parts``: physical group (gmsh) or cell set name → sub model part name. A group not
  listed keeps its own name; ``{}`` (the default) maps every group to a part of the same name.
  A part receives the group's entities and their nodes (a group of ``vertex`` cells: nodes only).
* ``ignore_cell_types``: cell types dropped silently (default ``["vertex"]``); any other unmapped
  type is an error, so no cell is lost without saying so.
* ``properties_id``: the properties of every entity (the materials file assigns them per part).

Points keep their 3 coordinates (2D meshes from gmsh have z = 0). Node ids are the point index
+ 1. Errors say which key, which cell type or group, and what was expected.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path
from typing import Any

import numpy as np

from .. import _core
from .._core import InputError
from ..parameters import suggest

#: Node count of the meshio cell types a mapping may name (linear and quadratic families).
CELL_NODES = {
    "vertex": 1,
    "line": 2,
    "line3": 3,
    "triangle": 3,
    "triangle6": 6,
    "quad": 4,
    "quad8": 8,
    "quad9": 9,
    "tetra": 4,
    "tetra10": 10,
    "hexahedron": 8,
    "hexahedron20": 20,
    "hexahedron27": 27,
    "wedge": 6,
    "pyramid": 5,
}

MAPPING_DEFAULTS: dict[str, Any] = {
    "elements": {},
    "conditions": {},
    "sub_model_parts": {},
    "ignore_cell_types": ["vertex"],
    "properties_id": 0,
}


def _fail(what: str, where: str, expected: str, fix: str = "") -> InputError:
    message = f"{what}\n  where:    {where}\n  expected: {expected}"
    return InputError(message + (f"\n  fix:      {fix}" if fix else ""))


def _check_names(mapping: dict[str, str], registered: Iterable[str], kind: str, where: str) -> None:
    known = set(registered)
    for cell_type, name in mapping.items():
        if cell_type not in CELL_NODES:
            raise _fail(
                f'unknown meshio cell type "{cell_type}" in mesh_mapping.{kind}',
                where,
                "one of " + ", ".join(sorted(CELL_NODES)),
            )
        if name not in known:
            raise _fail(
                f'"{name}" (for {cell_type} cells) is not a registered {kind[:-1]}',
                where,
                f"a registered {kind[:-1]} name",
                suggest(name, sorted(known)) or f"see contact_app.registered_{kind}()",
            )
        digits = "".join(ch for ch in name.rsplit("D", 1)[-1] if ch.isdigit())
        if digits and int(digits) != CELL_NODES[cell_type]:
            raise _fail(
                f'"{name}" has {digits} nodes but {cell_type} cells have {CELL_NODES[cell_type]}',
                where,
                f"a {kind[:-1]} with {CELL_NODES[cell_type]} nodes",
            )


def read_mesh(path: str | Path) -> Any:
    """``meshio.read`` with the file name in the error message."""
    import meshio

    try:
        return meshio.read(str(path))
    except (Exception, SystemExit) as failure:  # meshio raises many kinds, and sys.exit()s on some
        raise InputError(
            f"cannot read the mesh {path}: {failure}\n"
            "  expected: a mesh file meshio understands (gmsh .msh, .vtu, .inp, .med, ...)"
        ) from failure


#: Topological dimension of the meshio cell types (gmsh physical groups carry a dimension).
CELL_DIMENSION = {
    "vertex": 0,
    "line": 1,
    "line3": 1,
    "triangle": 2,
    "triangle6": 2,
    "quad": 2,
    "quad8": 2,
    "quad9": 2,
}


def _dimension(cell_type: str) -> int:
    return CELL_DIMENSION.get(cell_type, 3)


def _groups(mesh: Any) -> dict[str, dict[str, list[int]]]:
    """Group name → {cell type: indices among all cells of that type, in file order}.

    Cell sets (``cell_sets_dict``) are used as meshio gives them; gmsh physical groups are rebuilt
    from ``field_data`` (name → [tag, dimension]) and the ``gmsh:physical`` cell data, because
    meshio's gmsh reader does not turn them into cell sets.
    """
    groups: dict[str, dict[str, list[int]]] = {}
    for name, per_type in getattr(mesh, "cell_sets_dict", {}).items():
        if not name.startswith("gmsh:"):
            groups[name] = {t: [int(i) for i in indices] for t, indices in per_type.items()}
    physical = mesh.cell_data.get("gmsh:physical")
    if physical is None:
        return groups
    offsets: dict[str, int] = {}
    by_tag: dict[tuple[int, int], dict[str, list[int]]] = {}
    for block, tags in zip(mesh.cells, physical, strict=True):
        start = offsets.get(block.type, 0)
        for local, tag in enumerate(tags):
            key = (int(tag), _dimension(block.type))
            by_tag.setdefault(key, {}).setdefault(block.type, []).append(start + local)
        offsets[block.type] = start + len(block.data)
    for name, (tag, dimension) in ((n, v[:2]) for n, v in mesh.field_data.items()):
        cells = by_tag.get((int(tag), int(dimension)))
        if cells is not None and name not in groups:
            groups[name] = cells
    return groups


def ImportMeshioModelPart(
    model_part: Any, path: str | Path, mapping: dict[str, Any], where: str
) -> None:
    """Fill ``model_part`` (empty, variables declared) from the mesh at ``path``.

    Args:
        model_part: the root model part to fill.
        path: the mesh file.
        mapping: the ``mesh_mapping`` block as a dict (defaults are added here).
        where: the location of ``mesh_mapping`` in the settings, for messages.

    Raises:
        InputError: unreadable file, unknown key, unknown cell type or entity name, a node-count
            mismatch, an unmapped cell type, a group in ``sub_model_parts`` that the file lacks.
    """
    for key in mapping:
        if key not in MAPPING_DEFAULTS:
            raise _fail(
                f'unknown key "{key}" in mesh_mapping',
                where,
                "one of " + ", ".join(MAPPING_DEFAULTS),
                suggest(key, list(MAPPING_DEFAULTS)),
            )
    settings = {**MAPPING_DEFAULTS, **mapping}
    elements: dict[str, str] = dict(settings["elements"])
    conditions: dict[str, str] = dict(settings["conditions"])
    ignored = set(settings["ignore_cell_types"])
    _check_names(elements, _core.registered_elements(), "elements", where)
    _check_names(conditions, _core.registered_conditions(), "conditions", where)
    both = set(elements) & set(conditions)
    if both:
        raise _fail(
            f"cell type(s) {sorted(both)} mapped to both an element and a condition",
            where,
            "each cell type in one of the two maps",
        )

    mesh = read_mesh(path)
    present = [block.type for block in mesh.cells]
    for cell_type in present:
        if cell_type not in elements and cell_type not in conditions and cell_type not in ignored:
            raise _fail(
                f'{Path(path).name} has "{cell_type}" cells that mesh_mapping does not map',
                where,
                f'"{cell_type}" in "elements", "conditions" or "ignore_cell_types"',
            )
    for cell_type in list(elements) + list(conditions):
        if cell_type not in present:
            raise _fail(
                f'mesh_mapping maps "{cell_type}" cells but {Path(path).name} has none',
                where,
                "cell types present in the file: " + ", ".join(sorted(set(present))),
            )

    points = mesh.points
    for index in range(points.shape[0]):
        x = points[index]
        model_part.CreateNewNode(
            index + 1, float(x[0]), float(x[1]), float(x[2]) if x.shape[0] > 2 else 0.0
        )
    properties_id = int(settings["properties_id"])
    properties = (
        model_part.GetProperties(properties_id)
        if model_part.HasProperties(properties_id)
        else model_part.CreateNewProperties(properties_id)
    )

    # Entity ids per (cell type, index within the type), in file order.
    entity_ids: dict[str, list[int]] = {}
    next_element = next_condition = 1
    for block in mesh.cells:
        cell_type = block.type
        if cell_type in ignored and cell_type not in elements and cell_type not in conditions:
            continue
        is_element = cell_type in elements
        name = elements[cell_type] if is_element else conditions[cell_type]
        ids = entity_ids.setdefault(cell_type, [])
        for connectivity in block.data:
            nodes = [int(n) + 1 for n in connectivity]
            if is_element:
                model_part.CreateNewElement(name, next_element, nodes, properties)
                ids.append(next_element)
                next_element += 1
            else:
                model_part.CreateNewCondition(name, next_condition, nodes, properties)
                ids.append(next_condition)
                next_condition += 1

    groups = _groups(mesh)
    renames: dict[str, str] = dict(settings["sub_model_parts"])
    for group in renames:
        if group not in groups:
            raise _fail(
                f'mesh_mapping.sub_model_parts names the group "{group}", which '
                f"{Path(path).name} does not have",
                where,
                "one of " + (", ".join(sorted(groups)) or "(the file has no physical groups)"),
            )
    # Type-local indices → connectivities, to collect the nodes of each group.
    blocks_by_type: dict[str, list[Any]] = {}
    for block in mesh.cells:
        blocks_by_type.setdefault(block.type, []).append(block.data)
    for group, per_type in groups.items():
        part = model_part.CreateSubModelPart(renames.get(group, group))
        node_ids: set[int] = set()
        element_ids: list[int] = []
        condition_ids: list[int] = []
        for cell_type, indices in per_type.items():
            if not len(indices):
                continue
            data = np.concatenate(blocks_by_type[cell_type])
            for index in indices:
                node_ids.update(int(n) + 1 for n in data[index])
            if cell_type in elements:
                element_ids.extend(entity_ids[cell_type][i] for i in indices)
            elif cell_type in conditions:
                condition_ids.extend(entity_ids[cell_type][i] for i in indices)
        part.AddNodes(sorted(node_ids))
        if element_ids:
            part.AddElements(element_ids)
        if condition_ids:
            part.AddConditions(condition_ids)
