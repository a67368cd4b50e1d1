"""The iterative route on PETSc (issue 18, item 3): solver_type "amgcl" / "gmres".

GMRES + GAMG (rigid-body near-null space) on the dual-multiplier-condensed hertz_3d example
(frictionless, scalar multipliers) and cattaneo_mindlin_3d (frictional, vector multipliers), against
UMFPACK; the Krylov iterations in the step table and the summary; the preconditioner kept under
reform_preconditioner_at_each_step false; the same solve distributed over two MPI ranks (mpirun);
the settings' validation; the message naming the package when PETSc is absent. Skipped, naming
the package, when this build has no PETSc.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import contact_app as ca

sys.path.insert(0, str(Path(__file__).parent))
import petsc_hertz_3d_case as case  # noqa: E402
from test_direct_solver_ordering import _linear_settings_error, _static_solver  # noqa: E402

CASE_SCRIPT = Path(__file__).parent / "petsc_hertz_3d_case.py"
UNAVAILABLE = ca.PetscUnavailableReason()
needs_petsc = pytest.mark.skipif(bool(UNAVAILABLE), reason=f"no PETSc solver: {UNAVAILABLE}")


def _assert_same_solution(first: dict[int, list[float]], second: dict[int, list[float]]) -> None:
    ids = sorted(first)
    a = np.array([first[i] for i in ids])
    b = np.array([second[i] for i in ids])
    assert np.abs(a).max() > 0.0
    assert np.abs(a - b).max() <= 1e-6 * np.abs(a).max()


@needs_petsc
def test_amgcl_gives_the_umfpack_solution_of_hertz_3d(tmp_path: Path) -> None:
    direct, _ = case.run(tmp_path, "umfpack")
    krylov, table = case.run(tmp_path, "amgcl")
    assert [s.iterations for s in krylov.reporter.steps] == [
        s.iterations for s in direct.reporter.steps
    ]
    _assert_same_solution(case.displacements(direct), case.displacements(krylov))
    statistics = krylov.reporter.linear_solver
    assert statistics["solver"] == "mixed_ulm_linear_solver(petsc)"  # multipliers condensed
    assert statistics["near_null_space"] == 6
    assert "no (the linear solver is iterative" in statistics["condensation"]
    # One Krylov count per Newton iteration in every step row, and the totals in the summary.
    assert "krylov its" in table.splitlines()[0]
    for step in krylov.reporter.steps:
        assert step.krylov is not None and len(step.krylov) == step.iterations
        assert all(0 < n < 200 for n in step.krylov)
    assert "gmres + gamg" in table and "6 rigid-body modes" in table


@needs_petsc
def test_amgcl_gives_the_umfpack_solution_of_a_frictional_3d_case(tmp_path: Path) -> None:
    """cattaneo_mindlin_3d at level 2, the whole history, slip included.

    Pressed (steps 1-4), then pulled into partial slip (5-8, 3 to 6 slipping nodes; nodes also
    slip in step 1). A slipping node's condensed rows are combined before the AMG sees them
    (docs/theory/condensation.md §5) and GMRES runs as FGMRES (docs/running.md): measured at
    tolerance 1e-6, the slip steps took 115-136 Krylov iterations per solve before the
    combination and 33-39 with it, and at level 3 plain GMRES broke down in step 1.
    """
    folder = Path(__file__).resolve().parents[3] / "examples" / "cattaneo_mindlin_3d"
    sys.path.insert(0, str(folder))
    import run_cattaneo_mindlin_3d as example

    results = {}
    for solver_type in ("umfpack", "amgcl"):
        workdir = tmp_path / solver_type
        workdir.mkdir()
        parameters = json.loads((folder / "ProjectParameters.json").read_text())
        linear = {"solver_type": solver_type}
        if solver_type == "amgcl":
            linear["tolerance"] = 1.0e-10
        parameters["solver_settings"]["linear_solver_settings"] = linear
        parameters.pop("output_processes", None)
        (workdir / "ProjectParameters.json").write_text(json.dumps(parameters))
        results[solver_type] = example.run(workdir, refinement=2)
    direct, krylov = results["umfpack"], results["amgcl"]
    assert direct.converged and krylov.converged
    assert len(krylov.steps) == 8
    # Newton may take one iteration more or less where a criterion sits at round-off.
    for ours, theirs in zip(krylov.steps, direct.steps, strict=True):
        assert abs(ours.iterations - theirs.iterations) <= 1
        assert (ours.active, ours.slipping) == (theirs.active, theirs.slipping)
        assert ours.max_shear == pytest.approx(theirs.max_shear, rel=1e-5)
    assert [step.slipping for step in direct.steps[4:]] == [3, 4, 5, 6]
    assert krylov.a == pytest.approx(direct.a, rel=1e-6)


@needs_petsc
def test_without_reform_the_preconditioner_is_kept_and_the_results_stay(tmp_path: Path) -> None:
    """linear_solver_settings.reform_preconditioner_at_each_step false reaches the PETSc solver."""
    every, every_table = case.run(tmp_path, "amgcl")
    kept, kept_table = case.run(
        tmp_path, "amgcl", linear={"reform_preconditioner_at_each_step": False}
    )
    solves = len(every.reporter.linear_solver["krylov_iterations"])
    assert every.reporter.linear_solver["preconditioner_setups"] == solves
    assert f"({solves} preconditioner set-ups for {solves} solves)" in every_table
    statistics = kept.reporter.linear_solver
    assert len(statistics["krylov_iterations"]) == solves
    assert 1 <= statistics["preconditioner_setups"] < solves
    setups = statistics["preconditioner_setups"]
    assert f"({setups} preconditioner set-ups for {solves} solves)" in kept_table
    newton = [s.iterations for s in every.reporter.steps]
    assert [s.iterations for s in kept.reporter.steps] == newton
    _assert_same_solution(case.displacements(every), case.displacements(kept))


@needs_petsc
@pytest.mark.skipif(shutil.which("mpirun") is None, reason="no mpirun (Debian openmpi-bin)")
@pytest.mark.parametrize("reform", [True, False])
def test_two_mpi_ranks_give_the_serial_direct_solution(tmp_path: Path, reform: bool) -> None:
    """The kept matrices are updated on every rank.

    Without reform, rank 0's pattern check decides for all ranks.
    """
    direct, _ = case.run(tmp_path, "umfpack")
    command = ["mpirun", "-n", "2", "--allow-run-as-root", "--oversubscribe"]
    linear = json.dumps({"reform_preconditioner_at_each_step": reform})
    command += [sys.executable, str(CASE_SCRIPT), str(tmp_path), "amgcl", "", linear]
    env = dict(os.environ, OMPI_MCA_rmaps_base_oversubscribe="1")
    done = subprocess.run(command, capture_output=True, text=True, timeout=600, env=env)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    result = json.loads((tmp_path / "result.json").read_text())
    assert result["ranks"] == 2
    assert result["statistics"]["ranks"] == 2
    assert "2 MPI ranks" in result["statistics"]["krylov_method"]
    assert result["iterations"] == [s.iterations for s in direct.reporter.steps]
    setups, solves = result["statistics"]["preconditioner_setups"], sum(result["iterations"])
    assert setups == solves if reform else 1 <= setups < solves
    displacements = {int(k): v for k, v in result["displacements"].items()}
    _assert_same_solution(case.displacements(direct), displacements)


def test_unknown_amgcl_settings_name_the_key() -> None:
    bad = {"solver_type": "amgcl", "smoother_type": "gauss_seidl"}
    message = _linear_settings_error(bad, "smoother_type")
    assert 'linear_solver_settings.smoother_type "gauss_seidl"' in message
    assert 'did you mean "gauss_seidel"' in message
    with pytest.raises(ca.InputError, match="krylov_type"):
        _static_solver({"solver_type": "gmres", "krylov_type": "idrs"})
    with pytest.raises(ca.InputError, match="smoother_typ"):  # unknown keys stay rejected
        _static_solver({"solver_type": "amgcl", "smoother_typ": "ilu0"})
    _static_solver({"solver_type": "amgcl", "smoother_type": "ilu0", "krylov_type": "bicgstab"})


def test_without_petsc_the_factory_names_the_package(tmp_path: Path) -> None:
    env = dict(os.environ, CONTACT_APP_PETSC_PLUGIN=str(tmp_path / "libcontact_app_petsc.so"))
    code = "import contact_app as ca; ca.CreateLinearSolver('amgcl')"
    done = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=120
    )
    assert done.returncode != 0
    assert "ConfigurationError" in done.stderr
    assert "libpetsc-real" in done.stderr
    assert 'use a direct solver ("mumps"' in done.stderr
