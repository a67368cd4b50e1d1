"""Settings helpers shared by the contact processes and solvers.

The ``"0"``…``"9"`` pair blocks and errors: Kratos writes every per-pair setting as an object with
the fixed keys ``"0"`` to ``"9"`` (``docs/input_layer.md`` §3); a key outside that set is an unknown
key, as in Kratos. The solver ``mortar_type`` values and what each decodes into (condition family,
variables, DoFs, criterion), read from the C++ condition table (docs/registered_conditions.md §4).
"""

from __future__ import annotations

from collections.abc import Collection
from typing import Any

from contact_app._core import InputError, MortarType, MortarTypes
from contact_app.parameters import Parameters, suggest

#: The pair keys Kratos accepts, in order.
PAIR_KEYS = tuple(str(i) for i in range(10))

#: Every solver ``mortar_type`` by name, in the order of the C++ table.
MORTAR_TYPES: dict[str, MortarType] = {t.name: t for t in MortarTypes()}


def process_contact_types(method: str) -> tuple[str, ...]:
    """The ``contact_type`` values of the contact process of ``method`` ("ALM", "Penalty")."""
    return tuple(t.contact_type for t in MORTAR_TYPES.values() if t.method == method)


def process_mortar_type(method: str, contact_type: str) -> MortarType:
    """The mortar_type the ``method`` process runs for a (validated) ``contact_type``."""
    return next(
        t for t in MORTAR_TYPES.values() if t.method == method and t.contact_type == contact_type
    )


def pair_block(value: Any) -> dict[str, Any]:
    """A ``{"0": value, …, "9": value}`` default block (each value copied)."""
    return {key: (list(value) if isinstance(value, list) else value) for key in PAIR_KEYS}


def fail(settings: Parameters, key: str, what: str, expected: str, fix: str = "") -> InputError:
    """An InputError in the house format (what / where / expected / fix)."""
    message = f"{what}\n  where:    {settings.Where(key)}\n  expected: {expected}"
    if fix:
        message += f"\n  fix:      {fix}"
    return InputError(message)


def unknown_choice(
    settings: Parameters, key: str, written: str, value: str, choices: Collection[str]
) -> InputError:
    """:func:`fail` for ``settings[key]``, written ``written``, whose ``value`` is not a choice."""
    what = f'unknown {key} "{written}"'
    listing = ", ".join(f'"{choice}"' for choice in choices)
    return fail(settings, key, what, f"one of {listing}", suggest(value, list(choices)))


def string_lists(settings: Parameters, key: str) -> dict[str, list[str]]:
    """The non-empty ``{pair key: [model part names]}`` entries of a pair block.

    Raises:
        InputError: an entry is not a list of strings.
    """
    block = settings[key]
    result: dict[str, list[str]] = {}
    for pair in PAIR_KEYS:
        entry = block[pair]
        if not entry.IsArray() or not all(item.IsString() for item in entry):
            raise fail(
                block,
                pair,
                f'"{key}"["{pair}"] is {entry.WriteJsonString()}',
                'a list of model part names, e.g. ["Contact_Part"]',
            )
        names = entry.GetStringArray()
        if names:
            result[pair] = names
    return result
