"""``python -m contact_app`` in a child process, for the command-line tests.

On ``sys.path`` for the tests through pytest's ``pythonpath`` (pyproject.toml).
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path


def run_cli(
    *args: str, cwd: Path | None, timeout: float | None = 60.0
) -> subprocess.CompletedProcess[str]:
    """``python -m contact_app <args>`` in ``cwd`` (None: this process's), output captured.

    The child sees this process's ``sys.path``, so it imports the same contact_app.
    """
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if p))
    return subprocess.run(
        [sys.executable, "-m", "contact_app", *args],
        cwd=cwd,
        capture_output=True,
        text=True,
        env=env,
        timeout=timeout,
        check=False,
    )
