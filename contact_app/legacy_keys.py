"""Keys of older versions of the reference's files: the one table of what each becomes, and why.

Each row names the block the key is found in, the old key, the current key it becomes (``None``:
it has no current equivalent and is dropped) and the reason. :func:`convert_legacy_keys` applies
the rows of one block with one warning per key, naming the current key, before the block is
validated; a key that is in no row is validated as usual, so a key the current reference also
rejects gets the usual "unknown key" error with its suggestion.

Rows with a ``converter`` need more than a rename (one old flag sets a sub-block); the converter
named there does it, :func:`convert_legacy_keys` leaves them alone.

Blocks: ``solver_settings``, ``model_import_settings`` (in ``solver_settings``),
``contact_settings``, ``process`` (the ``Parameters`` of every process descriptor, converted by the
process factory, so the processes' own schemas keep ``mesh_id`` 0 as the reference's do) and a
process module name (``vtk_output_process``, converted by the process itself so that it also holds
when the process is built from Python).
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from typing import Any

from ._core import InputError
from .parameters import Parameters

logger = logging.getLogger("contact_app.analysis")

_ANY = object()


@dataclass(frozen=True)
class LegacyKey:
    """One key of an older file version.

    Attributes:
        block: where the key is found (see the module docstring).
        old: the old key.
        current: the key that replaces it (several: comma-separated, each gets the value), or None
            when it is dropped.
        reason: why, for the warning and the docs.
        only_value: a dropped key is dropped only with this value; another value is an error
            (``mesh_id`` other than 0 selected a mesh that no longer exists).
        converter: the function that converts a key that is not a plain rename.

    """

    block: str
    old: str
    current: str | None
    reason: str
    only_value: Any = _ANY
    converter: str = ""


_NO_COMPUTING_PART = "the computing model part is always the main model part now"

#: Every legacy key contact_app accepts (issue 17: the reference's example collection uses
#: ``input_file_label``, ``mesh_id`` and ``line_search``; the rest come from its older test files).
LEGACY_KEYS: tuple[LegacyKey, ...] = (
    LegacyKey("solver_settings", "use_computing_model_part", None, _NO_COMPUTING_PART),
    LegacyKey("solver_settings", "computing_model_part_name", None, _NO_COMPUTING_PART),
    LegacyKey(
        "solver_settings",
        "problem_domain_sub_model_part_list",
        None,
        "the materials file assigns the elements of each part",
    ),
    LegacyKey(
        "solver_settings",
        "processes_sub_model_part_list",
        None,
        "each process names its own model part",
    ),
    LegacyKey(
        "solver_settings",
        "block_builder",
        "builder_and_solver_settings.type",
        'true → "block", false → "elimination"',
        converter="settings_validation.convert_deprecated_settings",
    ),
    LegacyKey(
        "solver_settings",
        "line_search",
        "solving_strategy_settings.type",
        'true → "line_search"; false is the default',
        converter="settings_validation.convert_deprecated_settings",
    ),
    LegacyKey(
        "model_import_settings",
        "input_file_label",
        "restart_load_file_label",
        'the label of the restart file read with input_type "rest"; an mdpa input does not use it',
    ),
    LegacyKey(
        "contact_settings",
        "frictional_contact_displacement_relative_tolerance",
        "frictional_stick_contact_displacement_relative_tolerance,"
        "frictional_slip_contact_displacement_relative_tolerance",
        "the frictional tolerances were split into stick and slip ones",
    ),
    LegacyKey(
        "contact_settings",
        "frictional_contact_displacement_absolute_tolerance",
        "frictional_stick_contact_displacement_absolute_tolerance,"
        "frictional_slip_contact_displacement_absolute_tolerance",
        "the frictional tolerances were split into stick and slip ones",
    ),
    LegacyKey(
        "contact_settings",
        "frictional_contact_residual_relative_tolerance",
        "frictional_stick_contact_residual_relative_tolerance,"
        "frictional_slip_contact_residual_relative_tolerance",
        "the frictional tolerances were split into stick and slip ones",
    ),
    LegacyKey(
        "contact_settings",
        "frictional_contact_residual_absolute_tolerance",
        "frictional_stick_contact_residual_absolute_tolerance,"
        "frictional_slip_contact_residual_absolute_tolerance",
        "the frictional tolerances were split into stick and slip ones",
    ),
    LegacyKey(
        "process",
        "mesh_id",
        None,
        "model parts no longer hold numbered meshes: model_part_name selects the entities",
        only_value=0,
    ),
    LegacyKey("vtk_output_process", "output_frequency", "output_interval", "renamed"),
    LegacyKey("vtk_output_process", "folder_name", "output_path", "renamed"),
)


def legacy_rows(block: str) -> list[LegacyKey]:
    """The rows of one block."""
    return [row for row in LEGACY_KEYS if row.block == block]


def convert_legacy_keys(settings: Parameters, block: str) -> None:
    """Rename or drop the legacy keys of ``block`` in ``settings``, one warning each.

    Raises:
        InputError: both the old and the current key given, or a dropped key with a value that
            meant something (``mesh_id`` other than 0).

    """
    if not settings.IsSubParameter():
        return
    for row in legacy_rows(block):
        if row.converter or not settings.Has(row.old):
            continue
        where = settings.Where(row.old)
        if row.current is None:
            _drop(settings, row, where)
            continue
        value = settings[row.old].GetValue()
        for current in row.current.split(","):
            if settings.Has(current):
                raise InputError(
                    f'both "{row.old}" and "{current}" are given\n  where:    {where}\n'
                    f'  expected: only "{current}" ("{row.old}" is its old name: {row.reason})\n'
                    f'  fix:      remove "{row.old}"'
                )
            settings.AddValue(current, _as_type_of(current, value, block))
        settings.RemoveValue(row.old)
        names = " and ".join(f'"{current}"' for current in row.current.split(","))
        logger.warning(
            '"%s" is the old name of %s; using it with the value %s (%s)\n  where:    %s',
            row.old,
            names,
            _shown(value),
            row.reason,
            where,
        )


def _drop(settings: Parameters, row: LegacyKey, where: str) -> None:
    value = settings[row.old].GetValue()
    if row.only_value is not _ANY and value != row.only_value:
        raise InputError(
            f'"{row.old}" = {_shown(value)} is a key of older versions that can only be 0 now\n'
            f"  where:    {where}\n"
            f"  expected: {row.old} 0 or no {row.old} ({row.reason})\n"
            f'  fix:      remove "{row.old}" and name the entities by model_part_name'
        )
    settings.RemoveValue(row.old)
    logger.warning(
        '"%s" is a key of older versions with no current equivalent; ignored (%s)\n  where:    %s',
        row.old,
        row.reason,
        where,
    )


def _as_type_of(current: str, value: Any, block: str) -> Any:
    """The old value in the current key's type (a restart label was a number, it is a string)."""
    if current == "restart_load_file_label" and isinstance(value, int | float):
        return f"{value:g}" if isinstance(value, float) else str(value)
    return value


def _shown(value: Any) -> str:
    return f'"{value}"' if isinstance(value, str) else repr(value)
