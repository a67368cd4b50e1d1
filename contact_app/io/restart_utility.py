"""Restart files of a model part (Kratos ``RestartUtility``): names, schedule, atomic writes.

The bytes come from the compiled ``ModelPartCheckpoint`` (``io/model_part_checkpoint.h``:
header with magic, format version, payload size and a 64-bit payload hash). A file is written to a
temporary name in the same folder, flushed to disk (``fsync``), then renamed over the final name and
the folder synced, so a kill at any moment leaves either the previous file or the new one, never a
partial one. Loading checks the header and the hash before anything of the model part is touched.

Names follow Kratos: ``<folder>/<base>__restart_files/<base>_<label>.rest``, where the label is the
TIME (``restart_control_type`` "time", printed with 12 significant digits) or the STEP ("step").
"""

from __future__ import annotations

import contextlib
import json
import logging
import os
from pathlib import Path
from typing import Any

import contact_app as ca
from contact_app import _core

logger = logging.getLogger("contact_app.restart")

SERIALIZER_TRACES = ("no_trace", "trace_error", "trace_all")


class RestartUtility:
    """Save and load the restart files of one root model part.

    Args:
        model_part: the root model part written or filled.
        input_filename: base name of the files, possibly with a folder (``"hertz_2d"``).
        restart_load_file_label: label of the file ``LoadRestart`` reads.
        restart_save_frequency: time or step interval between files (0: every step).
        restart_control_type: ``"time"`` or ``"step"``.
        save_restart_files_in_folder: write into ``<base>__restart_files`` (else next to the base).
        load_restart_files_from_folder: read from ``<base>__restart_files`` (else next to the base).
        max_files_to_keep: the newest files kept (-1: all).

    Raises:
        InputError: an unknown control type or a negative frequency.

    """

    def __init__(
        self,
        model_part: ca.ModelPart,
        input_filename: str,
        *,
        restart_load_file_label: str = "",
        restart_save_frequency: float = 0.0,
        restart_control_type: str = "time",
        save_restart_files_in_folder: bool = True,
        load_restart_files_from_folder: bool = True,
        max_files_to_keep: int = -1,
    ) -> None:
        if restart_control_type not in ("time", "step"):
            raise ca.InputError(
                f'restart_control_type "{restart_control_type}" is not one of "time", "step"'
            )
        if not restart_save_frequency >= 0.0:
            raise ca.InputError(f"restart_save_frequency {restart_save_frequency} must be >= 0")
        self.model_part = model_part
        base = Path(input_filename)
        self.base_name = base.name
        self.base_folder = base.parent
        self.load_label = restart_load_file_label
        self.frequency = restart_save_frequency
        self.by_time = restart_control_type == "time"
        if not self.by_time:
            self.frequency = float(int(self.frequency))
        self.save_in_folder = save_restart_files_in_folder
        self.load_from_folder = load_restart_files_from_folder
        self.max_files_to_keep = max_files_to_keep
        self.next_output = self._Control() + self.frequency
        self.written: list[Path] = []

    # -- paths --

    def FileName(self, label: str, *, load: bool = False) -> Path:
        """Path of the restart file with ``label`` (as read when ``load``, else as written)."""
        in_folder = self.load_from_folder if load else self.save_in_folder
        return RestartFile(str(self.base_folder / self.base_name), label, in_folder)

    def _Control(self) -> float:
        info = self.model_part.ProcessInfo
        return float(info[ca.TIME]) if self.by_time else float(info[ca.STEP])

    def CurrentLabel(self) -> str:
        """The label of the current state: TIME to 12 significant digits, or STEP."""
        info = self.model_part.ProcessInfo
        if self.by_time:
            return str(float(f"{info[ca.TIME]:.12g}"))
        return str(int(info[ca.STEP]))

    # -- saving --

    def IsRestartOutputStep(self) -> bool:
        """True when the current TIME (STEP) has reached the next save."""
        return self._Control() >= self.next_output - 1e-9 * max(1.0, abs(self.next_output))

    def SaveRestart(self) -> Path:
        """Write the restart file of the current state atomically; returns its path."""
        path = self.FileName(self.CurrentLabel())
        path.parent.mkdir(parents=True, exist_ok=True)
        WriteAtomically(path, _core.SaveCheckpoint(self.model_part))
        logger.info("restart file written: %s", path)
        current = self._Control()
        if self.frequency > 0.0:
            while self.next_output <= current + 1e-9 * max(1.0, abs(current)):
                self.next_output += self.frequency
        if path not in self.written:
            self.written.append(path)
        if self.max_files_to_keep >= 0:
            while len(self.written) > self.max_files_to_keep:
                with contextlib.suppress(FileNotFoundError):
                    self.written.pop(0).unlink()
        return path

    # -- loading --

    def LoadRestart(self, path: str | os.PathLike[str] | None = None) -> Path:
        """Fill the (empty) model part from a restart file and mark it IS_RESTARTED.

        Raises:
            InputError: missing, truncated, corrupt, other-version or mismatched file (named); the
                model part is then left untouched.

        """
        file = Path(path) if path is not None else self.FileName(self.load_label, load=True)
        Load(self.model_part, file)
        self.model_part.ProcessInfo[ca.IS_RESTARTED] = True
        self.next_output = self._Control() + self.frequency
        return file


def _ProcessKey(index: int, process: Any) -> str:
    kind = type(process)
    return f"{index}:{kind.__module__}.{kind.__qualname__}"


def ProcessStates(processes: list[Any]) -> str:
    """The restart state of every process that has one, as JSON keyed by list position and class.

    Stored in the ProcessInfo (RESTART_PROCESS_STATES) before a restart file is written, so that
    the file carries what the processes keep in Python (output counters, search state).
    """
    states = {}
    for index, process in enumerate(processes):
        state = getattr(process, "GetRestartState", lambda: None)()
        if state is not None:
            states[_ProcessKey(index, process)] = state
    return json.dumps(states, sort_keys=True)


def RestoreProcessStates(processes: list[Any], text: str) -> None:
    """Hand each process of a restarted run the state its counterpart saved (same position, class).

    A process whose saved state is missing (the restarted run lists other processes) resumes from
    the model part alone; its state is ignored with a warning.
    """
    states = json.loads(text) if text else {}
    for index, process in enumerate(processes):
        state = states.pop(_ProcessKey(index, process), None)
        if state is not None:
            process.SetRestartState(state)
    for key in states:
        logger.warning(
            "restart: the saved state of process %s matches no process of this run (the process "
            "lists differ); it is ignored",
            key,
        )


def RestartFile(input_filename: str, label: str, in_folder: bool = True) -> Path:
    """``<base>__restart_files/<base>_<label>.rest`` (next to the base when not ``in_folder``)."""
    base = Path(input_filename)
    folder = base.parent / f"{base.name}__restart_files" if in_folder else base.parent
    return folder / f"{base.name}_{label}.rest"


def WriteAtomically(path: Path, data: bytes) -> None:
    """Write ``data`` to ``path`` so that a crash leaves either the old file or the new one."""
    temporary = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        with open(temporary, "wb") as stream:
            stream.write(data)
            stream.flush()
            os.fsync(stream.fileno())
        os.replace(temporary, path)
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            temporary.unlink()
        raise
    with contextlib.suppress(OSError):
        folder = os.open(path.parent, os.O_RDONLY)
        try:
            os.fsync(folder)
        finally:
            os.close(folder)


def Inspect(path: str | os.PathLike[str]) -> dict[str, Any]:
    """Header and first section of a restart file (version, model part, TIME, STEP), verified."""
    return _core.InspectCheckpoint(_Read(Path(path)), str(path))


def Load(model_part: ca.ModelPart, path: str | os.PathLike[str]) -> None:
    """Rebuild ``model_part`` (an empty root of the saved name) from the restart file ``path``."""
    _core.LoadCheckpoint(model_part, _Read(Path(path)), str(path))


def _Read(path: Path) -> bytes:
    if not path.is_file():
        raise ca.InputError(
            f'restart file "{path}" does not exist or is not a regular file'
            "\n  fix: check restart_load_file_label (the TIME or STEP label of a written file) and"
            " input_filename (the base name of the restart files)"
        )
    return path.read_bytes()
