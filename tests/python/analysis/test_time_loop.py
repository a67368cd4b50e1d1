"""The time loop: no extra step from round-off, and meaningless step sequences refused up front."""

from __future__ import annotations

import pytest

import contact_app as ca
from contact_app.analysis.time_loop import MAX_STEPS, count_steps, keep_advancing


def _constant(delta: float):  # type: ignore[no-untyped-def]
    return lambda time: delta


@pytest.mark.parametrize(
    ("end", "delta", "steps"),
    [(0.05, 0.005, 10), (1.0, 0.1, 10), (0.3, 0.1, 3), (0.7, 0.01, 70), (0.0501, 0.005, 11)],
)
def test_steps_that_add_up_to_end_time_stop_there(end: float, delta: float, steps: int) -> None:
    assert count_steps(0.0, end, _constant(delta), "here", constant=True) == steps


def test_keep_advancing_tolerates_round_off_only() -> None:
    assert not keep_advancing(0.049999999999999996, 0.05, 0.005)
    assert keep_advancing(0.0499, 0.05, 0.005)
    assert keep_advancing(0.0, 1.0e-12, 0.0)  # before the first step: strict


@pytest.mark.parametrize(
    ("start", "end", "delta", "fragment"),
    [
        (1.0e10, 1.0e10 + 1.0, 1.0e-10, "floating-point resolution of TIME"),
        (0.0, 1.0, 1.0e-9, "1e+09 steps from start_time 0 to end_time 1"),
        (0.0, 1.7e308, 1.5e308, "TIME would become inf"),
    ],
)
def test_meaningless_step_sequences_are_refused(
    start: float, end: float, delta: float, fragment: str
) -> None:
    with pytest.raises(ca.InputError, match="where:    here") as failure:
        count_steps(start, end, _constant(delta), "here", constant=True)
    assert fragment in str(failure.value)


def test_a_table_that_never_reaches_the_end_is_bounded() -> None:
    with pytest.raises(ca.InputError, match=f"more than {MAX_STEPS} steps"):
        count_steps(0.0, 1.0, lambda time: 1.0e-8 if time < 0.5 else 0.1, "here")
