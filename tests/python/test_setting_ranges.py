"""Numeric settings: every number a schema reads is finite and in the range of its key."""

from __future__ import annotations

import math

import pytest

import contact_app as ca
from contact_app.parameters import Parameters
from contact_app.setting_ranges import range_of


@pytest.mark.parametrize(
    ("key", "value", "fragment"),
    [
        ("time_step", -0.1, "a number > 0"),
        ("split_factor", 1.0, "a number > 1"),
        ("max_number_splits", 0, "a number ≥ 1"),
        ("residual_absolute_tolerance", -1e-9, "a number ≥ 0"),
        ("penalty", -5.0, "a number ≥ 0"),
        ("scale_factor", 0.0, "a number > 0"),
        ("damp_factor_m", 0.5, "a number in [-1, 0]"),
    ],
)
def test_out_of_range_numbers_name_the_path_and_range(
    key: str, value: float, fragment: str
) -> None:
    p = Parameters({"block": {key: value}}, "case.json")
    with pytest.raises(ca.InputError, match="out of range") as failure:
        p["block"].ValidateAndAssignDefaults({key: 0.5})
    assert f"case.json › block › {key}" in str(failure.value)
    assert fragment in str(failure.value)


@pytest.mark.parametrize("value", [math.nan, math.inf, -math.inf])
def test_non_finite_numbers_built_in_python_are_refused(value: float) -> None:
    p = Parameters({"value": value, "time_step": value}, "<parameters>")
    with pytest.raises(ca.InputError, match="finite"):
        p.ValidateAndAssignDefaults({"value": 0.0, "time_step": 1.0})
    for getter in (lambda: p["value"].GetDouble(), lambda: Parameters([[0.0, value]]).GetMatrix()):
        with pytest.raises(ca.InputError, match="not finite"):
            getter()


def test_entries_of_friction_coefficients_must_not_be_negative() -> None:
    p = Parameters({"friction_coefficients": {"0": -0.5}}, "case.json")
    with pytest.raises(ca.InputError, match="friction coefficient"):
        p["friction_coefficients"].ValidateAndAssignDefaults({"0": 0.0})
    assert range_of("value", None) is None  # loads keep any sign
