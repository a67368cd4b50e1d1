"""Shared checks: messages quote user values briefly and escaped."""

from __future__ import annotations

import pytest

import contact_app as ca
from contact_app.analysis.validation import choice
from contact_app.parameters import Parameters


def test_choice_quotes_a_huge_value_briefly_with_nul_escaped() -> None:
    settings = Parameters({"analysis_type": "z" * 20_000 + "\x00"}, "case.json")
    with pytest.raises(ca.InputError, match="unknown analysis_type") as failure:
        choice(settings, "analysis_type", ("linear", "non_linear"))
    message = str(failure.value)
    assert len(message) < 600 and "\x00" not in message
    assert "case.json › analysis_type" in message
