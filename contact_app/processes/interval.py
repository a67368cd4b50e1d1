"""The ``interval`` of a process: ``[begin, end]`` in TIME (Kratos ``IntervalUtility``)."""

from __future__ import annotations

from .._core import InputError
from ..parameters import Parameters

#: What ``"End"`` stands for (Kratos converts it to 1e30 too).
END_OF_TIME = 1.0e30


class Interval:
    """A time interval with Kratos' tolerance.

    A time ``t`` is inside iff ``begin - eps < t < end + eps`` with
    ``eps = max(1e-14 * begin, 1e-30)`` (Kratos ``IntervalUtility``, reproduced exactly). The begin
    is always inside. The end is inside only when ``eps`` is resolvable at ``end``: with
    ``begin = 0`` the tolerance is 1e-30, so ``t == end`` is **outside** for any end above ~1e-14
    (``[0.0, 1.0]`` does not act at t = 1.0, while ``[0.5, 1.0]`` does). ``"End"`` (1e30) has no
    such issue.

    Args:
        begin: first time at which the process acts.
        end: last time at which the process acts.
    """

    def __init__(self, begin: float = 0.0, end: float = END_OF_TIME) -> None:
        self.begin = float(begin)
        self.end = float(end)

    @classmethod
    def from_parameters(cls, interval: Parameters) -> Interval:
        """Read ``[begin, end]``; ``end`` may be ``"End"``.

        Raises:
            InputError: not two entries, a string other than "End", or ``end < begin``.
        """
        where = interval.Where()
        fix = 'write [begin, end] with numbers, e.g. [0.0, "End"] or [0.0, 1.0]'
        if not interval.IsArray() or interval.size() != 2:
            raise InputError(
                f"the interval {interval.WriteJsonString()} does not have two entries\n"
                f"  where:    {where}\n  expected: [begin, end]\n  fix:      {fix}"
            )
        if not interval[0].IsNumber():
            raise InputError(
                f"the interval begins with {interval[0].WriteJsonString()}\n"
                f"  where:    {where}\n  expected: a number\n  fix:      {fix}"
            )
        begin = interval[0].GetDouble()
        last = interval[1]
        if last.IsString() and last.GetString() == "End":
            end = END_OF_TIME
        elif last.IsNumber():
            end = last.GetDouble()
        else:
            raise InputError(
                f"the interval ends with {last.WriteJsonString()}\n"
                f'  where:    {where}\n  expected: a number or "End"\n  fix:      {fix}'
            )
        if end < begin:
            raise InputError(
                f"the interval [{begin:g}, {end:g}] ends before it begins\n"
                f"  where:    {where}\n  expected: begin <= end\n  fix:      swap the entries"
            )
        return cls(begin, end)

    def IsInInterval(self, time: float) -> bool:
        """True if ``time`` lies in the interval (both ends included, with a relative tolerance)."""
        eps = max(1.0e-14 * self.begin, 1.0e-30)
        return self.begin - eps < time < self.end + eps

    def __contains__(self, time: float) -> bool:
        return self.IsInInterval(time)

    def __repr__(self) -> str:
        end = '"End"' if self.end >= END_OF_TIME else f"{self.end:g}"
        return f"Interval([{self.begin:g}, {end}])"
