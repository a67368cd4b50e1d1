"""Static condensation of a linear bulk (issue 18 item 2; docs/theory/static_condensation.md).

The setting and its validation; the Hertz 2D (static and Bossak) and 3D examples and the
frictional Cattaneo-Mindlin 3D example at their coarsest level give the same iterations,
displacements and contact pressures with the condensation on and off; the run summary says which
ran; "auto" refuses a finite-strain or hyperelastic model with the reason.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from example_runs import load_make_mesh, run_without_output  # same folder
from test_direct_solver_ordering import (
    _state,
    _static_solver,
)  # same folder (pytest's rootdir import)

import contact_app as ca
from contact_app.analysis.reporting import condensation_text

EXAMPLES = Path(__file__).parents[3] / "examples"


@pytest.mark.parametrize("value", ["auto", True, False])
def test_static_condensation_values_are_accepted(value: Any) -> None:
    _static_solver({"solver_type": "umfpack", "static_condensation": value})


@pytest.mark.parametrize("value", ["yes", 1, "on"])
def test_other_static_condensation_values_name_the_key(value: Any) -> None:
    with pytest.raises(ca.InputError) as failure:
        _static_solver({"static_condensation": value})
    message = str(failure.value)
    assert f"static_condensation is {json.dumps(value)}" in message
    assert "case.json › solver_settings › linear_solver_settings › static_condensation" in message
    assert '"auto", true or false' in message


def _run(
    directory: Path,
    example: str,
    condensation: Any,
    element: str | None = None,
    law: str | None = None,
    dynamic: bool = False,
) -> tuple[Any, str]:
    """An example at its coarsest level, without output, with static_condensation set."""
    folder = EXAMPLES / example
    mesh = directory / f"{example}.msh"
    load_make_mesh(folder).write_mesh(mesh, 1)
    parameters = json.loads((folder / "ProjectParameters.json").read_text())
    solver = parameters["solver_settings"]
    solver["model_import_settings"]["input_filename"] = str(mesh)
    materials = json.loads((folder / "materials.json").read_text())
    if law is not None:
        for block in materials["properties"]:
            block["Material"]["constitutive_law"]["name"] = law
    (directory / "materials.json").write_text(json.dumps(materials))
    solver["material_import_settings"]["materials_filename"] = str(directory / "materials.json")
    solver["linear_solver_settings"]["static_condensation"] = condensation
    if dynamic:  # Bossak: the element matrices carry the mass, constant at a constant time step
        solver.update(
            solver_type="Dynamic", time_integration_method="implicit", scheme_type="bossak"
        )
    if element is not None:
        mapping = solver["model_import_settings"]["mesh_mapping"]["elements"]
        for cell in mapping:
            mapping[cell] = element
    return run_without_output(parameters)


def _summary_line(text: str) -> str:
    return next(line for line in text.splitlines() if "static condensation:" in line).strip()


@pytest.mark.parametrize(
    ("example", "dynamic", "condensations"),
    # Cattaneo-Mindlin (frictional) releases the constraint of the sphere's centre plane at t = 1:
    # the bulk changes once and is condensed again.
    [
        ("hertz_2d", False, 1),
        ("hertz_2d", True, 1),
        ("hertz_3d", False, 1),
        ("cattaneo_mindlin_3d", False, 2),
    ],
    ids=["hertz_2d", "hertz_2d_bossak", "hertz_3d", "cattaneo_mindlin_3d"],
)
def test_condensed_and_full_solves_give_the_same_run(
    tmp_path: Path, example: str, dynamic: bool, condensations: int
) -> None:
    (tmp_path / "on").mkdir()
    (tmp_path / "off").mkdir()
    on, on_text = _run(tmp_path / "on", example, True, dynamic=dynamic)
    off, off_text = _run(tmp_path / "off", example, False, dynamic=dynamic)
    assert [s.iterations for s in on.reporter.steps] == [s.iterations for s in off.reporter.steps]
    assert all(s.converged for s in on.reporter.steps)
    on_u, on_p = _state(on)
    off_u, off_p = _state(off)
    assert np.abs(off_p).max() > 0.0  # the contact is active
    assert np.abs(on_u - off_u).max() <= 1e-10 * np.abs(off_u).max()
    assert np.abs(on_p - off_p).max() <= 1e-10 * np.abs(off_p).max()
    # The summary says which ran, and that the bulk was condensed once per change only.
    line = _summary_line(on_text)
    assert line.startswith("static condensation: yes; interface ")
    assert f"bulk condensed {condensations}x in" in line
    statistics = on.reporter.linear_solver
    assert statistics["condensed_solves"] == sum(s.iterations for s in on.reporter.steps)
    assert _summary_line(off_text) == (
        "static condensation: no (switched off by linear_solver_settings.static_condensation)"
    )


def test_auto_leaves_a_small_system_to_the_sparse_solver(tmp_path: Path) -> None:
    _, text = _run(tmp_path, "hertz_2d", "auto")
    assert 'from which "auto" condenses)' in _summary_line(text)


@pytest.mark.parametrize(
    ("element", "law", "reason"),
    [
        (
            "TotalLagrangianElement2D4N",
            None,
            "is a TotalLagrangianElement, whose stiffness follows",
        ),
        (None, "HyperElasticPlaneStrain2DLaw", "has HyperElasticPlaneStrain2DLaw, not a linear"),
    ],
    ids=["total_lagrangian", "hyperelastic"],
)
def test_auto_refuses_a_non_linear_bulk_with_the_reason(
    tmp_path: Path, element: str | None, law: str | None, reason: str
) -> None:
    _, text = _run(tmp_path, "hertz_2d", "auto", element=element, law=law)
    line = _summary_line(text)
    assert line.startswith("static condensation: no (element ")
    assert reason in line


def test_condensation_line_of_the_summary() -> None:
    assert condensation_text({"condensation": ""}) == ""
    assert condensation_text({"condensation": "no (why)"}) == "static condensation: no (why)"
    line = condensation_text(
        {
            "condensation": "yes",
            "interface_size": 10,
            "bulk_size": 90,
            "bulk_factorizations": 1,
            "bulk_seconds": 2.0,
            "condensed_solves": 4,
            "interface_seconds": 1.0,
        }
    )
    assert line == (
        "static condensation: yes; interface 10 of 100 equations, bulk condensed 1x in 2 s, "
        "4 condensed solves in 1 s (0.25 s each)"
    )
