"""The direct solvers' fill-reducing ordering and MUMPS (issue 18).

The setting and its validation, identical results AMD vs METIS and UMFPACK vs MUMPS on a contact
case, and the linear-solver line of the run summary.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from example_runs import load_make_mesh, run_without_output  # same folder (pytest rootdir)

import contact_app as ca
from contact_app.analysis.solvers import StaticMechanicalSolver
from contact_app.parameters import Parameters

HERTZ_2D = Path(__file__).parents[3] / "examples" / "hertz_2d"


def _static_solver(linear: dict[str, Any]) -> StaticMechanicalSolver:
    settings = {
        "solver_type": "Static",
        "model_part_name": "Structure",
        "domain_size": 2,
        "model_import_settings": {"input_type": "use_input_model_part"},
        "time_stepping": {"time_step": 0.1},
        "linear_solver_settings": linear,
    }
    return StaticMechanicalSolver(
        ca.Model(), Parameters(settings, source="case.json", path=("solver_settings",))
    )


def _linear_settings_error(linear: dict[str, Any], key: str) -> str:
    """The message of the InputError ``linear`` raises; checks it names the place of ``key``."""
    with pytest.raises(ca.InputError) as failure:
        _static_solver(linear)
    message = str(failure.value)
    assert f"case.json › solver_settings › linear_solver_settings › {key}" in message
    return message


@pytest.mark.parametrize("ordering", ["auto", "amd", "metis"])
def test_every_ordering_is_accepted(ordering: str) -> None:
    _static_solver({"solver_type": "umfpack", "ordering": ordering})
    solver = ca.CreateLinearSolver("skyline_lu_factorization", ordering=ordering)
    assert solver.GetStatistics()["ordering_setting"] == ordering


def test_unknown_ordering_names_the_key_and_suggests() -> None:
    message = _linear_settings_error({"solver_type": "umfpack", "ordering": "metiss"}, "ordering")
    assert 'unknown linear_solver_settings.ordering "metiss"' in message
    assert '"amd", "auto", "metis"' in message
    assert 'did you mean "metis"' in message


def test_ordering_of_a_solver_other_than_umfpack_is_an_error() -> None:
    with pytest.raises(ca.InputError, match="applies to UMFPACK and MUMPS only"):
        _static_solver({"solver_type": "cholmod", "ordering": "amd"})
    _static_solver({"solver_type": "cholmod", "ordering": "auto"})  # the default is fine
    with pytest.raises(ca.InputError, match='"ordering" has the wrong type'):
        _static_solver({"solver_type": "umfpack", "ordering": 3})


def _run_hertz_2d(
    directory: Path, ordering: str, echo_level: int = 0, solver_type: str | None = None
) -> tuple[Any, str]:
    """The hertz_2d example at its coarsest level, without output, with the given ordering."""
    load_make_mesh(HERTZ_2D).write_mesh(directory / "hertz_2d.msh", 1)
    parameters = json.loads((HERTZ_2D / "ProjectParameters.json").read_text())
    parameters["problem_data"]["echo_level"] = echo_level
    parameters["solver_settings"]["model_import_settings"]["input_filename"] = str(
        directory / "hertz_2d.msh"
    )
    parameters["solver_settings"]["material_import_settings"]["materials_filename"] = str(
        HERTZ_2D / "materials.json"
    )
    parameters["solver_settings"]["linear_solver_settings"]["ordering"] = ordering
    if solver_type is not None:
        parameters["solver_settings"]["linear_solver_settings"]["solver_type"] = solver_type
    return run_without_output(parameters)


def _state(analysis: Any) -> tuple[np.ndarray, np.ndarray]:
    main = analysis.model.GetModelPart("Structure")
    nodes = sorted(main.Nodes, key=lambda node: node.Id)
    displacement = np.array([node.GetSolutionStepValue(ca.DISPLACEMENT) for node in nodes])
    slave = sorted(main.GetSubModelPart("Contact_Slave").Nodes, key=lambda node: node.Id)
    pressure = np.array([node.GetValue(ca.AUGMENTED_NORMAL_CONTACT_PRESSURE) for node in slave])
    return displacement, pressure


def _assert_same_contact_solution(first: Any, second: Any, tolerance: float) -> None:
    """Same Newton iterations; displacements and contact pressures equal to ``tolerance``."""
    iterations = [[s.iterations for s in a.reporter.steps] for a in (first, second)]
    assert iterations[0] == iterations[1]
    first_u, first_p = _state(first)
    second_u, second_p = _state(second)
    assert np.abs(first_p).max() > 0.0  # the contact is active
    assert np.abs(second_u - first_u).max() <= tolerance * np.abs(first_u).max()
    assert np.abs(second_p - first_p).max() <= tolerance * np.abs(first_p).max()


def test_amd_and_metis_give_the_same_contact_solution(tmp_path: Path) -> None:
    amd, amd_text = _run_hertz_2d(tmp_path, "amd")
    metis, metis_text = _run_hertz_2d(tmp_path, "metis", echo_level=1)
    statistics = {
        name: analysis.reporter.linear_solver for name, analysis in (("amd", amd), ("metis", metis))
    }
    for name, figures in statistics.items():
        assert figures["solver"] == "umfpack"
        assert figures["ordering"] == name  # Debian's UMFPACK has METIS built in
        assert figures["ordering_setting"] == name
        assert figures["max_factor_nonzeros"] > 0 and figures["max_factor_memory"] > 0
    # Two pivot sequences of the same Newton iterates: equal to round-off of the solves.
    _assert_same_contact_solution(amd, metis, 1e-9)

    # The summary names the solver, the ordering, the fill and the factor memory.
    summary_line = next(line for line in amd_text.splitlines() if "linear solver:" in line)
    assert summary_line.startswith('  linear solver: umfpack, ordering amd ("amd"), ')
    assert "largest factors" in summary_line and "nnz in" in summary_line
    assert summary_line.rstrip().endswith("MB")
    assert amd_text.count("linear solver:") == 1  # echo_level 0: no line per step
    # echo_level 1: one line under every step row as well.
    per_step = [line for line in metis_text.splitlines() if "last factors" in line]
    assert len(per_step) == len(metis.reporter.steps)
    assert all('ordering metis ("metis")' in line for line in per_step)


def test_mumps_gives_the_umfpack_contact_solution(tmp_path: Path) -> None:
    umfpack, _ = _run_hertz_2d(tmp_path, "auto", solver_type="umfpack")
    mumps, mumps_text = _run_hertz_2d(tmp_path, "auto", solver_type="mumps")
    figures = mumps.reporter.linear_solver
    assert figures["solver"] == "mumps"
    assert figures["ordering"] == "metis" and figures["ordering_setting"] == "auto"
    assert figures["max_factor_nonzeros"] > 0 and figures["max_factor_memory"] > 0
    _assert_same_contact_solution(umfpack, mumps, 1e-10)
    summary_line = next(line for line in mumps_text.splitlines() if "linear solver:" in line)
    assert summary_line.startswith('  linear solver: mumps, ordering metis ("auto"), ')
