"""Base classes of every process: the Kratos life-cycle hooks (``Process``, ``OutputProcess``).

The analysis calls the hooks in this order (``docs/input_layer.md`` §1): ``ExecuteInitialize``
and ``Check`` once, ``ExecuteBeforeSolutionLoop`` once, then per step
``ExecuteInitializeSolutionStep`` → solve → ``ExecuteFinalizeSolutionStep``, then
``ExecuteBeforeOutputStep`` / ``PrintOutput`` / ``ExecuteAfterOutputStep`` when some output process
reports ``IsOutputStep()``, and ``ExecuteFinalize`` at the end.

Restart (contact_app's own, not Kratos'): ``GetRestartState`` returns what a process keeps between
steps in Python (counters, schedules), JSON-serialisable; the analysis stores it in each restart
file and hands it back to ``SetRestartState`` of the same process of the restarted run, after
``ExecuteInitialize`` and before ``ExecuteBeforeSolutionLoop``.
"""

from __future__ import annotations

from typing import Any


class Process:
    """A process with every hook a no-op; subclasses override what they need."""

    def ExecuteInitialize(self) -> None:
        """Called once, after the model part is read and before the solver is initialised."""

    def ExecuteBeforeSolutionLoop(self) -> None:
        """Called once, after the solver is initialised and before the first step."""

    def ExecuteInitializeSolutionStep(self) -> None:
        """Called at the start of every step (TIME is already the new time)."""

    def ExecuteFinalizeSolutionStep(self) -> None:
        """Called at the end of every step, after the solver has finished it."""

    def ExecuteBeforeOutputStep(self) -> None:
        """Called before the output processes print, in steps that produce output."""

    def ExecuteAfterOutputStep(self) -> None:
        """Called after the output processes have printed."""

    def ExecuteFinalize(self) -> None:
        """Called once at the end of the analysis."""

    def Execute(self) -> None:
        """Do the process' work once (Kratos' generic entry point)."""

    def Check(self) -> None:
        """Check the settings against the model; raise InputError if something is wrong."""

    def GetRestartState(self) -> dict[str, Any] | None:
        """What a restart needs of this process beyond the model part (None: nothing)."""
        return None

    def SetRestartState(self, state: dict[str, Any]) -> None:
        """Take back the state ``GetRestartState`` gave when the restart file was written."""


class OutputProcess(Process):
    """A process that writes results; the analysis asks ``IsOutputStep``, calls ``PrintOutput``."""

    def IsOutputStep(self) -> bool:
        """True if this step should be written."""
        raise NotImplementedError(f"{type(self).__name__} must implement IsOutputStep")

    def PrintOutput(self) -> None:
        """Write the results of the current step."""
        raise NotImplementedError(f"{type(self).__name__} must implement PrintOutput")
