"""Running one of the repository's examples from a solver test: its mesh writer and a quiet run.

Shared by the solver tests of this folder and by ``petsc_hertz_3d_case.py`` (also run as a
script under mpirun), so it depends on nothing but contact_app.
"""

from __future__ import annotations

import importlib.util
import io
from pathlib import Path
from types import ModuleType
from typing import Any

import contact_app as ca
from contact_app.analysis import Reporter
from contact_app.parameters import Parameters


def load_make_mesh(example_folder: Path) -> ModuleType:
    """The example's ``make_mesh.py`` as a module (``write_mesh(path, level)``)."""
    name = f"{example_folder.name}_make_mesh"
    spec = importlib.util.spec_from_file_location(name, example_folder / "make_mesh.py")
    assert spec is not None and spec.loader is not None
    make_mesh = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(make_mesh)
    return make_mesh


def run_without_output(parameters: dict) -> tuple[Any, str]:
    """Run ``parameters`` (a ProjectParameters dict) without its output processes.

    Returns the analysis and the step table it printed.
    """
    parameters.pop("output_processes", None)
    stream = io.StringIO()
    analysis = ca.analysis.StructuralMechanicsAnalysis(
        ca.Model(), Parameters(parameters), reporter=Reporter(stream)
    )
    analysis.Run()
    return analysis, stream.getvalue()
