"""Fixtures of the analysis tests: the data cases copied to a temporary folder."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
from analysis_cases import DATA, bar_dynamic_results, plate_static_results


@pytest.fixture
def case_dir(tmp_path: Path) -> Path:
    """The data cases with their reference results, in ``tmp_path/case``."""
    target = tmp_path / "case"
    shutil.copytree(DATA, target)
    (target / "plate_static_results.json").write_text(json.dumps(plate_static_results([0.5, 1.0])))
    (target / "bar_dynamic_results.json").write_text(json.dumps(bar_dynamic_results()))
    return target


@pytest.fixture
def in_tmp(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """Run the test with ``tmp_path`` as working directory."""
    monkeypatch.chdir(tmp_path)
    return tmp_path
