"""The committed type stubs of the compiled module match what pybind11-stubgen writes for it."""

from __future__ import annotations

import filecmp
import importlib.util
import os
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
SCRIPT = REPO / "scripts" / "generate_stubs.sh"
COMMITTED = REPO / "contact_app" / "_core"


def _differences(left: Path, right: Path) -> list[str]:
    """Relative paths of the files that are in one tree only or differ between the two."""
    comparison = filecmp.dircmp(left, right)
    names = [*comparison.left_only, *comparison.right_only, *comparison.diff_files]
    names += filecmp.cmpfiles(left, right, comparison.common_files, shallow=False)[1]
    for sub in comparison.common_dirs:
        names += [f"{sub}/{name}" for name in _differences(left / sub, right / sub)]
    return sorted(set(names))


def test_core_stubs_are_up_to_date(tmp_path: Path) -> None:
    if importlib.util.find_spec("pybind11_stubgen") is None:
        pytest.skip("pybind11-stubgen is not installed (scripts/bootstrap.sh installs it)")
    result = subprocess.run(
        ["bash", str(SCRIPT), str(tmp_path)],
        capture_output=True,
        text=True,
        env={**os.environ, "PYTHON": sys.executable},
        check=False,
    )
    assert result.returncode == 0, f"{SCRIPT.name} failed:\n{result.stdout}{result.stderr}"
    differences = _differences(COMMITTED, tmp_path / "contact_app" / "_core")
    assert not differences, (
        f"stubs out of date: run `bash scripts/generate_stubs.sh` (differing: {differences})"
    )
