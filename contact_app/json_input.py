"""Reading JSON inputs that a user (or an attacker) wrote: every refusal is an ``InputError``.

One reader for every JSON file a run reads (``ProjectParameters.json``, materials, reference
results) and for JSON text given in memory. Beyond what :func:`json.loads` checks it refuses:

* anything that is not a regular file (a device such as ``/dev/zero`` or a FIFO would be read
  forever) and files over :data:`MAX_BYTES`;
* bytes that are not UTF-8 (file and byte offset);
* nesting deeper than :data:`MAX_DEPTH` (the parser would otherwise recurse until it fails);
* a key written twice in one object (both lines: the last one would win silently);
* ``NaN``, ``Infinity`` and numbers that overflow a double (``1e400``), which Python's parser
  accepts although JSON has no such values, and integers beyond 64 bits;
* escapes of unpaired UTF-16 surrogates, which decode to strings that are not text (the C++
  layer and the console could not encode them).

:func:`quote` shortens and escapes a user value for a message.
"""

from __future__ import annotations

import json
import math
import os
import re
import stat
from pathlib import Path
from typing import Any

from ._core import InputError

#: Largest JSON input read (reference result files of long runs stay far below).
MAX_BYTES = 256 * 1024 * 1024
#: Deepest nesting of arrays and objects (Kratos settings nest about 8 levels).
MAX_DEPTH = 64
#: Longest quote of a user value in a message.
MAX_QUOTE = 200

# Strings (keys or values) and brackets; numbers and literals are skipped by the search.
_TOKEN = re.compile(r'"(?:[^"\\]|\\.)*"|[\[\]{}]', re.DOTALL)
_COLON = re.compile(r"\s*:")
# Strings, punctuation and the literals between them (numbers, true, NaN, ...).
_SCAN = re.compile(r'"(?:[^"\\]|\\.)*"|[\[\]{}:,]|[^\s\[\]{}:,"]+', re.DOTALL)
_SURROGATE = re.compile(r"\\u[dD][89a-fA-F][0-9a-fA-F]{2}")
#: Integers are ids, counts and orders: 64 bits, as in the C++ layer.
_MAX_INT = 2**63 - 1


def quote(value: Any, limit: int = MAX_QUOTE) -> str:
    """Return ``value`` as text for a message: control characters escaped, at most ``limit``.

    A NUL would cut the message where C code prints it, and a 20,000-character line buries it.
    """
    text = value if isinstance(value, str) else repr(value)
    shown = "".join(
        c if c.isprintable() else c.encode("unicode_escape").decode("ascii")
        for c in text[: 4 * limit]  # escape only what can be shown
    )
    if len(text) <= limit and len(shown) <= limit:
        return shown
    return f"{shown[:limit]}… ({len(text)} characters)"


def not_regular(filename: str | Path, what: str, where: str = "") -> InputError:
    """The error for an input that exists but is not a regular file (folder, device, FIFO)."""
    kind = "a folder" if Path(filename).is_dir() else "not a regular file"
    located = f"\n  where:    {where}" if where else ""
    return InputError(
        f'the {what} "{quote(str(filename))}" is {kind}{located}\n'
        "  expected: a file on disk (not a folder, device, FIFO or socket: /dev/zero would be "
        "read forever)\n"
        "  fix:      name the file itself"
    )


def read_bytes(filename: str | Path, what: str, where: str = "") -> bytes:
    """Return the content of a regular file of at most :data:`MAX_BYTES`.

    Args:
        filename: the path.
        what: what the file is, for the message ("settings file", "materials file", ...).
        where: the settings key that names it, for the message.

    Raises:
        InputError: missing or unreadable, not a regular file, or too large.

    """
    located = f"\n  where:    {where}" if where else ""
    try:
        # O_NONBLOCK: opening a FIFO must not wait for a writer before it can be refused.
        descriptor = os.open(filename, os.O_RDONLY | os.O_NONBLOCK)
    except OSError as error:
        raise InputError(
            f'cannot read the {what} "{quote(str(filename))}": {error.strerror}{located}\n'
            "  fix:      check the path (relative paths start from the working directory)"
        ) from None
    with os.fdopen(descriptor, "rb") as stream:
        if not stat.S_ISREG(os.fstat(descriptor).st_mode):
            raise not_regular(filename, what, where)
        os.set_blocking(descriptor, True)
        data = stream.read(MAX_BYTES + 1)
    if len(data) > MAX_BYTES:
        raise InputError(
            f'the {what} "{quote(str(filename))}" is larger than '
            f"{MAX_BYTES // 2**20} MiB{located}\n"
            "  expected: a JSON input of reasonable size\n"
            "  fix:      check that this is the intended file"
        )
    return data


def decode(data: bytes, source: str) -> str:
    """Decode UTF-8 bytes; InputError with the byte offset and line otherwise."""
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as error:
        line = data.count(b"\n", 0, error.start) + 1
        raise InputError(
            f"{source} is not UTF-8 text: byte 0x{data[error.start]:02x} at byte offset "
            f"{error.start} (line {line}) {error.reason}\n"
            "  expected: a UTF-8 encoded JSON file\n"
            "  fix:      save the file as UTF-8 (or remove the stray bytes)"
        ) from None


def _line(text: str, index: int) -> int:
    return text.count("\n", 0, index) + 1


def _check_structure(text: str, source: str) -> None:
    """Refuse nesting deeper than MAX_DEPTH and keys written twice in one object (with lines)."""
    # One entry per open bracket: the keys seen so far (None for an array).
    stack: list[dict[str, int] | None] = []
    for match in _TOKEN.finditer(text):
        token = match.group()
        if token in "[{":
            if len(stack) >= MAX_DEPTH:
                raise InputError(
                    f"{source} nests arrays and objects deeper than {MAX_DEPTH} levels\n"
                    f"  where:    line {_line(text, match.start())}\n"
                    f"  expected: at most {MAX_DEPTH} levels of [ ] and {{ }}\n"
                    "  fix:      check for unbalanced or runaway brackets"
                )
            stack.append({} if token == "{" else None)
        elif token in "]}":
            if stack:
                stack.pop()
        elif stack and stack[-1] is not None and _COLON.match(text, match.end()):
            keys, line = stack[-1], _line(text, match.start())
            key = token[1:-1]
            if key in keys:
                raise InputError(
                    f'the key "{quote(key)}" is written twice in one object of {source}\n'
                    f"  where:    lines {keys[key]} and {line}\n"
                    "  expected: each key once per object (JSON readers keep only the last)\n"
                    "  fix:      remove one of the two entries"
                )
            keys[key] = line


def _key_text(token: str) -> str:
    try:
        return str(json.loads(token))
    except ValueError:
        return token[1:-1]


def _number_location(text: str, written: str, source: str) -> str:
    """``file › key › [index] ›…, line n`` of the first number or literal written ``written``.

    The parser reads in document order and stops at the first refused number, so the first
    literal outside strings with that spelling is the one it refused.
    """
    # Each frame: ["{", last key] or ["[", element index].
    frames: list[list[Any]] = []
    for match in _SCAN.finditer(text):
        token = match.group()
        if token in "[{":
            frames.append([token, None if token == "{" else 0])
        elif token in "]}":
            if frames:
                frames.pop()
        elif token == ",":
            if frames and frames[-1][0] == "[":
                frames[-1][1] += 1
        elif token.startswith('"'):
            if frames and frames[-1][0] == "{" and _COLON.match(text, match.end()):
                frames[-1][1] = _key_text(token)
        elif token == written:
            path = [str(label) if kind == "{" else f"[{label}]" for kind, label in frames]
            where = " › ".join(quote(part, 80) for part in [source, *path])
            return f"{where}, line {_line(text, match.start())}"
    return source


def _finite_float(text: str) -> float:
    value = float(text)
    if not math.isfinite(value):
        raise _NonFinite(text)
    return value


class _NonFinite(ValueError):
    """A number JSON cannot hold (raised inside the parser, reported with its line)."""

    def __init__(self, written: str) -> None:
        super().__init__(written)
        self.written = written


def _refuse_constant(name: str) -> float:
    raise _NonFinite(name)


def _checked_int(text: str) -> int:
    # The length test comes first: int() of a 5,000-digit string raises ValueError by itself.
    if len(text.lstrip("-")) > 19 or abs(int(text)) > _MAX_INT:
        raise _NonFinite(text)
    return int(text)


def _check_strings(value: Any, text: str, source: str) -> None:
    """Refuse strings that are not text (unpaired surrogates written as escapes)."""
    pending = [value]
    while pending:
        item = pending.pop()
        if isinstance(item, dict):
            pending.extend(item.keys())
            pending.extend(item.values())
        elif isinstance(item, list):
            pending.extend(item)
        elif isinstance(item, str):
            try:
                item.encode("utf-8")
            except UnicodeEncodeError:
                match = _SURROGATE.search(text)
                line = f"line {_line(text, match.start())}" if match else "the file"
                raise InputError(
                    f'{source} holds the string "{quote(item, 80)}" with an unpaired surrogate '
                    f"escape, which is not text\n  where:    {line}\n"
                    "  expected: text (escapes \\uD800-\\uDFFF only as high-low pairs)\n"
                    "  fix:      write the intended character"
                ) from None


def loads(text: str, source: str) -> Any:
    """Parse JSON text with the checks of the module docstring.

    Args:
        text: the JSON text.
        source: the file name (or ``<string>``) for messages.

    Raises:
        InputError: malformed JSON (line, column), too deep, a key twice, a non-finite number.

    """
    _check_structure(text, source)
    try:
        value = json.loads(
            text,
            parse_float=_finite_float,
            parse_int=_checked_int,
            parse_constant=_refuse_constant,
        )
    except json.JSONDecodeError as error:
        raise InputError(
            f"malformed JSON in {source}: {error.msg}\n"
            f"  where:    line {error.lineno}, column {error.colno}\n"
            "  fix:      check for a missing comma, quote or bracket there"
        ) from None
    except _NonFinite as error:
        written = quote(error.written, 40)
        raise InputError(
            f"{source} holds the number {written}, which is not a finite double or 64-bit integer\n"
            f"  where:    {_number_location(text, error.written, source)}\n"
            "  expected: a finite number (JSON has no NaN or Infinity; doubles end near 1.8e308, "
            "integers at 64 bits)\n"
            "  fix:      write the intended finite value"
        ) from None
    _check_strings(value, text, source)
    return value


def load_file(filename: str | Path, what: str, where: str = "") -> Any:
    """Read and parse a JSON file (:func:`read_bytes`, :func:`decode`, :func:`loads`)."""
    name = Path(filename).name
    return loads(decode(read_bytes(filename, what, where), name), name)
