"""Relative paths: working directory first, then the folder of the parameters file."""

from __future__ import annotations

from pathlib import Path

import pytest

import contact_app as ca
from contact_app.analysis import PathResolver


@pytest.fixture
def layout(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """tmp_path (cwd) holds here.txt and out/; tmp_path/case holds case.txt, here.txt and sub/."""
    case = tmp_path / "case"
    (case / "sub").mkdir(parents=True)
    (case / "case.txt").write_text("")
    (case / "here.txt").write_text("")
    (tmp_path / "here.txt").write_text("")
    (tmp_path / "out").mkdir()
    monkeypatch.chdir(tmp_path)
    return case


def test_inputs(layout: Path) -> None:
    paths = PathResolver(layout)
    assert paths.input_path("here.txt", "w") == "here.txt"  # the working directory wins
    assert paths.input_path("case.txt", "w") == str(layout / "case.txt")
    absolute = str(layout / "case.txt")
    assert paths.input_path(absolute, "w") == absolute
    with pytest.raises(
        ca.InputError, match="looked for .*missing.txt and .*case/missing.txt"
    ) as failure:
        paths.input_path("missing.txt", "file.json › a", "mdpa file")
    assert 'mdpa file "missing.txt" not found' in str(failure.value)
    assert "where:    file.json › a" in str(failure.value)


def test_inputs_without_a_parameters_folder(layout: Path) -> None:
    with pytest.raises(ca.InputError, match="not found"):
        PathResolver(None).input_path("case.txt", "w")


def test_outputs(layout: Path) -> None:
    paths = PathResolver(layout)
    assert paths.output_path("vtk") == "vtk"  # a new folder in the working directory
    assert paths.output_path("out/results.json") == "out/results.json"
    assert paths.output_path("sub/results.json") == str(layout / "sub" / "results.json")
    assert paths.output_path("nowhere/results.json") == "nowhere/results.json"


def test_inputs_written_from_a_suite_folder_resolve_through_the_ancestors(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # Kratos layout: tests/<case_folder>/case_parameters.json names "case_folder/mesh".
    suite = tmp_path / "tests"
    (suite / "case_folder").mkdir(parents=True)
    (suite / "case_folder" / "mesh.mdpa").write_text("")
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    paths = PathResolver(suite / "case_folder")
    assert paths.input_path("case_folder/mesh.mdpa", "w") == str(
        suite / "case_folder" / "mesh.mdpa"
    )
    with pytest.raises(ca.InputError, match="and the same below its parent folders"):
        paths.input_path("case_folder/other.mdpa", "w")
