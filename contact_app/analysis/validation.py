"""Checks shared by the analysis layer: choices, required keys, ranges (what/where/fix)."""

from __future__ import annotations

from collections.abc import Sequence

from .._core import ConfigurationError, InputError
from ..json_input import quote
from ..parameters import Parameters, suggest


def _listing(choices: Sequence[str]) -> str:
    return ", ".join(f'"{c}"' for c in choices)


def error(
    settings: Parameters, key: str | None, what: str, expected: str, fix: str = ""
) -> InputError:
    """Build an InputError located at ``settings`` (or its child ``key``).

    ``what`` is escaped and capped, as it may quote a user value (a NUL, a 20,000-character line).
    """
    text = f"{quote(what, 300)}\n  where:    {settings.Where(key)}\n  expected: {expected}"
    if fix:
        text += f"\n  fix:      {fix}"
    return InputError(text)


def not_supported(settings: Parameters, key: str | None, what: str, fix: str) -> ConfigurationError:
    """Build a ConfigurationError for a valid Kratos option that contact_app does not implement."""
    return ConfigurationError(
        f"{what} is not supported yet\n  where:    {settings.Where(key)}\n  fix:      {fix}"
    )


def choice(settings: Parameters, key: str, choices: Sequence[str], what: str = "") -> str:
    """Return the string ``settings[key]`` after checking it is one of ``choices``.

    Raises:
        InputError: not a string, or not one of the choices (with a did-you-mean).

    """
    value = settings[key].GetString()
    if value not in choices:
        label = what or key
        raise error(
            settings,
            key,
            f'unknown {label} "{quote(value)}"',
            f"one of {_listing(choices)}",
            suggest(value, list(choices)),
        )
    return value


def require(settings: Parameters, key: str, expected: str, fix: str) -> Parameters:
    """Return ``settings[key]``; InputError naming the missing key otherwise."""
    if not settings.Has(key):
        raise error(settings, key, f'missing required key "{key}"', expected, fix)
    return settings[key]


def positive(settings: Parameters, key: str, *, allow_zero: bool = False) -> float:
    """Return the number ``settings[key]`` after checking it is > 0 (or >= 0)."""
    value = settings[key].GetDouble()
    if value < 0.0 or (value == 0.0 and not allow_zero):
        bound = "≥ 0" if allow_zero else "> 0"
        raise error(settings, key, f'"{key}" is {value}', f"a number {bound}")
    return value


def string_list(settings: Parameters, key: str) -> list[str]:
    """Return an array of strings; InputError (located) otherwise."""
    return settings[key].GetStringArray()
