"""The work behind the assign/fix processes: one scalar variable on nodes or conditions.

Values are written in the steps of an interval; nodal fixity is held from step start to step end.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .. import _core
from ._utilities import ScalarValue, coordinates
from .interval import Interval


class NodalAssignment:
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
        self.model_part = model_part
        self.variable = variable
        self.value = value
        self.interval = interval
        self.constrained = constrained
        self.active = False

    def apply(self) -> None:
        """Fix and assign if TIME is in the interval (ExecuteInitializeSolutionStep)."""
        time = self.model_part.ProcessInfo[_core.TIME]
        if not self.interval.IsInInterval(time):
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


class ConditionAssignment:
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

    def __init__(self, model_part: Any, variable: Any, value: ScalarValue, interval: Interval):
        self.model_part = model_part
        self.variable = variable
        self.value = value
        self.interval = interval

    def apply(self) -> None:
        """Assign if TIME is in the interval (ExecuteInitializeSolutionStep)."""
        time = self.model_part.ProcessInfo[_core.TIME]
        if not self.interval.IsInInterval(time):
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
