"""The repository explains itself: no source or document cites documents outside it (issue 19).

The theory the code relies on lives in ``docs/`` (``docs/theory/*.md``, ``docs/input_layer.md``,
``docs/registered_conditions.md``); a comment points there, never to the specification documents the
project was started from, which a maintainer who clones the repository alone does not have. Tests
may still *read* reference data next to the checkout (``../shared/kratos_cases``,
``../shared/kratos_examples``); only citations of the specification folder are refused. Test data
folders (``tests/**/data/``) record the provenance of fixtures and are not scanned.
"""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

#: Source folders (C++ and Python) and the documentation that must not cite outside documents.
SOURCE_DIRS = (
    "contact_app",
    "custom_conditions",
    "custom_processes",
    "custom_strategies",
    "custom_utilities",
    "automatic_differentiation",
    "python_scripts",
    "examples",
    "benchmarks",
    "scripts",
    "tests",
    "docs",
)
SOURCE_SUFFIXES = {".h", ".hpp", ".cpp", ".py", ".pyi", ".md", ".sh"}
TOP_LEVEL_FILES = ("README.md", "CMakeLists.txt", "pyproject.toml")

#: The specification documents by name, and the folder that holds them. Built from pieces so
#: that this file does not match itself.
_SPEC_NAMES = (
    "kratos_" + "residuals",
    "kratos_" + "cpp_internals",
    "kratos_" + "structural",
    "kratos_" + "python_layer",
    "kratos_" + "test_catalog",
    "condition_" + "classes",
    "variables",
)
CITATION = re.compile(
    r"shared/" + r"spec\b" + "|" + r"\b(?:" + "|".join(_SPEC_NAMES) + r")\.md\b",
)


def _scanned_files() -> list[Path]:
    files = [ROOT / name for name in TOP_LEVEL_FILES if (ROOT / name).is_file()]
    for folder in SOURCE_DIRS:
        for path in sorted((ROOT / folder).rglob("*")):
            relative = path.relative_to(ROOT)
            if not path.is_file() or path.suffix not in SOURCE_SUFFIXES:
                continue
            if "data" in relative.parts or "__pycache__" in relative.parts:
                continue
            files.append(path)
    return files


def _citations() -> list[str]:
    found = []
    for path in _scanned_files():
        text = path.read_text(encoding="utf-8", errors="replace")
        if not CITATION.search(text):
            continue
        for number, line in enumerate(text.splitlines(), start=1):
            match = CITATION.search(line)
            if match:
                found.append(f"{path.relative_to(ROOT)}:{number}: {match.group(0)}")
    return found


def test_the_scan_sees_the_sources() -> None:
    names = {path.relative_to(ROOT).as_posix() for path in _scanned_files()}
    for expected in (
        "custom_conditions/mortar_contact_condition.h",
        "contact_app/kernel/variables.h",
        "python_scripts/contact/search_base_process.py",
        "docs/theory/contact_residuals.md",
        "README.md",
    ):
        assert expected in names


def test_the_pattern_finds_a_citation() -> None:
    assert CITATION.search("see ../shared/" + "spec/ARCHITECTURE.md")
    assert CITATION.search("RHS of " + _SPEC_NAMES[0] + ".md §3.1")
    assert not CITATION.search("reads ../shared/kratos_cases/hertz")
    assert not CITATION.search("docs/theory/contact_residuals.md §3")


def test_no_source_cites_documents_outside_the_repository() -> None:
    citations = _citations()
    assert not citations, (
        "cite docs/ instead of documents outside the repository (write the fact into docs/theory/ "
        "in our own words first):\n" + "\n".join(citations)
    )
