"""Relative paths written in a settings file: the working directory first, then the file's folder.

Kratos opens every relative path (``input_filename``, ``materials_filename``, the json
``input_file_name``, ``output_path`` ...) against the working directory, and its test suites run
with the working directory set to the folder of the settings file. ``contact-app run`` keeps that
rule and adds one fallback so that a case runs from anywhere: when an input path does not exist
relative to the working directory, it is looked up relative to the folder of the
``ProjectParameters.json`` and then relative to each of that folder's ancestors (nearest first), so
a Kratos test case, whose paths start from the suite's ``tests/`` folder, also runs when named from
elsewhere. Outputs (files or folders that may not exist yet) go to the working directory unless
only the settings file's folder has their parent directory.
"""

from __future__ import annotations

from pathlib import Path

from .._core import InputError
from ..json_input import not_regular, quote


def _regular(path: str, where: str, what: str) -> str:
    if not Path(path).is_file():
        raise not_regular(path, what, where)
    return path


class PathResolver:
    """Resolve the relative paths of one settings file.

    Args:
        base_dir: folder of the settings file, or None for settings built in memory (then paths
            resolve against the working directory only).

    """

    def __init__(self, base_dir: str | Path | None = None):
        self.base_dir = Path(base_dir).resolve() if base_dir is not None else None

    def _fallback_dir(self, path: Path) -> Path | None:
        """The settings file's folder if a relative path is also looked up there, else None."""
        if path.is_absolute() or self.base_dir is None or self.base_dir == Path.cwd():
            return None
        return self.base_dir

    def input_path(self, value: str, where: str, what: str = "file") -> str:
        """Return the path of an existing input file.

        Args:
            value: the path as written in the settings.
            where: its location in the settings, for the message.
            what: what the file is ("mdpa file", "materials file", ...), for the message.

        Returns:
            ``value`` itself when it exists relative to the working directory (or is absolute and
            exists), else the path inside the settings file's folder.

        Raises:
            InputError: the file exists in neither place, or is not a regular file (a folder,
                a device such as /dev/zero or a FIFO would be read forever or as nothing).

        """
        path = Path(value)
        if path.exists():
            return _regular(value, where, what)
        looked = [str(path.resolve())]
        base_dir = self._fallback_dir(path)
        if base_dir is not None:
            folders = [base_dir, *base_dir.parents]
            for folder in folders:
                candidate = folder / path
                if candidate.exists():
                    return _regular(str(candidate), where, what)
            looked.append(str(base_dir / path) + " (and the same below its parent folders)")
        raise InputError(
            f'{what} "{quote(value)}" not found\n  where:    {where}\n'
            f"  expected: an existing file; looked for {' and '.join(looked)}\n"
            "  fix:      correct the path (relative paths start from the working directory, "
            "then from the folder of the parameters file)"
        )

    def output_path(self, value: str) -> str:
        """Return where an output file or folder goes.

        The working directory is used when the path or its parent exists there; the settings
        file's folder when only it has them; otherwise the working directory (the writer creates
        the folders).
        """
        path = Path(value)
        base_dir = self._fallback_dir(path)
        if base_dir is None:
            return value
        candidate = base_dir / path
        here_ok = path.exists() or path.parent.exists()
        there_ok = candidate.exists() or candidate.parent.exists()
        if not here_ok and there_ok:
            return str(candidate)
        return value
