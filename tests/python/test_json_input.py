"""JSON inputs: non-finite numbers, duplicate keys, depth, encoding, non-regular and huge files."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

import contact_app as ca
from contact_app import json_input
from contact_app.parameters import Parameters


@pytest.mark.parametrize("number", ["NaN", "Infinity", "-Infinity", "1e400", "-2.5e999"])
def test_non_finite_numbers_are_refused_with_their_line(number: str) -> None:
    text = '{\n  "solver_settings": {\n    "time_step": ' + number + "\n  }\n}"
    with pytest.raises(ca.InputError, match="not a finite double") as failure:
        json_input.loads(text, "ProjectParameters.json")
    assert "ProjectParameters.json › solver_settings › time_step, line 3" in str(failure.value)


def test_non_finite_number_location_skips_strings_and_counts_array_elements() -> None:
    text = '{"name": "NaN", "a\\"b": [1, {"NaN": 2, "c": [0, "x,y", NaN]}]}'
    with pytest.raises(ca.InputError) as failure:
        json_input.loads(text, "case.json")
    assert 'case.json › a"b › [1] › c › [2], line 1' in str(failure.value)


@pytest.mark.parametrize("digits", [30, 5000])
def test_integers_beyond_64_bits_are_refused(digits: int) -> None:
    with pytest.raises(ca.InputError, match="64-bit integer") as failure:
        json_input.loads('{"properties_id": 1' + "0" * digits + "}", "case.json")
    assert len(str(failure.value)) < 600


def test_unpaired_surrogate_escapes_are_refused_with_their_line() -> None:
    with pytest.raises(ca.InputError, match="unpaired surrogate") as failure:
        json_input.loads('{"model_part_name":\n "a\\udc80"}', "case.json")
    assert "line 2" in str(failure.value)
    assert json_input.loads('"\\ud83d\\ude00"', "x") == "\U0001f600"


def test_a_key_written_twice_names_both_lines() -> None:
    text = '{\n  "problem_data": {\n    "end_time": 1.0,\n    "x": [1, {"end_time": 2}],\n'
    text += '    "end_time": 5.0\n  }\n}'
    with pytest.raises(ca.InputError, match='"end_time" is written twice') as failure:
        json_input.loads(text, "case.json")
    assert "lines 3 and 5" in str(failure.value)


def test_same_key_in_sibling_objects_is_fine() -> None:
    assert json_input.loads('[{"a": 1}, {"a": 2}, {"b": {"a": 3}, "a": "a"}]', "x") is not None


@pytest.mark.parametrize("bracket", ["[", '{"a": '])
def test_deep_nesting_is_bounded(bracket: str) -> None:
    with pytest.raises(ca.InputError, match="deeper than 64 levels"):
        json_input.loads(bracket * 100_000, "deep.json")


def test_brackets_inside_strings_do_not_count() -> None:
    assert json_input.loads('{"a": "' + "[" * 1000 + '"}', "x") == {"a": "[" * 1000}


def test_non_utf8_bytes_name_the_file_and_offset(tmp_path: Path) -> None:
    path = tmp_path / "case.json"
    path.write_bytes(b'{\n  "a": "caf\xe9"\n}')
    with pytest.raises(ca.InputError, match="byte 0xe9 at byte offset 13 \\(line 2\\)") as failure:
        Parameters.from_file(path)
    assert "case.json is not UTF-8" in str(failure.value)


def test_non_regular_files_are_refused() -> None:
    with pytest.raises(ca.InputError, match="is not a regular file"):
        json_input.load_file("/dev/zero", "materials file")


def test_a_fifo_is_refused_without_waiting(tmp_path: Path) -> None:
    fifo = tmp_path / "pipe.json"
    os.mkfifo(fifo)
    with pytest.raises(ca.InputError, match="is not a regular file"):
        json_input.load_file(fifo, "settings file")


def test_oversized_files_are_refused(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(json_input, "MAX_BYTES", 10)
    path = tmp_path / "big.json"
    path.write_text('{"a": [1, 2, 3, 4, 5]}')
    with pytest.raises(ca.InputError, match="is larger than"):
        json_input.load_file(path, "reference file")


def test_quote_truncates_and_escapes() -> None:
    quoted = json_input.quote("x" * 20_000)
    assert len(quoted) < 250 and quoted.endswith("(20000 characters)")
    assert json_input.quote("a\x00b") == "a\\x00b"


def test_parameters_messages_quote_huge_values_briefly() -> None:
    p = Parameters({"max_iteration": "y" * 50_000}, "case.json")
    with pytest.raises(ca.InputError) as failure:
        p.ValidateAndAssignDefaults({"max_iteration": 10})
    assert len(str(failure.value)) < 600
    with pytest.raises(ca.InputError) as failure:
        Parameters({"k\x00" + "z" * 30_000: 1}, "case.json").ValidateAndAssignDefaults({"a": 1})
    assert "\x00" not in str(failure.value) and len(str(failure.value)) < 800
