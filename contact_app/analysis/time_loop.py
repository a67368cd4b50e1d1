"""The time loop's rule and its check before a run: when to stop, and whether the steps make sense.

The loop advances while :func:`keep_advancing` holds. It compares with a tolerance relative to
the step because the times are sums of steps in floating point: ten steps of 0.005 add up to
0.049999999999999996, and a strict ``time < end_time`` would then run an eleventh step to 0.055.

:func:`count_steps` walks the same times without solving, before the mesh is read, and refuses a
time step that makes TIME non-finite, a step that TIME cannot resolve (``start_time`` 1e10 with
``time_step`` 1e-10 never advances) and more than :data:`MAX_STEPS` steps.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from .._core import InputError

#: Most steps a run may have (10^9 steps of 1e-9 would run for days without a word).
MAX_STEPS = 10_000_000
#: A remainder below this fraction of the step is round-off, not a step still to take.
END_TOLERANCE = 1.0e-6
#: Largest relative error of a step allowed by the floating-point resolution of TIME.
RESOLUTION = 1.0e-6


def keep_advancing(time: float, end_time: float, delta: float) -> bool:
    """True while ``time`` is before ``end_time`` by more than round-off of the step ``delta``."""
    return time < end_time - END_TOLERANCE * abs(delta)


def count_steps(
    start: float,
    end: float,
    delta_at: Callable[[float], float],
    where: str,
    *,
    constant: bool = False,
) -> int:
    """Return the number of steps from ``start`` to ``end``, checking every step.

    Args:
        start: start_time.
        end: end_time.
        delta_at: the time step taken from a time (the solver's time stepping).
        where: the time_stepping settings, for messages.
        constant: the step is the same at every time: the steps are then checked where TIME is
            largest in magnitude (where its resolution is coarsest) and counted in closed form.

    Raises:
        InputError: TIME becomes non-finite, a step is lost in the resolution of TIME, or the
            count exceeds :data:`MAX_STEPS`.

    """
    if constant:
        delta = delta_at(start)
        for time in (start, end):  # the resolution of TIME is coarsest at one of the ends
            _check_step(time, delta, where)
        ratio = (end - start) / delta
        _check_count(ratio, start, end, delta, where, constant)
        return max(math.ceil(ratio - END_TOLERANCE), 0)
    time, delta, count = start, 0.0, 0
    while keep_advancing(time, end, delta):
        delta = delta_at(time)
        _check_step(time, delta, where)
        time, count = time + delta, count + 1
        _check_count(count, start, end, delta, where, constant)
    return count


def _check_step(time: float, delta: float, where: str) -> None:
    """Refuse a step from ``time`` that overflows or that TIME cannot resolve."""
    following = time + delta
    if not math.isfinite(following):
        raise InputError(
            f"TIME would become {following} (TIME {time:.12g} + time step {delta:g})\n"
            f"  where:    {where}\n"
            "  expected: times and steps whose sums stay finite doubles\n"
            "  fix:      check the magnitudes of start_time, end_time and the time step"
        )
    if abs((following - time) - delta) > RESOLUTION * delta:
        raise InputError(
            f"the time step {delta:g} is below the floating-point resolution of TIME near "
            f"{time:.12g} (TIME + Δt = {following!r}): the time would not advance as written\n"
            f"  where:    {where}\n"
            f"  expected: a step larger than {math.ulp(time) / RESOLUTION:.3g} at this time\n"
            "  fix:      start the analysis nearer to 0 (shift start_time and end_time) or "
            "use a larger time step"
        )


def _check_count(
    count: float, start: float, end: float, delta: float, where: str, constant: bool
) -> None:
    """Refuse more than MAX_STEPS steps, naming the numbers."""
    if count > MAX_STEPS:
        steps = f"{count:.3g} steps" if constant else f"more than {MAX_STEPS} steps"
        raise InputError(
            f"{steps} from start_time {start:.12g} to end_time {end:.12g} with time step "
            f"{delta:g}{'' if constant else ' (from the time step table or intervals)'}\n"
            f"  where:    {where}\n"
            f"  expected: at most {MAX_STEPS} steps\n"
            "  fix:      use a larger time step or a shorter interval"
        )
