"""The work behind the assign/fix processes: one scalar variable on nodes or conditions.

Values are written in the steps of an interval; nodal fixity is held from step start to step end.
``read_target`` reads the keys every assign/fix process shares; ``NodalAssignmentProcess`` and
``ConditionAssignmentProcess`` run the assignments in the Kratos hooks.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, Generic, NamedTuple, TypeVar

import numpy as np

from .. import _core
from .._core import Model
from ..parameters import Parameters
from ._utilities import (
    ScalarValue,
    array_components,
    check_historical,
    coordinates,
    get_variable,
    model_part_of,
)
from .interval import Interval
from .process import Process


class Target(NamedTuple):
    """What an assign/fix process acts on, and where its variable is named (for messages)."""

    model_part: Any
    variable: Any
    where: str

    def components(self) -> list[Any]:
        """The ``_X, _Y, _Z`` component variables of a 3-vector variable."""
        return array_components(self.variable, self.where)


def read_target(
    model: Model, settings: Parameters, kinds: Sequence[str], historical: bool
) -> Target:
    """Return the model part and variable that validated ``settings`` name.

    Args:
        model: the model holding the model part.
        settings: the ``Parameters`` block, validated against the process' DEFAULTS.
        kinds: accepted variable kinds (``SCALAR_KINDS`` or ``("Array",)``).
        historical: the variable must be a solution-step variable (nodal values are written).

    Raises:
        InputError: unknown model part or variable; a variable of another kind; a variable not
            stored historically while ``historical``.
    """
    model_part = model_part_of(model, settings)
    where = settings.Where("variable_name")
    variable = get_variable(settings["variable_name"].GetString(), where, kinds)
    if historical:
        check_historical(model_part, variable, where)
    return Target(model_part, variable, where)


class _Assignment:
    """One variable, one value and the interval it is written in (the shared part of both kinds)."""

    def __init__(
        self, model_part: Any, variable: Any, value: ScalarValue | None, interval: Interval
    ) -> None:
        self.model_part = model_part
        self.variable = variable
        self.value = value
        self.interval = interval

    def apply(self) -> None:
        """Act if TIME is in the interval (ExecuteInitializeSolutionStep)."""
        raise NotImplementedError(f"{type(self).__name__} must implement apply")

    def _time_in_interval(self) -> float | None:
        """TIME of the model part if it lies in the interval, else None."""
        time = self.model_part.ProcessInfo[_core.TIME]
        return time if self.interval.IsInInterval(time) else None


class NodalAssignment(_Assignment):
    """Assign (and optionally fix) one double or component variable on every node of a part.

    In a step whose TIME lies in ``interval``, :meth:`apply` fixes the DoF on every node if
    ``constrained`` (adding the DoF if needed) and writes the historical value (buffer step 0);
    :meth:`release` frees the DoFs it fixed. Outside the interval nothing is touched.

    Args:
        model_part: the nodes' model part.
        variable: a double or component variable (historical).
        value: what to write; None only fixes/frees (``fix_*_variable_process``).
        interval: when to act.
        constrained: fix the DoF from :meth:`apply` to :meth:`release`.
    """

    def __init__(
        self,
        model_part: Any,
        variable: Any,
        value: ScalarValue | None,
        interval: Interval,
        constrained: bool,
    ) -> None:
        super().__init__(model_part, variable, value, interval)
        self.constrained = constrained
        self.active = False

    def apply(self) -> None:
        """Fix and assign if TIME is in the interval (ExecuteInitializeSolutionStep)."""
        time = self._time_in_interval()
        if time is None:
            return
        self.active = True
        nodes = list(self.model_part.Nodes)
        if self.constrained:
            for node in nodes:
                node.Fix(self.variable)
        if self.value is None:
            return
        if self.value.depends_on_space:
            values = self.value.at_points(time, *coordinates(nodes))
        else:
            values = np.full(len(nodes), self.value.at_time(time))
        variable = self.variable
        for node, value in zip(nodes, values.tolist(), strict=True):
            node.SetSolutionStepValue(variable, 0, value)

    def release(self) -> None:
        """Free the DoFs fixed in this step (ExecuteFinalizeSolutionStep)."""
        if self.active and self.constrained:
            for node in self.model_part.Nodes:
                node.Free(self.variable)
        self.active = False


class ConditionAssignment(_Assignment):
    """Assign one double or component variable as the (non-historical) value of every condition.

    In a step whose TIME lies in ``interval``, :meth:`apply` writes ``condition.SetValue``; a
    spatial function is evaluated at the condition's centre (mean of its nodes, current and initial
    coordinates). Values persist after the interval.

    Args:
        model_part: the conditions' model part.
        variable: a double or component variable.
        value: what to write.
        interval: when to act.
    """

    value: ScalarValue

    def __init__(self, model_part: Any, variable: Any, value: ScalarValue, interval: Interval):
        super().__init__(model_part, variable, value, interval)

    def apply(self) -> None:
        """Assign if TIME is in the interval (ExecuteInitializeSolutionStep)."""
        time = self._time_in_interval()
        if time is None:
            return
        conditions = list(self.model_part.Conditions)
        if self.value.depends_on_space:
            current = np.zeros((len(conditions), 3))
            initial = np.zeros((len(conditions), 3))
            for i, condition in enumerate(conditions):
                node_current, node_initial = coordinates(condition.GetNodes())
                current[i] = node_current.mean(axis=0)
                initial[i] = node_initial.mean(axis=0)
            values = self.value.at_points(time, current, initial)
        else:
            values = np.full(len(conditions), self.value.at_time(time))
        for condition, value in zip(conditions, values.tolist(), strict=True):
            condition.SetValue(self.variable, value)


AssignmentKind = TypeVar("AssignmentKind", bound=_Assignment)


class _AssignmentProcess(Process, Generic[AssignmentKind]):
    """Applies its assignments at every step start (the shared part of both processes).

    Args:
        assignments: the assignments, one per variable component.
    """

    def __init__(self, assignments: list[AssignmentKind]) -> None:
        self.assignments = assignments

    def ExecuteInitializeSolutionStep(self) -> None:
        """Apply every assignment if TIME is in its interval."""
        for assignment in self.assignments:
            assignment.apply()


class NodalAssignmentProcess(_AssignmentProcess[NodalAssignment]):
    """Runs nodal assignments: at the start time, at every step start, released at step end."""

    def ExecuteBeforeSolutionLoop(self) -> None:
        """Apply at the start time too."""
        self.ExecuteInitializeSolutionStep()

    def ExecuteFinalizeSolutionStep(self) -> None:
        """Free the DoFs fixed in this step."""
        for assignment in self.assignments:
            assignment.release()


class ConditionAssignmentProcess(_AssignmentProcess[ConditionAssignment]):
    """Runs condition assignments at every step start (the values persist after the interval)."""
