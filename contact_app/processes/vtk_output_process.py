"""``vtk_output_process``.

One ``.vtu`` file per output step (written with meshio) and a ``.pvd`` collection that lists them
with their TIME, for ParaView.

Keys (Kratos ``vtk_output``; defaults in brackets):

* ``model_part_name`` (required); ``output_sub_model_parts`` [false]: also write every direct sub
  model part that has nodes, each to its own files and collection.
* ``output_control_type`` ["step"] or "time"; ``output_interval`` [1.0]: steps or time between
  outputs (0 = every step). The first output is the first step; after each output the next one is
  moved on by the interval until it lies beyond the current step/time (times compared at 12
  significant digits).
* ``file_format`` ["binary"] or "ascii"; ``output_precision`` [7]: significant digits of the ascii
  values (binary files store full doubles).
* ``output_path`` ["VTK_Output"] with ``save_output_files_in_folder`` [true] (false writes into the
  working directory); ``custom_name_prefix``/``custom_name_postfix`` [""]. Files are named
  ``<prefix><Model_Part_Path>_0_<step or time><postfix>.vtu`` and
  ``<prefix><Model_Part_Path><postfix>.pvd``. ``ExecuteInitialize`` deletes earlier files of
  exactly this naming pattern (Kratos deletes the whole folder; we never delete other files).
* ``entity_type`` ["automatic": elements if the part has any, else conditions], "element" or
  "condition": which entities become cells. A part with neither is written as vertex cells.
* ``write_deformed_configuration`` [false]: points at current instead of initial coordinates;
  ``write_ids`` [false]: ``KRATOS_NODE_ID`` and ``KRATOS_ELEMENT_ID``/``KRATOS_CONDITION_ID``.
* Point data: ``nodal_solution_step_data_variables`` (historical), ``nodal_data_value_variables``
  (non-historical), ``nodal_flags`` (1.0/0.0), ``gauss_point_variables_extrapolated_to_nodes``
  (integration-point values extrapolated to the nodes of each cell — exactly when the cell has as
  many points as nodes, as a constant otherwise — then averaged over the cells of each node).
* Cell data: ``element_data_value_variables``/``element_flags`` when the cells are elements,
  ``condition_data_value_variables``/``condition_flags`` when they are conditions (the other pair is
  ignored with a warning), ``gauss_point_variables_in_elements`` (mean over the integration points).

Legacy keys ``output_frequency`` (→ ``output_interval``) and ``folder_name`` (→ ``output_path``) are
converted with a warning. 3-vectors have 3 components, Vectors their length, matrices are
flattened row by row.
"""

from __future__ import annotations

import contextlib
import glob
import io
import logging
import os
from pathlib import Path
from typing import Any
from xml.sax.saxutils import quoteattr

import meshio
import numpy as np

from .. import _core
from .._core import InputError, Model
from ..launch_rank import is_output_rank
from ..legacy_keys import convert_legacy_keys
from ..parameters import Parameters
from ._utilities import check_historical, get_flag, get_variable, model_part_of, validate
from .process import OutputProcess

LOGGER = logging.getLogger(__name__)

DEFAULTS: dict[str, Any] = {
    "model_part_name": "",
    "file_format": "binary",
    "output_precision": 7,
    "output_control_type": "step",
    "output_interval": 1.0,
    "output_sub_model_parts": False,
    "output_path": "VTK_Output",
    "custom_name_prefix": "",
    "custom_name_postfix": "",
    "save_output_files_in_folder": True,
    "entity_type": "automatic",
    "write_deformed_configuration": False,
    "write_ids": False,
    "nodal_solution_step_data_variables": [],
    "nodal_data_value_variables": [],
    "nodal_flags": [],
    "element_data_value_variables": [],
    "element_flags": [],
    "condition_data_value_variables": [],
    "condition_flags": [],
    "gauss_point_variables_extrapolated_to_nodes": [],
    "gauss_point_variables_in_elements": [],
}

#: Kratos geometry name -> meshio cell type (node orderings agree for these).
CELL_TYPES = {
    "Point2D": "vertex",
    "Point3D": "vertex",
    "Line2D2": "line",
    "Line3D2": "line",
    "Line2D3": "line3",
    "Line3D3": "line3",
    "Triangle2D3": "triangle",
    "Triangle3D3": "triangle",
    "Triangle2D6": "triangle6",
    "Triangle3D6": "triangle6",
    "Quadrilateral2D4": "quad",
    "Quadrilateral3D4": "quad",
    "Tetrahedra3D4": "tetra",
    "Tetrahedra3D10": "tetra10",
    "Hexahedra3D8": "hexahedron",
    "Prism3D6": "wedge",
}
VALUE_KINDS = ("Double", "Component", "Array", "Vector", "Matrix", "Integer", "Bool")
GAUSS_KINDS = ("Double", "Array", "Vector", "Matrix")


def Factory(settings: Parameters, model: Model) -> OutputProcess:
    """Create the process from its descriptor (``settings["Parameters"]`` configures it)."""
    return VtkOutputProcess(model, settings["Parameters"])


class VtkOutputProcess(OutputProcess):
    """Write VTK unstructured-grid files and a ParaView collection.

    Args:
        model: the model holding the model part.
        settings: the ``Parameters`` block.

    Raises:
        InputError: unknown key, model part, variable or flag; a bad enum value; both a legacy key
            and its replacement.
    """

    def __init__(self, model: Model, settings: Parameters) -> None:
        convert_legacy_keys(settings, "vtk_output_process")  # output_frequency, folder_name
        validate(settings, DEFAULTS, ("model_part_name",), "vtk_output_process")
        self.model_part = model_part_of(model, settings)
        self.binary = _choice(settings, "file_format", ("binary", "ascii")) == "binary"
        self.precision = settings["output_precision"].GetInt()
        self.control = _choice(settings, "output_control_type", ("step", "time"))
        self.interval = settings["output_interval"].GetDouble()
        self.entity_type = _choice(settings, "entity_type", ("automatic", "element", "condition"))
        self.deformed = settings["write_deformed_configuration"].GetBool()
        self.write_ids = settings["write_ids"].GetBool()
        self.folder = (
            Path(settings["output_path"].GetString())
            if settings["save_output_files_in_folder"].GetBool()
            else Path()
        )
        self.prefix = settings["custom_name_prefix"].GetString()
        self.postfix = settings["custom_name_postfix"].GetString()
        self.parts = [self.model_part]
        if settings["output_sub_model_parts"].GetBool():
            self.parts += [p for p in self.model_part.SubModelParts if p.NumberOfNodes() > 0]

        def variables(key: str, kinds: tuple[str, ...]) -> list[Any]:
            where = settings.Where(key)
            return [get_variable(n, where, kinds) for n in settings[key].GetStringArray()]

        def flags(key: str) -> list[tuple[str, Any]]:
            where = settings.Where(key)
            return [(n, get_flag(n, where)) for n in settings[key].GetStringArray()]

        self.nodal_historical = variables(
            "nodal_solution_step_data_variables", ("Double", "Component", "Array")
        )
        for variable in self.nodal_historical:
            check_historical(
                self.model_part,
                variable,
                settings.Where("nodal_solution_step_data_variables"),
                "list it under nodal_data_value_variables (non-historical values)",
            )
        self.nodal_values = variables("nodal_data_value_variables", VALUE_KINDS)
        self.nodal_flags = flags("nodal_flags")
        self.extrapolated = variables("gauss_point_variables_extrapolated_to_nodes", GAUSS_KINDS)
        self.cell_values = {
            "element": variables("element_data_value_variables", VALUE_KINDS),
            "condition": variables("condition_data_value_variables", VALUE_KINDS),
        }
        self.cell_flags = {"element": flags("element_flags"), "condition": flags("condition_flags")}
        self.in_cells = variables("gauss_point_variables_in_elements", GAUSS_KINDS)
        _refuse_duplicates(
            settings,
            [v.Name() for v in self.nodal_historical + self.nodal_values + self.extrapolated]
            + [name for name, _ in self.nodal_flags],
            "point data",
        )
        process_info = self.model_part.ProcessInfo
        self.next_output: float = float(
            process_info[_core.TIME] if self.control == "time" else process_info[_core.STEP]
        )
        self.collections: dict[str, list[tuple[float, str]]] = {}
        self._warned: set[str] = set()

    # -- life cycle --

    def ExecuteInitialize(self) -> None:
        """Delete files of earlier runs that follow this process' naming pattern.

        After a restart (ProcessInfo IS_RESTARTED) the files up to the restart TIME are kept and
        the collection goes on from them; later files of the interrupted run are deleted. Only the
        writing MPI rank touches the files (launch_rank.py).
        """
        if not is_output_rank():
            return
        process_info = self.model_part.ProcessInfo
        if process_info[_core.IS_RESTARTED]:
            self._resume(float(process_info[_core.TIME]))
            return
        for part in self.parts:
            stem = self._stem(part)
            pattern = (
                glob.escape(str(self.folder / f"{stem}_0_"))
                + "*"
                + glob.escape(f"{self.postfix}.vtu")
            )
            for path in glob.glob(pattern):
                os.remove(path)
            pvd = self.folder / f"{stem}{self.postfix}.pvd"
            if pvd.exists():
                pvd.unlink()

    def _resume(self, time: float) -> None:
        current = time if self.control == "time" else float(self.model_part.ProcessInfo[_core.STEP])
        if (
            self.interval > 0.0
        ):  # the schedule of a run that started from 0 and printed on its multiples
            self.next_output = 0.0
            while _round(self.next_output) <= _round(current):
                self.next_output += self.interval
        for part in self.parts:
            stem = self._stem(part)
            pvd = self.folder / f"{stem}{self.postfix}.pvd"
            entries = _read_pvd(pvd)
            kept = [e for e in entries if _round(e[0]) <= _round(time)]
            for entry_time, name in entries:
                if _round(entry_time) > _round(time) and (self.folder / name).is_file():
                    os.remove(self.folder / name)
            self.collections[stem] = kept
            if entries:
                _write_pvd(pvd, kept)

    def GetRestartState(self) -> dict[str, Any]:
        """The next output TIME (STEP) of the schedule."""
        return {"next_output": self.next_output}

    def SetRestartState(self, state: dict[str, Any]) -> None:
        """Resume the saving run's schedule (``_resume`` only rebuilds one that started at 0)."""
        self.next_output = float(state["next_output"])

    def IsOutputStep(self) -> bool:
        """True if the current step/time has reached the next output."""
        process_info = self.model_part.ProcessInfo
        if self.control == "time":
            return _round(process_info[_core.TIME]) >= _round(self.next_output)
        return process_info[_core.STEP] >= self.next_output

    def PrintOutput(self) -> None:
        """Write the current state of every part and update the collections."""
        process_info = self.model_part.ProcessInfo
        time = float(process_info[_core.TIME])
        step = int(process_info[_core.STEP])
        label = f"{time:.{self.precision}g}" if self.control == "time" else str(step)
        self.folder.mkdir(parents=True, exist_ok=True)
        for part in self.parts:
            stem = self._stem(part)
            name = f"{stem}_0_{label}{self.postfix}.vtu"
            self._write(part, self.folder / name)
            entries = [e for e in self.collections.setdefault(stem, []) if e[1] != name]
            entries.append((time, name))
            self.collections[stem] = entries
            _write_pvd(self.folder / f"{stem}{self.postfix}.pvd", entries)
        if self.interval > 0.0:
            current = time if self.control == "time" else float(step)
            while _round(self.next_output) <= _round(current):
                self.next_output += self.interval

    # -- writing --

    def _stem(self, part: Any) -> str:
        return self.prefix + part.FullName().replace(".", "_")

    def _write(self, part: Any, path: Path) -> None:
        if self.extrapolated:  # extrapolation works entity by entity
            points, blocks, point_data, cell_data = self._gather_per_entity(part)
        else:
            points, blocks, point_data, cell_data = self._gather_bulk(part)
        if not self.binary:
            points = _round_significant(points, self.precision)
            point_data = {k: _round_significant(v, self.precision) for k, v in point_data.items()}
            cell_data = {
                k: [_round_significant(v, self.precision) for v in blocks_data]
                for k, blocks_data in cell_data.items()
            }
        mesh = meshio.Mesh(points, blocks, point_data=point_data, cell_data=cell_data)
        with contextlib.redirect_stderr(io.StringIO()):  # meshio warns about ascii on stderr
            meshio.write(path, mesh, file_format="vtu", binary=self.binary)

    def _gather_bulk(self, part: Any) -> tuple[Any, ...]:
        """Points, cell blocks, point and cell data from whole-part arrays of ``_core``.

        The same arrays, in the same order, as :meth:`_gather_per_entity`: the part's nodes, then
        the other nodes of its cells in the order they first appear; cells grouped by type in the
        order the types first appear.
        """
        kind = self._kind(part)
        elements = kind == "element"
        root = part.GetRootModelPart()
        ids = _core.BulkNodeIds(part)
        entity_ids, codes, names, connectivity, offsets = _core.BulkEntities(part, elements)
        extra = connectivity[~np.isin(connectivity, ids)]
        if extra.size:
            unique, first = np.unique(extra, return_index=True)
            ids = np.concatenate([ids, unique[np.argsort(first)]])
        order = np.argsort(ids, kind="stable")
        positions = order[np.searchsorted(ids[order], connectivity)]
        points = _core.BulkNodalCoordinates(root, ids, not self.deformed)
        blocks: list[tuple[str, np.ndarray]] = []
        members: list[np.ndarray] = []
        types = [
            _cell_type(name, part, entity_ids[np.argmax(codes == c)])
            for c, name in enumerate(names)
        ]
        block_of_type = {t: i for i, t in enumerate(dict.fromkeys(types))}
        block_of_code = np.array([block_of_type[t] for t in types], dtype=np.int64)
        entity_block = block_of_code[codes] if codes.size else codes
        for cell_type, block in block_of_type.items():
            chosen = np.flatnonzero(entity_block == block)
            width = int(offsets[chosen[0] + 1] - offsets[chosen[0]])
            nodes = positions[offsets[chosen][:, None] + np.arange(width)]
            blocks.append((cell_type, nodes.astype(np.int64)))
            members.append(chosen)
        if not blocks:  # nodes only: vertex cells, so the file is valid and visible
            blocks = [("vertex", np.arange(len(ids)).reshape(-1, 1))]
            kind = "node"
        point_data: dict[str, np.ndarray] = {}
        for variable in self.nodal_historical:
            point_data[variable.Name()] = _rows(*_core.BulkNodalValues(root, ids, variable, True))
        for variable in self.nodal_values:
            point_data[variable.Name()] = _rows(*_core.BulkNodalValues(root, ids, variable, False))
        for name, flag in self.nodal_flags:
            point_data[name] = _core.BulkNodalFlags(root, ids, flag)
        if self.write_ids:
            point_data["KRATOS_NODE_ID"] = ids.astype(np.int64)
        cell_data: dict[str, list[np.ndarray]] = {}
        if kind != "node":
            for variable in self.cell_values[kind]:
                values, sizes = _core.BulkEntityValues(part, elements, variable)
                cell_data[variable.Name()] = _rows_per_block(values, sizes, members)
            for name, flag in self.cell_flags[kind]:
                flags = _core.BulkEntityFlags(part, elements, flag)
                cell_data[name] = [flags[chosen] for chosen in members]
            for variable in self.in_cells:
                means, sizes = _integration_point_means(
                    *_core.BulkIntegrationPointValues(part, elements, variable, part.ProcessInfo)
                )
                cell_data[variable.Name()] = _rows_per_block(means, sizes, members)
            if self.write_ids:
                cell_data[f"KRATOS_{kind.upper()}_ID"] = [entity_ids[c] for c in members]
        return points, blocks, point_data, cell_data

    def _gather_per_entity(self, part: Any) -> tuple[Any, ...]:
        """Points, cell blocks, point and cell data from the nodes and entities one by one."""
        nodes = list(part.Nodes)
        kind, entities = self._entities(part)
        index = {node.Id: i for i, node in enumerate(nodes)}
        for entity in entities:
            for node in entity.GetNodes():
                if node.Id not in index:
                    index[node.Id] = len(nodes)
                    nodes.append(node)
        points = np.array(
            [(n.X, n.Y, n.Z) if self.deformed else (n.X0, n.Y0, n.Z0) for n in nodes], dtype=float
        ).reshape(-1, 3)
        blocks = _cell_blocks(entities, index, part)
        if not blocks:  # nodes only: vertex cells, so the file is valid and visible
            blocks = [("vertex", np.arange(len(nodes)).reshape(-1, 1), nodes)]
            kind = "node"
        point_data = self._point_data(part, nodes, kind, entities, index)
        cell_data = self._cell_data(part, kind, blocks)
        return points, [(t, c) for t, c, _ in blocks], point_data, cell_data

    def _entities(self, part: Any) -> tuple[str, list[Any]]:
        kind = self._kind(part)
        return kind, list(part.Elements if kind == "element" else part.Conditions)

    def _kind(self, part: Any) -> str:
        """What the cells of ``part`` are: "element" or "condition" (warns once about the other)."""
        kind = self.entity_type
        if kind == "automatic":
            kind = "element" if part.NumberOfElements() > 0 else "condition"
        other = "condition" if kind == "element" else "element"
        if (self.cell_values[other] or self.cell_flags[other]) and other not in self._warned:
            self._warned.add(other)
            LOGGER.warning(
                'vtk_output_process: the cells of "%s" are %ss, so %s_data_value_variables and '
                '%s_flags are not written (set entity_type to "%s" to write them)',
                part.FullName(),
                kind,
                other,
                other,
                other,
            )
        return kind

    def _point_data(
        self, part: Any, nodes: list[Any], kind: str, entities: list[Any], index: dict[int, int]
    ) -> dict[str, np.ndarray]:
        data: dict[str, np.ndarray] = {}
        for variable in self.nodal_historical:
            data[variable.Name()] = _stack([n.GetSolutionStepValue(variable) for n in nodes])
        for variable in self.nodal_values:
            data[variable.Name()] = _stack([n.GetValue(variable) for n in nodes])
        for name, flag in self.nodal_flags:
            data[name] = np.array([1.0 if n.Is(flag) else 0.0 for n in nodes])
        if self.write_ids:
            data["KRATOS_NODE_ID"] = np.array([n.Id for n in nodes], dtype=np.int64)
        if self.extrapolated:
            usable = entities if kind in ("element", "condition") else []
            process_info = part.ProcessInfo
            for variable in self.extrapolated:
                data[variable.Name()] = _extrapolate(
                    usable, variable, process_info, index, len(nodes)
                )
        return data

    def _cell_data(
        self, part: Any, kind: str, blocks: list[tuple[str, np.ndarray, list[Any]]]
    ) -> dict[str, list[np.ndarray]]:
        data: dict[str, list[np.ndarray]] = {}
        if kind == "node":
            return data
        process_info = part.ProcessInfo
        for variable in self.cell_values[kind]:
            data[variable.Name()] = _per_block(blocks, lambda e, v=variable: e.GetValue(v))
        for name, flag in self.cell_flags[kind]:
            data[name] = _per_block(blocks, lambda e, f=flag: 1.0 if e.Is(f) else 0.0)
        for variable in self.in_cells:
            data[variable.Name()] = _per_block(
                blocks, lambda e, v=variable: _gauss_mean(e, v, process_info)
            )
        if self.write_ids:
            data[f"KRATOS_{kind.upper()}_ID"] = [
                np.array([e.Id for e in entities], dtype=np.int64) for _, _, entities in blocks
            ]
        return data


# -- helpers --


def _choice(settings: Parameters, key: str, allowed: tuple[str, ...]) -> str:
    value = settings[key].GetString()
    if value not in allowed:
        listing = " or ".join(f'"{a}"' for a in allowed)
        raise InputError(
            f'{key} is "{value}"\n  where:    {settings.Where(key)}\n  expected: {listing}'
        )
    return value


def _refuse_duplicates(settings: Parameters, names: list[str], what: str) -> None:
    seen: set[str] = set()
    for name in names:
        if name in seen:
            raise InputError(
                f'"{name}" is requested twice as {what}\n  where:    {settings.Where()}\n'
                "  fix:      list it once (the arrays of one file need unique names)"
            )
        seen.add(name)


def _round(value: float) -> float:
    """Round to 12 significant digits (how output times are compared)."""
    return float(f"{value:.12g}")


def _round_significant(values: np.ndarray, digits: int) -> np.ndarray:
    """Round floating-point values to ``digits`` significant digits (integers are kept)."""
    if not np.issubdtype(values.dtype, np.floating):
        return values
    finite = np.isfinite(values) & (values != 0.0)
    magnitude = np.zeros_like(values)
    magnitude[finite] = np.floor(np.log10(np.abs(values[finite])))
    scale = 10.0 ** (digits - 1 - magnitude)
    rounded = np.where(finite, np.round(values * scale) / scale, values)
    return rounded


def _row(value: Any) -> np.ndarray:
    return np.asarray(value, dtype=float).ravel()


def _stack(values: list[Any]) -> np.ndarray:
    """Stack scalars into (n,) and vectors into (n, k) (shorter ones padded with zeros)."""
    rows = [_row(v) for v in values]
    if all(r.size == 1 for r in rows):
        return np.array([r[0] for r in rows], dtype=float)
    width = max(r.size for r in rows)
    out = np.zeros((len(rows), width))
    for i, r in enumerate(rows):
        out[i, : r.size] = r
    return out


def _per_block(blocks: list[tuple[str, np.ndarray, list[Any]]], value: Any) -> list[np.ndarray]:
    stacked = [_stack([value(e) for e in entities]) for _, _, entities in blocks]
    widths = {a.shape[1] if a.ndim == 2 else 0 for a in stacked}
    if len(widths) > 1:  # meshio needs one width across blocks
        width = max(widths)
        stacked = [_widen(a, width) for a in stacked]
    return stacked


def _widen(values: np.ndarray, width: int) -> np.ndarray:
    out = np.zeros((len(values), width))
    if values.ndim == 1:
        out[:, 0] = values
    else:
        out[:, : values.shape[1]] = values
    return out


def _gauss_mean(entity: Any, variable: Any, process_info: Any) -> np.ndarray:
    values = [_row(v) for v in entity.CalculateOnIntegrationPoints(variable, process_info)]
    return np.mean(values, axis=0) if values else np.zeros(1)


def _rows(values: np.ndarray, sizes: np.ndarray) -> np.ndarray:
    """What :func:`_stack` makes of the rows ``values[i, :sizes[i]]`` (zero-padded arrays)."""
    if np.all(sizes == 1):
        return values[:, 0].copy() if values.shape[1] else np.zeros(len(values))
    return values[:, : int(sizes.max())].copy()


def _rows_per_block(
    values: np.ndarray, sizes: np.ndarray, members: list[np.ndarray]
) -> list[np.ndarray]:
    """What :func:`_per_block` makes of per-entity rows: stacked per block, one width for all."""
    stacked = [_rows(values[chosen], sizes[chosen]) for chosen in members]
    widths = {a.shape[1] if a.ndim == 2 else 0 for a in stacked}
    if len(widths) > 1:  # meshio needs one width across blocks
        width = max(widths)
        stacked = [_widen(a, width) for a in stacked]
    return stacked


def _integration_point_means(
    values: np.ndarray, sizes: np.ndarray, points: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Per entity the mean over its integration points (as :func:`_gauss_mean`), padded rows.

    ``values[e]`` holds the ``points[e]`` rows of entity ``e`` one after the other. Entities with
    the same number of points and row width are averaged together (the same sums as one by one).
    """
    count = len(points)
    widths = np.where(points > 0, sizes // np.maximum(points, 1), 1)
    means = np.zeros((count, int(widths.max()) if count else 1))
    shapes = np.unique(np.stack([points, widths], axis=1)[points > 0], axis=0)
    for k, w in shapes.tolist():
        chosen = np.flatnonzero((points == k) & (widths == w))
        means[chosen, :w] = np.mean(values[chosen, : k * w].reshape(-1, k, w), axis=1)
    return means, widths


def _cell_type(geometry_name: str, part: Any, entity_id: int) -> str:
    """The meshio cell type of a geometry (InputError naming the entity if there is none)."""
    cell_type = CELL_TYPES.get(geometry_name)
    if cell_type is None:
        raise InputError(
            f'entity {entity_id} of "{part.FullName()}" has the geometry {geometry_name}, '
            "which vtk_output_process cannot write\n"
            f"  expected: one of {', '.join(CELL_TYPES)}\n"
            '  fix:      set "entity_type" to the other kind of entity, or leave this part out'
        )
    return cell_type


def _cell_blocks(
    entities: list[Any], index: dict[int, int], part: Any
) -> list[tuple[str, np.ndarray, list[Any]]]:
    """Group entities by cell type (first-appearance order): (type, connectivity, entities)."""
    grouped: dict[str, tuple[list[list[int]], list[Any]]] = {}
    for entity in entities:
        cell_type = _cell_type(entity.GetGeometry().Name(), part, entity.Id)
        connectivity, members = grouped.setdefault(cell_type, ([], []))
        connectivity.append([index[n.Id] for n in entity.GetNodes()])
        members.append(entity)
    return [
        (cell_type, np.array(connectivity, dtype=np.int64), members)
        for cell_type, (connectivity, members) in grouped.items()
    ]


def _extrapolate(
    entities: list[Any], variable: Any, process_info: Any, index: dict[int, int], count: int
) -> np.ndarray:
    """Extrapolate integration-point values to the nodes of each entity and average per node.

    With as many integration points as nodes the values are interpolated exactly (``N x = v``);
    otherwise the entity contributes its mean value to each of its nodes.
    """
    totals: np.ndarray | None = None
    hits = np.zeros(count)
    for entity in entities:
        values = np.array(
            [_row(v) for v in entity.CalculateOnIntegrationPoints(variable, process_info)]
        )
        if values.size == 0:
            continue
        geometry = entity.GetGeometry()
        node_ids = [n.Id for n in entity.GetNodes()]
        nodal = np.repeat(values.mean(axis=0, keepdims=True), len(node_ids), axis=0)
        points = geometry.IntegrationPoints()
        if len(points) == len(node_ids) == len(values):
            shape = np.array([geometry.ShapeFunctionsValues(np.asarray(p[0])) for p in points])
            with contextlib.suppress(np.linalg.LinAlgError):
                nodal = np.linalg.solve(shape, values)
        if totals is None:
            totals = np.zeros((count, values.shape[1]))
        for node_id, row in zip(node_ids, nodal, strict=True):
            totals[index[node_id]] += row
            hits[index[node_id]] += 1.0
    if totals is None:
        return np.zeros(count)
    averaged = totals / np.maximum(hits, 1.0)[:, None]
    return averaged[:, 0] if averaged.shape[1] == 1 else averaged


def _read_pvd(path: Path) -> list[tuple[float, str]]:
    """The ``(time, file)`` entries of a collection written by :func:`_write_pvd` ([] if none)."""
    if not path.is_file():
        return []
    from xml.etree import ElementTree

    root = ElementTree.parse(path).getroot()
    return [
        (float(item.get("timestep", "0")), item.get("file", ""))
        for item in root.iter("DataSet")
        if item.get("file")
    ]


def _write_pvd(path: Path, entries: list[tuple[float, str]]) -> None:
    """Write a ParaView collection listing ``(time, file)`` entries (files relative to it)."""
    lines = [
        '<?xml version="1.0"?>',
        '<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">',
        "  <Collection>",
    ]
    for time, name in entries:
        lines.append(f'    <DataSet timestep="{time!r}" group="" part="0" file={quoteattr(name)}/>')
    lines += ["  </Collection>", "</VTKFile>", ""]
    temporary = path.with_name(path.name + ".tmp")
    temporary.write_text("\n".join(lines), encoding="utf-8")
    os.replace(temporary, path)
