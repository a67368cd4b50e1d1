"""Interval: Kratos' in-interval rule (tolerance tied to the begin), "End", and bad intervals."""

from __future__ import annotations

import pytest

import contact_app as ca
from contact_app.parameters import Parameters
from contact_app.processes.interval import END_OF_TIME, Interval


def _interval(text: str) -> Interval:
    return Interval.from_parameters(Parameters(text, "case.json")["interval"])


def test_interval_end_string_means_no_end() -> None:
    interval = _interval('{"interval": [0.0, "End"]}')
    assert interval.end == END_OF_TIME
    assert interval.IsInInterval(0.0) and interval.IsInInterval(1.0e20)
    assert not interval.IsInInterval(-1.0e-12)


def test_interval_begin_is_inside_and_end_follows_kratos_tolerance() -> None:
    late = _interval('{"interval": [0.5, 1.0]}')
    assert [t in late for t in (0.4999, 0.5, 0.75, 1.0, 1.0 + 1e-15, 1.0 + 1e-13)] == [
        False,
        True,
        True,
        True,
        True,
        False,
    ]
    from_zero = _interval('{"interval": [0.0, 1.0]}')  # eps = 1e-30: t == 1.0 is outside
    assert [t in from_zero for t in (0.0, 0.999999, 1.0)] == [True, True, False]


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ('{"interval": [0.0]}', "does not have two entries"),
        ('{"interval": ["Begin", 1.0]}', "expected: a number"),
        ('{"interval": [0.0, "end"]}', 'a number or "End"'),
        ('{"interval": [2.0, 1.0]}', "ends before it begins"),
    ],
)
def test_interval_bad_entries_raise_input_error(text: str, message: str) -> None:
    with pytest.raises(ca.InputError, match=message) as error:
        _interval(text)
    assert "case.json › interval" in str(error.value)
