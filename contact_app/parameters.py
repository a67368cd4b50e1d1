"""Kratos-style ``Parameters``: a JSON tree with typed access, defaults and validation.

Every node knows where it comes from (file and JSON path), so an unknown key, a wrong type or a
missing value is reported as::

    InputError: unknown key "max_iterations"
      where:    ProjectParameters.json › solver_settings › max_iterations
      expected: one of "max_iteration", "echo_level", ...
      fix:      did you mean "max_iteration"?
"""

from __future__ import annotations

import copy
import difflib
import json
import math
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from . import json_input
from ._core import InputError
from .json_input import quote
from .setting_ranges import range_of

_JsonValue = Any


def _kind(value: _JsonValue) -> str:
    """Name the JSON kind of a value the way messages show it."""
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "bool"
    if isinstance(value, int):
        return "int"
    if isinstance(value, float):
        return "double"
    if isinstance(value, str):
        return "string"
    if isinstance(value, list):
        return "array"
    return "object"


def _compatible(value: _JsonValue, default: _JsonValue) -> bool:
    """Tell whether a user value may replace a default (ints are accepted where doubles are)."""
    if default is None:
        return True
    value_kind, default_kind = _kind(value), _kind(default)
    if value_kind == default_kind:
        return True
    return value_kind == "int" and default_kind == "double"


def suggest(name: str, candidates: list[str]) -> str:
    """Return a 'did you mean' hint for a misspelt name, or an empty string."""
    close = difflib.get_close_matches(name, candidates, n=3, cutoff=0.6)
    if not close:
        return ""
    return "did you mean " + " or ".join(f'"{c}"' for c in close) + "?"


class Parameters:
    """A node of a JSON settings tree (Kratos ``KratosMultiphysics.Parameters``).

    Args:
        value: a JSON string, or an already parsed value (dict, list, number, ...).
        source: the file the tree was read from (for messages).
        path: the JSON path of this node from the root (for messages).

    """

    def __init__(
        self,
        value: _JsonValue = "{}",
        source: str = "<string>",
        path: tuple[str, ...] = (),
        _slot: tuple[dict[str, Any] | list[Any], str | int] | None = None,
    ):
        if isinstance(value, str) and path == ():
            value = json_input.loads(value, source)
        self._value = value
        self._source = source
        self._path = path
        self._slot = _slot  # (container, key) in the parent, so setters write through

    # -- construction --

    @classmethod
    def from_file(cls, filename: str | Path) -> Parameters:
        """Read a JSON file (checks of :mod:`contact_app.json_input`); InputError otherwise."""
        return cls(json_input.load_file(filename, "settings file"), source=Path(filename).name)

    def Clone(self) -> Parameters:
        """Return a deep copy."""
        return Parameters(copy.deepcopy(self._value), self._source, self._path)

    # -- location --

    def Where(self, key: str | None = None) -> str:
        """Describe the location of this node (or of its child ``key``) for messages."""
        parts = [self._source, *self._path] + ([key] if key is not None else [])
        return " › ".join(quote(part, 80) for part in parts)

    def _error(self, what: str, expected: str, fix: str = "", key: str | None = None) -> InputError:
        text = f"{quote(what, 300)}\n  where:    {self.Where(key)}\n  expected: {expected}"
        if fix:
            text += f"\n  fix:      {fix}"
        return InputError(text)

    # -- structure --

    def _object(self) -> dict[str, _JsonValue]:
        if not isinstance(self._value, dict):
            raise self._error(f"a {_kind(self._value)} is used as an object", "an object { ... }")
        return self._value

    def Has(self, key: str) -> bool:
        """Tell whether the object has ``key``."""
        return isinstance(self._value, dict) and key in self._value

    def __contains__(self, key: str) -> bool:
        return self.Has(key)

    def __getitem__(self, key: str | int) -> Parameters:
        if isinstance(key, int):
            if not isinstance(self._value, list):
                raise self._error(
                    f"a {_kind(self._value)} is indexed like an array", "an array [ ... ]"
                )
            if not -len(self._value) <= key < len(self._value):
                raise self._error(
                    f"index {key} is out of range", f"an index below {len(self._value)}"
                )
            path = (*self._path, f"[{key}]")
            return Parameters(self._value[key], self._source, path, (self._value, key))
        values = self._object()
        if key not in values:
            raise self._error(
                f'missing key "{key}"', "the key to be present", suggest(key, list(values)), key
            )
        return Parameters(values[key], self._source, (*self._path, key), (values, key))

    def keys(self) -> list[str]:
        """Return the keys of an object, in file order."""
        return list(self._object().keys())

    def items(self) -> Iterator[tuple[str, Parameters]]:
        """Iterate over (key, child) pairs of an object."""
        for key in self.keys():
            yield key, self[key]

    def values(self) -> Iterator[Parameters]:
        """Iterate over the entries of an array or the values of an object."""
        if isinstance(self._value, list):
            for i in range(len(self._value)):
                yield self[i]
        else:
            for key in self.keys():
                yield self[key]

    def __iter__(self) -> Iterator[Parameters]:
        return self.values()

    def size(self) -> int:
        """Return the number of entries of an array (or keys of an object)."""
        return len(self._value) if isinstance(self._value, list | dict) else 0

    def __len__(self) -> int:
        return self.size()

    def AddValue(self, key: str, value: Parameters | _JsonValue) -> None:
        """Add (or replace) a child."""
        self._object()[key] = copy.deepcopy(
            value._value if isinstance(value, Parameters) else value
        )

    def AddEmptyValue(self, key: str) -> Parameters:
        """Add a null child and return it."""
        self._object()[key] = None
        return self[key]

    def RemoveValue(self, key: str) -> None:
        """Remove a child if present."""
        self._object().pop(key, None)

    # -- typed access --

    def IsNull(self) -> bool:
        """True for a JSON null."""
        return self._value is None

    def IsBool(self) -> bool:
        """True for true/false."""
        return isinstance(self._value, bool)

    def IsInt(self) -> bool:
        """True for an integer."""
        return isinstance(self._value, int) and not isinstance(self._value, bool)

    def IsDouble(self) -> bool:
        """True for a real number written with a point or exponent."""
        return isinstance(self._value, float)

    def IsNumber(self) -> bool:
        """True for an integer or a real number."""
        return self.IsInt() or self.IsDouble()

    def IsString(self) -> bool:
        """True for a string."""
        return isinstance(self._value, str)

    def IsArray(self) -> bool:
        """True for an array."""
        return isinstance(self._value, list)

    def IsSubParameter(self) -> bool:
        """True for an object."""
        return isinstance(self._value, dict)

    def IsVector(self) -> bool:
        """True for an array of numbers."""
        return self.IsArray() and all(
            isinstance(v, int | float) and not isinstance(v, bool) for v in self._value
        )

    def IsMatrix(self) -> bool:
        """True for an array of arrays of numbers."""
        return self.IsArray() and all(Parameters(row).IsVector() for row in self._value)

    def _typed(self, ok: bool, expected: str) -> _JsonValue:
        if not ok:
            raise self._error(
                f"wrong type: found a {_kind(self._value)} ({quote(repr(self._value))})", expected
            )
        return self._value

    def _finite(self, values: list[int | float]) -> list[float]:
        """Refuse NaN, infinities and huge integers (JSON text cannot hold them; a dict can)."""
        for value in values:
            if isinstance(value, int) and abs(value) > 2**63 - 1:
                raise self._error(
                    f"an integer of {value.bit_length()} bits", "a 64-bit integer or a double"
                )
            if not math.isfinite(value):
                raise self._error(f"the number {value} is not finite", "a finite number")
        return [float(value) for value in values]

    def GetString(self) -> str:
        """Return the string; InputError otherwise."""
        return self._typed(self.IsString(), "a string")

    def GetBool(self) -> bool:
        """Return the bool; InputError otherwise."""
        return self._typed(self.IsBool(), "true or false")

    def GetInt(self) -> int:
        """Return the integer; InputError otherwise."""
        return self._typed(self.IsInt(), "an integer")

    def GetDouble(self) -> float:
        """Return the number as a float; InputError otherwise."""
        return self._finite([self._typed(self.IsNumber(), "a number")])[0]

    def GetVector(self) -> list[float]:
        """Return an array of numbers as floats; InputError otherwise."""
        return self._finite(list(self._typed(self.IsVector(), "an array of numbers")))

    def GetMatrix(self) -> list[list[float]]:
        """Return an array of arrays of numbers; InputError otherwise."""
        rows = self._typed(self.IsMatrix(), "an array of arrays of numbers")
        return [self._finite(list(row)) for row in rows]

    def GetStringArray(self) -> list[str]:
        """Return an array of strings; InputError otherwise."""
        ok = self.IsArray() and all(isinstance(v, str) for v in self._value)
        return list(self._typed(ok, "an array of strings"))

    def GetValue(self) -> _JsonValue:
        """Return the plain (parsed JSON) value."""
        return self._value

    def SetString(self, value: str) -> None:
        """Replace the value (written through to the parent)."""
        self._set(value)

    def SetBool(self, value: bool) -> None:
        """Replace the value (written through to the parent)."""
        self._set(bool(value))

    def SetInt(self, value: int) -> None:
        """Replace the value (written through to the parent)."""
        self._set(int(value))

    def SetDouble(self, value: float) -> None:
        """Replace the value (written through to the parent)."""
        self._set(float(value))

    def SetVector(self, value: list[float]) -> None:
        """Replace the value (written through to the parent)."""
        self._set([float(v) for v in value])

    def _set(self, value: _JsonValue) -> None:
        self._value = value
        if self._slot is not None:
            container, key = self._slot
            container[key] = value  # type: ignore[index]

    # -- defaults and validation --

    def ValidateAndAssignDefaults(self, defaults: Parameters | dict[str, _JsonValue]) -> None:
        """Check this object's keys and value kinds against ``defaults``; add the missing ones.

        Only this level is checked (sub-objects are copied when missing but not validated), as in
        Kratos. Every number given must be finite and lie in the range of its key
        (:mod:`contact_app.setting_ranges`). Raises InputError for an unknown key (with a
        suggestion), a wrong value kind or a number out of range.
        """
        reference = defaults._value if isinstance(defaults, Parameters) else defaults
        values = self._object()
        for key, value in values.items():
            if key not in reference:
                known = list(reference)
                listing = ", ".join(f'"{k}"' for k in known[:12]) + (
                    ", ..." if len(known) > 12 else ""
                )
                raise self._error(
                    f'unknown key "{quote(key, 80)}"',
                    f"one of {listing}",
                    suggest(key, known),
                    key,
                )
            if not _compatible(value, reference[key]):
                raise self._error(
                    f'"{key}" has the wrong type: found a {_kind(value)} ({quote(repr(value))})',
                    f"a {_kind(reference[key])} like the default {json.dumps(reference[key])}",
                    key=key,
                )
            self._CheckNumber(key, value)
        for key, value in reference.items():
            if key not in values:
                values[key] = copy.deepcopy(value)

    def _CheckNumber(self, key: str, value: _JsonValue) -> None:
        """Refuse a non-finite number, or one outside the range its key allows."""
        if isinstance(value, bool) or not isinstance(value, int | float):
            return
        self[key]._finite([value])  # a dict may hold NaN or a huge integer
        allowed = range_of(key, self._path[-1] if self._path else None)
        if allowed is not None and not allowed.contains(value):
            meaning = f" ({allowed.meaning})" if allowed.meaning else ""
            raise self._error(
                f'"{key}" is {value}, out of range',
                allowed.text() + meaning,
                "correct the value",
                key=key,
            )

    def RecursivelyValidateAndAssignDefaults(
        self, defaults: Parameters | dict[str, _JsonValue]
    ) -> None:
        """Validate this level and every sub-object that has an object default."""
        reference = defaults._value if isinstance(defaults, Parameters) else defaults
        self.ValidateAndAssignDefaults(reference)
        for key, value in reference.items():
            if isinstance(value, dict) and value and self[key].IsSubParameter():
                self[key].RecursivelyValidateAndAssignDefaults(value)

    def AddMissingParameters(self, defaults: Parameters | dict[str, _JsonValue]) -> None:
        """Add the keys of ``defaults`` that are missing (no validation)."""
        reference = defaults._value if isinstance(defaults, Parameters) else defaults
        values = self._object()
        for key, value in reference.items():
            values.setdefault(key, copy.deepcopy(value))

    def RecursivelyAddMissingParameters(self, defaults: Parameters | dict[str, _JsonValue]) -> None:
        """Add missing keys at every level where both sides are objects."""
        reference = defaults._value if isinstance(defaults, Parameters) else defaults
        self.AddMissingParameters(reference)
        for key, value in reference.items():
            if isinstance(value, dict) and self[key].IsSubParameter():
                self[key].RecursivelyAddMissingParameters(value)

    # -- output --

    def WriteJsonString(self) -> str:
        """Return compact JSON."""
        return json.dumps(self._value)

    def PrettyPrintJsonString(self) -> str:
        """Return indented JSON."""
        return json.dumps(self._value, indent=4)

    def __repr__(self) -> str:
        return f"Parameters({self.WriteJsonString()})"
