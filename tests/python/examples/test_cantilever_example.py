"""The bundled cantilever example runs through the driver and matches beam theory."""

import json
import shutil
import subprocess
import sys
from pathlib import Path

import meshio
import pytest

EXAMPLE = Path(__file__).parents[3] / "examples" / "cantilever_2d"


def test_cantilever_example_matches_timoshenko_within_discretisation_error(tmp_path: Path) -> None:
    for name in ("ProjectParameters.json", "cantilever.mdpa", "cantilever_materials.json"):
        shutil.copy(EXAMPLE / name, tmp_path / name)
    run = subprocess.run(
        [sys.executable, "-m", "contact_app", "run", "ProjectParameters.json"],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert run.returncode == 0, run.stderr
    data = json.loads((tmp_path / "cantilever_tip.json").read_text())
    tips = [v["DISPLACEMENT_Y"][-1] for k, v in data.items() if k.startswith("NODE_")]
    computed = -sum(tips) / len(tips)
    analytic = 0.01 * 1000.0 / (3 * 1000.0 / 12.0) + 0.01 * 10.0 / (5.0 / 6.0 * 500.0)
    # Bilinear quads, 80 x 8: measured 0.78 % below Timoshenko, converging as h^2.
    assert computed == pytest.approx(analytic, rel=0.01)
    assert computed < analytic  # fully integrated quads are stiff
    mesh = meshio.read(tmp_path / "vtk_output" / "Structure_0_4.vtu")
    assert mesh.point_data["DISPLACEMENT"].shape == (len(mesh.points), 3)
    assert min(mesh.point_data["DISPLACEMENT"][:, 1]) == pytest.approx(min(tips), rel=1e-9)
