"""The hertz_2d example: a cylinder on an elastic foundation against the 2D Hertz solution.

Analytic values (Hertz, cylinders; K. L. Johnson, Contact Mechanics, 1985, §4.3):
b = sqrt(4 P' R / (pi E*)), p0 = 2 P' / (pi b).
b is the moment estimate b^2 = 4 sum(x^2 f) / sum(f) of the nodal forces, p0 the semi-ellipse fit.
The quick test runs the coarsest mesh through the example script (as a user does) and checks its
outputs; the slow study runs three nested refinements (h halved each time) in-process.
"""

from __future__ import annotations

import json
import math
import shutil
from pathlib import Path

import hertz_examples_common as common
import pytest

EXAMPLE = common.EXAMPLES / "hertz_2d"
STUDY_LEVELS = (1, 2, 3)


def _example_module():
    return common.load(EXAMPLE, "run_hertz_2d")


def test_semi_ellipse_fit_recovers_half_width_and_peak() -> None:
    import numpy as np

    fit = _example_module().fit_semi_ellipse
    x = np.linspace(0.0, 0.9, 7)
    b, p0 = fit(x, 3.0 * np.sqrt(1.0 - (x / 1.2) ** 2))
    assert b == pytest.approx(1.2, rel=1e-12)
    assert p0 == pytest.approx(3.0, rel=1e-12)


def test_moment_estimate_recovers_half_width() -> None:
    import numpy as np

    # Nodal forces of p = p0 sqrt(1 - x^2/b^2) on a fine uniform grid (midpoint lengths).
    edges = np.linspace(0.0, 1.2, 20001)
    x = 0.5 * (edges[1:] + edges[:-1])
    force = 3.0 * np.sqrt(1.0 - (x / 1.2) ** 2) * np.diff(edges)
    assert _example_module().moment_half_width(x, force) == pytest.approx(1.2, rel=1e-6)


def test_hertz_2d_coarsest_mesh_runs_converges_and_matches_hertz(tmp_path: Path) -> None:
    common.run_coarsest(EXAMPLE, tmp_path)

    # Same run, evaluated in-process from the files it left (mesh reused, not rewritten).
    result = _example_module().run(tmp_path, None)
    assert result.converged
    # About 4.7 surface intervals over the half-width: measured b 1.06 % (the fit's b 0.06 %),
    # p0 0.41 % off.
    assert result.b_error < 0.03
    assert result.b_fit_error < 0.03
    assert result.p0_error < 0.03
    assert result.active_nodes >= 4
    # The fitted profile carries the applied load: P'/2 = (pi/4) p0 b on the half model.
    assert math.pi * result.p0 * result.b_fit / 4.0 == pytest.approx(result.load / 2.0, rel=0.03)


def _errors(result) -> str:
    return (
        f"b error {100 * result.b_error:.3f} % (fit {100 * result.b_fit_error:.3f} %), "
        f"p0 error {100 * result.p0_error:.3f} %"
    )


@pytest.mark.slow
def test_hertz_2d_converges_with_refinement(tmp_path: Path) -> None:
    results = common.study(EXAMPLE, _example_module(), tmp_path, STUDY_LEVELS, _errors, ("b", "p0"))
    assert all(result.converged for result in results)
    assert [r.p0_error for r in results] == sorted((r.p0_error for r in results), reverse=True)
    # The moment estimate of b falls monotonically: measured 1.06, 0.15, 0.08 %. The fitted b does
    # not (0.06, 0.55, 0.16 %): where the contact edge falls between two nodes (b/h = 4.7, 9.4,
    # 18.8) moves the fit by a few tenths of a percent; it must stay below 1 % on every level.
    assert [r.b_error for r in results] == sorted((r.b_error for r in results), reverse=True)
    assert all(r.b_fit_error < 0.01 for r in results)
    assert results[-1].b_error < 0.02
    assert results[-1].p0_error < 0.05


@pytest.mark.slow
# Regression: pairs the search left inactive missed nodes activated later (b was 3.98 % off).
def test_hertz_2d_high_load_has_no_edge_pressure_spike(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    module = _example_module()
    # 16 x the example's load (b/R = 0.047) on a mesh whose fine zone is scaled to match.
    # Refinement 4 at the example's own load shows the same kind of defect: b 0.67 % off.
    monkeypatch.setattr(module.make_mesh, "FINE_LENGTH", 0.08 * module.make_mesh.RADIUS)
    parameters = json.loads((EXAMPLE / "ProjectParameters.json").read_text())
    load = parameters["processes"]["loads_process_list"][0]["Parameters"]
    load["modulus"] = "100.0*t"
    (tmp_path / "ProjectParameters.json").write_text(json.dumps(parameters))
    shutil.copy(EXAMPLE / "materials.json", tmp_path / "materials.json")
    result = module.run(tmp_path, 3)
    assert result.converged
    assert result.load == pytest.approx(2000.0, rel=1e-12)
    assert result.b_error < 0.02
