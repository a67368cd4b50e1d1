"""Output paths checked at set-up: never one of the run's inputs, and a folder that can be written.

An output process writes its first file before the first step (``json_output_process``) or after
it (``vtk_output_process``); a path that is one of the run's inputs would overwrite it silently,
and a folder that cannot be created would be found only after the work. :func:`CheckOutputs`
looks at every output path of the process lists when the analysis is created, before the mesh is
read, and so does the copy of the parameters written when ``echo_level`` > 1 (never over an input,
and no output file written by two writers). Output paths outside the case folder stay allowed
(the summary lists the files written).
"""

from __future__ import annotations

import os
from pathlib import Path

from .._core import InputError
from ..json_input import quote
from ..parameters import Parameters
from .paths import PathResolver
from .process_factory import INPUT_PATH_KEYS

#: Keys of process ``Parameters`` that name an output file, and those that name a folder.
FILE_KEYS = ("output_file_name",)
FOLDER_KEYS = ("output_path", "folder_name")
#: Written to the working folder by ``Initialize`` when ``problem_data.echo_level`` > 1.
PARAMETERS_ECHO = "ProjectParametersOutput.json"


def _same(first: str, second: str) -> bool:
    try:
        return os.path.samefile(first, second)
    except OSError:
        return os.path.realpath(first) == os.path.realpath(second)


def _unwritable(folder: Path) -> str | None:
    """Why files cannot be created in ``folder`` (created on demand), or None."""
    probe = folder
    while not os.path.lexists(probe) and probe.parent != probe:
        probe = probe.parent
    if not probe.is_dir():
        return f'"{quote(str(probe))}" is a file, not a folder'
    if not os.access(probe, os.W_OK | os.X_OK):
        return f'the folder "{quote(str(probe))}" is not writable'
    return None


def _outputs(settings: Parameters) -> list[tuple[str, str, bool]]:
    """(key, value, is a folder) of every output path of one process's Parameters."""
    found = []
    in_folder = not (
        settings.Has("save_output_files_in_folder")
        and settings["save_output_files_in_folder"].IsBool()
        and not settings["save_output_files_in_folder"].GetBool()
    )
    for key in FILE_KEYS + FOLDER_KEYS:
        if settings.Has(key) and settings[key].IsString() and settings[key].GetString():
            is_folder = key in FOLDER_KEYS
            if not is_folder or in_folder:
                found.append((key, settings[key].GetString(), is_folder))
    return found


def _process_settings(parameters: Parameters, list_keys: tuple[str, ...]) -> list[Parameters]:
    found = []
    for list_key in list_keys:
        if not parameters.Has(list_key):
            continue
        for process_list in parameters[list_key].values():
            for item in process_list:
                if item.IsSubParameter() and item.Has("Parameters"):
                    if item["Parameters"].IsSubParameter():
                        found.append(item["Parameters"])
    return found


def CheckOutputs(
    parameters: Parameters,
    list_keys: tuple[str, ...],
    paths: PathResolver,
    inputs: list[tuple[str, str]],
) -> None:
    """Refuse an output path that is an input of the run, or that cannot be written.

    Args:
        parameters: the whole parameters tree.
        list_keys: the top-level keys holding process lists.
        paths: how the relative paths resolve.
        inputs: (path, where it is named) of the solver's inputs and the parameters file; the
            processes' own input files (``input_file_name``) are added here.

    Raises:
        InputError: naming the output key and the input key, or the output key and the reason
            its folder cannot be written.

    """
    every_input = list(inputs)
    processes = _process_settings(parameters, list_keys)
    for settings in processes:
        for key in INPUT_PATH_KEYS:
            if settings.Has(key) and settings[key].IsString() and settings[key].GetString():
                try:
                    path = paths.input_path(settings[key].GetString(), settings.Where(key))
                except InputError:
                    continue  # reported with its own message when the process is created
                every_input.append((path, settings.Where(key)))
    # (where, value as written, resolved path, is a folder) of every output of the run.
    outputs = [
        (settings.Where(key), value, paths.output_path(value), is_folder)
        for settings in processes
        for key, value, is_folder in _outputs(settings)
    ]
    outputs += _parameters_echo(parameters)
    written: dict[str, str] = {}
    for where, value, resolved, is_folder in outputs:
        for path, input_where in every_input:
            if not is_folder and _same(resolved, path):
                raise InputError(
                    f'the output file "{quote(value)}" is an input of this run\n'
                    f"  where:    {where}\n"
                    f"  input:    {input_where}\n"
                    "  expected: outputs that never overwrite the run's inputs\n"
                    "  fix:      give the output another file name"
                )
        if not is_folder:
            for other, other_where in written.items():
                if _same(resolved, other) or os.path.abspath(resolved) == os.path.abspath(other):
                    raise InputError(
                        f'the output file "{quote(value)}" is written twice\n'
                        f"  where:    {other_where}\n"
                        f"  and:      {where}\n"
                        "  expected: one writer per output file (the last one would win)\n"
                        "  fix:      give one of the outputs another file name"
                    )
            written[resolved] = where
        folder = Path(resolved) if is_folder else Path(resolved).parent
        if not is_folder and Path(resolved).is_dir():
            problem: str | None = f'"{quote(value)}" is a folder, not a file'
        else:
            problem = _unwritable(folder)
        if problem is not None:
            raise InputError(
                f'the output {"folder" if is_folder else "file"} "{quote(value)}" cannot '
                f"be written: {problem}\n"
                f"  where:    {where}\n"
                "  expected: a path whose folder exists or can be created, and is writable\n"
                "  fix:      choose another output path"
            )


def _parameters_echo(parameters: Parameters) -> list[tuple[str, str, str, bool]]:
    """The copy of the parameters that Initialize writes when echo_level > 1 (as Kratos does)."""
    if not parameters.Has("problem_data"):
        return []
    problem_data = parameters["problem_data"]
    if not (
        problem_data.Has("echo_level")
        and problem_data["echo_level"].IsInt()
        and problem_data["echo_level"].GetInt() > 1
    ):
        return []
    where = f"{problem_data.Where('echo_level')} (> 1: written to the working folder)"
    return [(where, PARAMETERS_ECHO, os.path.abspath(PARAMETERS_ECHO), False)]
