"""The command line: ``contact-app info`` / ``python -m contact_app`` exit codes and output."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import contact_app as ca
from contact_app import cli

SMALL_MDPA = """\
Begin ModelPartData
End ModelPartData

Begin Properties 1
    YOUNG_MODULUS 210e9
End Properties

Begin Nodes
    1 0.0 0.0 0.0
    2 1.0 0.0 0.0
    3 1.0 1.0 0.0
    4 0.0 1.0 0.0
    5 2.0 0.0 0.0
    6 2.0 1.0 0.0
End Nodes

Begin Elements Element2D4N // two quadrilaterals
    1 1 1 2 3 4
    2 1 2 5 6 3
End Elements

Begin Conditions LineCondition2D2N
    1 1 1 2
    2 1 2 5
End Conditions

Begin Conditions PointCondition2D1N
    3 1 6
End Conditions

Begin SubModelPart Contact
    Begin SubModelPartNodes
        1
        2
    End SubModelPartNodes
    Begin SubModelPartConditions
        1
    End SubModelPartConditions
End SubModelPart
"""

MALFORMED_MDPA = "Begin Nodes\n    1 0.0 0.0\nEnd Nodes\n"


@pytest.fixture
def small_mdpa(tmp_path: Path) -> Path:
    path = tmp_path / "small.mdpa"
    path.write_text(SMALL_MDPA)
    return path


@pytest.fixture
def malformed_mdpa(tmp_path: Path) -> Path:
    path = tmp_path / "malformed.mdpa"
    path.write_text(MALFORMED_MDPA)
    return path


def _run_module(*args: str) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(path for path in sys.path if path))
    return subprocess.run(
        [sys.executable, "-m", "contact_app", *args],
        capture_output=True,
        text=True,
        env=env,
        check=False,
    )


def test_cli_info_prints_tree_and_type_counts(
    small_mdpa: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert cli.main(["info", str(small_mdpa)]) == 0
    out = capsys.readouterr().out
    assert "ModelPart Structure: 6 nodes, 2 elements, 3 conditions" in out
    assert "  ModelPart Structure.Contact: 2 nodes, 0 elements, 1 conditions" in out
    assert "elements by type:\n  Element2D4N: 2\n" in out
    assert "conditions by type:\n  LineCondition2D2N: 2\n  PointCondition2D1N: 1\n" in out
    assert f"read {small_mdpa} in " in out


def test_cli_info_accepts_the_name_without_extension(
    small_mdpa: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert cli.main(["info", str(small_mdpa.with_suffix(""))]) == 0
    assert "6 nodes" in capsys.readouterr().out


def test_cli_python_m_info_exits_zero(small_mdpa: Path) -> None:
    result = _run_module("info", str(small_mdpa))
    assert result.returncode == 0, result.stderr
    assert "Element2D4N: 2" in result.stdout


@pytest.mark.skipif(shutil.which("contact-app") is None, reason="console script not installed")
def test_cli_console_script_info_exits_zero(small_mdpa: Path) -> None:
    result = subprocess.run(
        ["contact-app", "info", str(small_mdpa)], capture_output=True, text=True, check=False
    )
    assert result.returncode == 0, result.stderr
    assert "conditions by type:" in result.stdout


def test_cli_info_malformed_file_exits_two_without_traceback(malformed_mdpa: Path) -> None:
    result = _run_module("info", str(malformed_mdpa))
    assert result.returncode == 2
    assert result.stderr.startswith("error: ")
    assert "malformed.mdpa:2" in result.stderr
    assert "Traceback" not in result.stderr
    assert result.stdout == ""


def test_cli_info_missing_file_exits_two(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert cli.main(["info", str(tmp_path / "nothing")]) == 2
    assert capsys.readouterr().err.startswith("error: cannot open")


@pytest.mark.parametrize("argv", [["--debug", "info"], ["info", "--debug"]])
def test_cli_debug_reraises(malformed_mdpa: Path, argv: list[str]) -> None:
    with pytest.raises(ca.InputError, match="malformed.mdpa:2"):
        cli.main([*argv, str(malformed_mdpa)])


def test_cli_run_is_not_available_yet(capsys: pytest.CaptureFixture[str]) -> None:
    assert cli.main(["run", "ProjectParameters.json"]) == 2
    assert "not available yet" in capsys.readouterr().err


def test_cli_without_command_is_a_usage_error() -> None:
    with pytest.raises(SystemExit) as exit_info:
        cli.main([])
    assert exit_info.value.code == 2


def test_cli_count_entity_types_ignores_comments_and_sub_model_parts(small_mdpa: Path) -> None:
    counts = cli.count_entity_types(str(small_mdpa))
    assert counts["Elements"] == {"Element2D4N": 2}
    assert counts["Conditions"] == {"LineCondition2D2N": 2, "PointCondition2D1N": 1}
