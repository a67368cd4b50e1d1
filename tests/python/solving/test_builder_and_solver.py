"""The parallel assembly gives the same run, to the bit, with 1 and 2 threads (issue 18 item 5).

docs/architecture.md, "Threading model": the builder evaluates the local systems in parallel and
adds them in entity order, so OMP_NUM_THREADS changes the time a build takes, never its result;
``import contact_app`` makes waiting threads sleep (OMP_WAIT_POLICY=PASSIVE) unless the user chose.
OpenBLAS is held at one thread in both runs: it reads OMP_NUM_THREADS when OPENBLAS_NUM_THREADS is
unset, and its threaded kernels move the factorisation's round-off (measured on this case: 2.6e-16
apart in the displacements), which is not the assembly's doing.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np

CASE_SCRIPT = Path(__file__).parent / "parallel_assembly_case.py"


def _run(directory: Path, threads: int) -> dict[str, np.ndarray]:
    """The frictional 3D case run in its own process with ``threads`` OpenMP threads."""
    directory.mkdir()
    environment = dict(os.environ, OMP_NUM_THREADS=str(threads), OPENBLAS_NUM_THREADS="1")
    done = subprocess.run(
        [sys.executable, str(CASE_SCRIPT), str(directory)],
        env=environment,
        capture_output=True,
        text=True,
        check=False,
    )
    assert done.returncode == 0, done.stderr[-3000:]
    with np.load(directory / "result.npz") as result:
        return {name: result[name] for name in result.files}


def test_a_frictional_3d_run_is_bit_identical_with_one_and_two_threads(tmp_path: Path) -> None:
    one = _run(tmp_path / "one", 1)
    two = _run(tmp_path / "two", 2)
    assert one["converged"].all()
    assert one["slip"].any() and one["active"].any()  # stick and slip nodes both present
    assert np.abs(one["multiplier"]).max() > 0.0
    for name, values in one.items():
        assert values.dtype == two[name].dtype and values.shape == two[name].shape, name
        assert values.tobytes() == two[name].tobytes(), f"{name} differs between 1 and 2 threads"


def test_import_makes_waiting_threads_sleep_unless_the_user_chose() -> None:
    script = "import os, contact_app; print(os.environ['OMP_WAIT_POLICY'])"
    for preset, expected in ((None, "PASSIVE"), ("ACTIVE", "ACTIVE")):
        environment = {k: v for k, v in os.environ.items() if k != "OMP_WAIT_POLICY"}
        if preset is not None:
            environment["OMP_WAIT_POLICY"] = preset
        done = subprocess.run(
            [sys.executable, "-c", script], env=environment, capture_output=True, text=True
        )
        assert done.stdout.strip() == expected, done.stderr[-2000:]
