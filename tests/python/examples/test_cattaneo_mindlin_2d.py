"""The cattaneo_mindlin_2d example: Coulomb partial slip of a cylinder against Cattaneo-Mindlin.

Analytic (Johnson, Contact Mechanics, 7.1; identical materials): Hertz half-width a, stick zone
|x| < c with c/a = sqrt(1 - Q'/(mu P')), q = mu p in the slip zones. c is measured as the
half-width of the STICK nodes (midpoint to the first slip node on each side): when the discrete
stick set is the set of nodes with |x| < c, that estimate is within h/2 of c (h the node spacing,
uniform over the contact), so h/(2a) is the tolerance on c/a. The quick test runs the coarsest
mesh in-process and writes the example's outputs; the slow study runs three nested refinements.
"""

from __future__ import annotations

import importlib.util
import json
import math
import shutil
import sys
from pathlib import Path

import pytest

EXAMPLE = Path(__file__).parents[3] / "examples" / "cattaneo_mindlin_2d"
STUDY_LEVELS = (1, 2, 3)


def _example_module():
    spec = importlib.util.spec_from_file_location(
        "run_cattaneo_mindlin_2d", EXAMPLE / "run_cattaneo_mindlin_2d.py"
    )
    module = importlib.util.module_from_spec(spec)
    assert spec.loader is not None
    sys.modules[spec.name] = module  # dataclasses look their module up there
    spec.loader.exec_module(module)
    return module


def _copy_inputs(directory: Path, vtk: bool = True) -> None:
    parameters = json.loads((EXAMPLE / "ProjectParameters.json").read_text())
    if not vtk:  # the VTK files of refinement 3 take about as long to write as the solve
        parameters["output_processes"] = {}
    (directory / "ProjectParameters.json").write_text(json.dumps(parameters))
    shutil.copy(EXAMPLE / "materials.json", directory / "materials.json")


def test_parameters_file_holds_the_default_loads() -> None:
    module = _example_module()
    parameters = json.loads((EXAMPLE / "ProjectParameters.json").read_text())
    mu = module.common.friction_coefficient(parameters)
    assert mu == 0.3
    values = parameters["processes"]["loads_process_list"][0]["Parameters"]["value"]
    # `contact-app run ProjectParameters.json` runs the example's default case.
    assert values == module.load_values(module.DEFAULT_RATIO, mu)


def test_mirrored_mesh_is_the_whole_cylinder_on_the_whole_foundation() -> None:
    import numpy as np

    module = _example_module()
    mesh = module.make_mesh.build(1)
    quads = np.vstack([block.data for block in mesh.cells if block.type == "quad"])
    x, y = mesh.points[quads][:, :, 0], mesh.points[quads][:, :, 1]
    area = 0.5 * np.sum(x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y, axis=1)
    assert area.min() > 0.0  # counter-clockwise after mirroring
    radius = module.make_mesh.RADIUS
    # Half disc (a polygon inscribed in it) plus the 4R x 2R foundation.
    assert area.sum() == pytest.approx(0.5 * math.pi * radius**2 + 8.0 * radius**2, rel=1e-3)
    x = mesh.points[:, 0]
    assert x.min() == pytest.approx(-2.0 * radius) and x.max() == pytest.approx(2.0 * radius)
    # The nodes on x = 0 are shared, not doubled: only the contact point is there twice (one
    # node of each body).
    assert len(np.unique(np.round(mesh.points / 1e-9), axis=0)) == len(mesh.points) - 1


def test_cattaneo_mindlin_2d_coarsest_mesh_matches_the_partial_slip_solution(
    tmp_path: Path,
) -> None:
    _copy_inputs(tmp_path)
    module = _example_module()
    result = module.run(tmp_path, 1)
    text = module.write_outputs(result, tmp_path)
    for name in ("cattaneo_mindlin_2d.msh", module.PLOT, module.SUMMARY):
        assert (tmp_path / name).stat().st_size > 0, name
    assert (tmp_path / module.PLOT).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert len(list((tmp_path / "vtk_output").glob("Structure_0_*.vtu"))) == 8
    assert "all steps converged" in text

    # Every step converged (measured: 2 Newton iterations each, 16 in all).
    assert len(result.steps) == 8
    assert all(step.converged for step in result.steps)
    assert result.load == pytest.approx(125.0, rel=1e-12)
    assert result.ratio == pytest.approx(0.5, rel=1e-12)
    assert abs(result.applied_moment) < 1e-9 * result.tangential_load * module.make_mesh.RADIUS

    # The slave nodes in contact are the ACTIVE ones: exactly those within the Hertz half-width
    # (nodes at 0.1 = a - 0.7 h and 0.125 = a + 0.3 h), all in compression.
    a, h = result.a_analytic, result.spacing
    assert h == pytest.approx(0.025, rel=1e-5)  # x spacing of nodes 0.025 apart on the arc
    for node in result.profile:
        assert node.active == (abs(node.x) < a), node.x
    assert all(node.p > 0.0 for node in result.active)
    assert len(result.active) == 9

    # Coulomb: |q| = mu p on the slip nodes (measured to 1e-16), inside the cone on the stick
    # nodes (measured max |q| / (mu p) = 0.886). The friction on the cylinder opposes its slide
    # relative to the foundation (the slip nodes slide by +2e-5 mm along Q').
    slip = [node for node in result.active if node.slip]
    stick = [node for node in result.active if not node.slip]
    assert [node.x for node in slip] == pytest.approx([-0.1, 0.1], abs=1e-5)  # R sin(4h/R)
    for node in slip:
        assert abs(node.q) == pytest.approx(result.mu * node.p, rel=1e-6)
        assert node.q > 0.0 and node.slide > 0.0
        assert node.slip_angle < 0.1  # t along +WEIGHTED_SLIP (measured 0)
    for node in stick:
        assert abs(node.q) < result.mu * node.p

    # The tangential force: the base carries Q' (equilibrium, measured to 6e-12); the nodal shear
    # tractions times their lumped lengths sum to Q' (1 - 5.5e-5).
    assert -result.base_reaction_x == pytest.approx(result.tangential_load, rel=1e-9)
    assert result.contact_tangential_force == pytest.approx(result.tangential_load, rel=1e-4)

    # The stick set is the nodes with |x| < c (c = 0.0830: 0.075 = c - 0.32 h sticks, 0.1 =
    # c + 0.68 h slips), so the midpoint estimate 0.0875 is within h/2: measured c/a = 0.745
    # against sqrt(1/2) = 0.707 (5.4 %), tolerance h/(2a) = 0.106.
    c = result.c_analytic
    assert [node.x for node in stick] == [node.x for node in result.active if abs(node.x) < c]
    assert result.stick_contiguous
    assert result.stick_offset == pytest.approx(0.0, abs=1e-9)
    assert abs(result.c / a - math.sqrt(0.5)) <= h / (2.0 * a)
    assert result.c / a == pytest.approx(0.745, abs=5e-4)


@pytest.mark.slow
def test_cattaneo_mindlin_2d_stick_zone_converges_with_refinement(tmp_path: Path) -> None:
    module = _example_module()
    results = []
    for level in STUDY_LEVELS:
        run_dir = tmp_path / f"refinement_{level}"
        run_dir.mkdir()
        _copy_inputs(run_dir, vtk=False)
        results.append(module.run(run_dir, level))
    for r in results:
        print(
            f"refinement {r.refinement}: h = {r.spacing:.4g}, c/a {r.c / r.a_analytic:.4f} "
            f"(error {100 * r.c_error:.2f} %, deficit moment {100 * r.c_deficit_error:.2f} %), "
            f"a error {100 * r.a_error:.2f} %, Newton {sum(r.iterations)}, {r.wall_time:.1f} s"
        )
    for r in results:
        assert r.converged
        assert r.coulomb_slip_deviation < 1e-6
        assert r.stick_max_ratio < 1.0
        assert r.stick_contiguous
        a, h = r.a_analytic, r.spacing
        assert abs(r.c / a - r.c_over_a_analytic) <= h / (2.0 * a)
        # Each tangential step's stick zone too (c/a = 0.935, 0.866, 0.791, 0.707).
        for step in r.steps:
            if not math.isnan(step.stick_half_width):
                assert abs(step.stick_half_width - a * math.sqrt(1.0 - step.ratio)) <= h / 2.0
    # Measured c/a errors (midpoint) 5.36, 2.16, 1.60 % for h = 0.025, 0.0125, 0.00625; the
    # second-moment estimate of the deficit mu p - |q|, which does not depend on where c falls
    # between two nodes, 2.35, 0.62, 0.16 %.
    errors = [r.c_error for r in results]
    assert errors == sorted(errors, reverse=True)
    deficit_errors = [r.c_deficit_error for r in results]
    assert deficit_errors == sorted(deficit_errors, reverse=True)
    assert results[-1].c_error < 0.02
    assert results[-1].c_deficit_error < 0.005
