"""A run saving a restart file every step, killed (SIGKILL) at random moments, resumes exactly.

A subprocess runs the frictional stick-slip block (ALM, 100 steps) with SaveRestart every step and
JSON + VTK output, resuming from the newest restart file present. The test kills it at seeded
random moments (while it starts, solves, writes outputs or a restart file) and after each kill
checks that the newest restart file loads and that a run continued from it (in a copy of the
folder) ends with the nodal results, the JSON file and the VTK files of a run never interrupted,
bit for bit. A chain of killed runs that reached the end is replaced by a new one; the last chain
is finally let finish and its output files checked the same way.
"""

from __future__ import annotations

import filecmp
import json
import os
import random
import shutil
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest
from test_restart_routes_and_outputs import _with_outputs
from test_restart_utility import _assert_identical, _run, _state, _stick_slip_module

import contact_app as ca
from contact_app.io.restart_utility import Inspect, Load

SEED = 16
KILLS = 6
BASE = "stick_slip"  # problem_name of the case: <BASE>__restart_files/<BASE>_<TIME>.rest
END = 5.0

_WORKER = textwrap.dedent(
    """
    import json, sys
    from pathlib import Path
    import contact_app as ca
    from contact_app.analysis import StructuralMechanicsAnalysis
    from contact_app.analysis.reporting import Reporter
    parameters = json.loads(Path(sys.argv[1]).read_text())
    options = {"SaveRestart": True, "RestartFrequency": 0.0}
    if sys.argv[2]:
        options.update({"LoadRestart": True, "Restart Step": float(sys.argv[2])})
    parameters["restart_options"] = options
    StructuralMechanicsAnalysis(ca.Model(), parameters, reporter=Reporter(quiet=True)).Run()
    """
)


def _parameters(case_folder: Path) -> dict:
    case = _stick_slip_module()
    case_folder.mkdir()
    case._write_case(case_folder, case.NON_MATCHING, case.MU)
    parameters = case._parameters(case_folder, "ALMContactFrictional", 2)
    # 100 steps (about 2 s with a restart file per step), so that the kills fall inside the run.
    parameters["solver_settings"]["time_stepping"]["time_step"] = 0.05
    return _with_outputs(parameters, slave="Structure.Contact_Slave", vtk_control=("time", 1.0))


def _newest_label(folder: Path) -> str:
    """The TIME label of the newest complete restart file in ``folder`` ("" if none)."""
    files = folder / f"{BASE}__restart_files"
    labels = [
        p.name[len(BASE) + 1 : -len(".rest")]
        for p in (files.iterdir() if files.is_dir() else [])
        if p.name.startswith(f"{BASE}_") and p.name.endswith(".rest")
    ]
    return max(labels, key=float, default="")


def _assert_same_outputs(reference: Path, folder: Path) -> None:
    assert (folder / "results.json").read_bytes() == (reference / "results.json").read_bytes()
    written = sorted(p.name for p in (reference / "vtk_output").iterdir())
    assert written == sorted(p.name for p in (folder / "vtk_output").iterdir())
    for name in written:
        assert filecmp.cmp(reference / "vtk_output" / name, folder / "vtk_output" / name, False)


@pytest.mark.slow
def test_random_kills_always_resume_bit_identically(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    parameters = _parameters(tmp_path / "case")
    (tmp_path / "parameters.json").write_text(json.dumps(parameters))
    reference = tmp_path / "continuous"
    reference.mkdir()
    monkeypatch.chdir(reference)
    started = time.perf_counter()
    expected = _state(_run(parameters, END))
    duration = time.perf_counter() - started

    # Python and contact_app take a while to start: the kills are drawn over start + remaining run.
    started = time.perf_counter()
    subprocess.run([sys.executable, "-c", "import contact_app.analysis"], check=True)
    startup = time.perf_counter() - started

    worker = [sys.executable, "-c", _WORKER, str(tmp_path / "parameters.json")]
    rng = random.Random(SEED)
    chain = 0
    killed = tmp_path / f"killed_{chain}"
    killed.mkdir()
    labels = []
    for kill in range(KILLS):
        label = _newest_label(killed)
        if label == f"{END}":  # this chain reached the end before a kill: start another
            chain += 1
            killed = tmp_path / f"killed_{chain}"
            killed.mkdir()
            label = ""
        remaining = 1.3 * duration * (END - float(label or 0.0)) / END
        process = subprocess.Popen(worker + [label], cwd=killed, stderr=subprocess.DEVNULL)
        time.sleep(rng.uniform(0.0, startup + remaining))
        os.kill(process.pid, signal.SIGKILL)
        process.wait()
        label = _newest_label(killed)
        labels.append(label)
        if not label:
            continue  # killed before its first step ended: the next run starts from the mesh
        path = killed / f"{BASE}__restart_files" / f"{BASE}_{label}.rest"
        assert Inspect(path)["time"] == pytest.approx(float(label), rel=1e-11)  # label: 12 digits
        Load(ca.Model().CreateModelPart("Structure"), path)
        resumed = tmp_path / f"resumed_{kill}"
        shutil.copytree(killed, resumed)
        monkeypatch.chdir(resumed)
        state = _state(_run(parameters, END, LoadRestart=True, **{"Restart Step": float(label)}))
        _assert_identical(expected, state)
        _assert_same_outputs(reference, resumed)
    print(f"\nnewest restart file after each kill: {labels} (chains: {chain + 1})")
    assert len({label for label in labels if label and label != f"{END}"}) >= 3

    label = _newest_label(killed)
    result = subprocess.run(
        worker + [label], cwd=killed, capture_output=True, text=True, check=False
    )
    assert result.returncode == 0, result.stderr
    assert _newest_label(killed) == f"{END}"
    _assert_same_outputs(reference, killed)
