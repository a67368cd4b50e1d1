"""A slave body that starts inside the master: pushed out when the search reaches it, else an error.

Two elastic blocks (E = 1000, nu = 0.3), ALM frictionless mortar contact, rollers on x = 0 (and
y = 0 in 3D), the base of the lower block fixed, a pressure P on the top of the upper block. The
upper (slave) block is placed ``depth`` into the lower one. Before issue 16 every depth beyond the
OBB slab (0.1 NODAL_H) gave 0 active nodes: a singular solve or, with the upper block held, a
converged run with the bodies overlapping. Now the slave nodes within the search reach are paired,
activated and pushed out: the final state equals the one of the touching start (depth 0) and the
base reaction equals the applied load. Deeper than the reach, the run stops with an InputError
naming the nodes, the depth and search_factor (CLI: exit code 2).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from contact_cases import contact_process, problem_data, roller, static_contact_solver, top_load
from patch_meshes import Mdpa, box, faces_on, quad_block

import contact_app as ca
from contact_app.analysis import StructuralMechanicsAnalysis
from contact_app.analysis.reporting import Reporter
from contact_app.cli import main as cli_main
from contact_app.parameters import Parameters

PRESSURE = 10.0


def write_case(directory: Path, depth: float, dimension: int) -> Path:
    """Writes mesh, materials and parameters; returns the parameters file."""
    mesh = Mdpa()
    if dimension == 2:
        lower = quad_block((0.0, 0.0), (1.0, 0.5), (3, 2), 1, 1)
        upper = quad_block((0.0, 0.5 - depth), (1.0, 0.5), (4, 2), 16, 7)
        element, load, axis = "SmallDisplacementElement2D4N", "LineLoadCondition2D2N", 1
        mesh.add_part("Base", lower.where(1, 0))
    else:
        lower = box((0.0, 0.0, 0.0), (1.0, 1.0, 0.5), (3, 3, 2), 1, 1, tetrahedra=False)
        upper = box((0.0, 0.0, 0.5 - depth), (1.0, 1.0, 0.5), (4, 4, 2), 49, 19, tetrahedra=False)
        element, load, axis = "SmallDisplacementElement3D8N", "SurfaceLoadCondition3D4N", 2
        mesh.add_part("Base", lower.where(2, 0))
    law = "LinearElasticPlaneStrain2DLaw" if dimension == 2 else "LinearElastic3DLaw"
    mesh.add_body("Lower", element, lower, 0)
    mesh.add_body("Upper", element, upper, 0)
    mesh.add_conditions("Top_Load", load, faces_on(upper, axis, -1))
    mesh.add_part("Contact_Slave", upper.where(axis, 0))
    mesh.add_part("Contact_Master", lower.where(axis, -1))
    mesh.add_part("Roller_X", lower.where(0, 0) + upper.where(0, 0))
    constraints = [roller("Roller_X", (0,)), roller("Base", (0, 1, 2))]
    if dimension == 3:
        mesh.add_part("Roller_Y", lower.where(1, 0) + upper.where(1, 0))
        constraints.append(roller("Roller_Y", (1,)))
    mesh.write(directory / "case.mdpa")
    variables = {"YOUNG_MODULUS": 1000.0, "POISSON_RATIO": 0.3, "DENSITY": 1.0}
    materials = [
        {
            "model_part_name": f"Structure.{name}",
            "properties_id": index + 1,
            "Material": {"constitutive_law": {"name": law}, "Variables": variables, "Tables": {}},
        }
        for index, name in enumerate(("Lower", "Upper"))
    ]
    (directory / "materials.json").write_text(json.dumps({"properties": materials}))
    direction = [0.0, 0.0, 0.0]
    direction[axis] = -1.0
    parameters = {
        "problem_data": problem_data("penetration", 1.0),
        "solver_settings": static_contact_solver(
            directory,
            "case",
            dimension,
            "ALMContactFrictionless",
            max_iteration=30,
            residual_relative_tolerance=1e-10,
            residual_absolute_tolerance=1e-12,
            displacement_relative_tolerance=1e-10,
            displacement_absolute_tolerance=1e-12,
            linear_solver_settings={"solver_type": "skyline_lu_factorization"},
        ),
        "processes": {
            "constraints_process_list": constraints,
            "loads_process_list": [
                top_load("LINE_LOAD" if dimension == 2 else "SURFACE_LOAD", PRESSURE, direction)
            ],
            "contact_process_list": [contact_process("alm_contact_process", "Frictionless")],
        },
        "output_processes": {},
    }
    path = directory / "ProjectParameters.json"
    path.write_text(json.dumps(parameters, indent=1))
    return path


def run_case(directory: Path, depth: float, dimension: int) -> dict:
    """Runs the case; returns the slave/master surface heights, active count and base reaction."""
    path = write_case(directory, depth, dimension)
    analysis = StructuralMechanicsAnalysis(
        ca.Model(),
        Parameters(path.read_text()),
        reporter=Reporter(quiet=True),
        stop_on_non_convergence=True,
    )
    analysis.Run()
    structure = analysis.model["Structure"]
    axis = dimension - 1
    displacement = (ca.DISPLACEMENT_X, ca.DISPLACEMENT_Y, ca.DISPLACEMENT_Z)[axis]
    reaction = (ca.REACTION_X, ca.REACTION_Y, ca.REACTION_Z)[axis]

    def heights(part: str) -> np.ndarray:
        nodes = structure.GetSubModelPart(part).Nodes
        return np.array(
            [(n.X0, n.Y0, n.Z0)[axis] + n.GetSolutionStepValue(displacement) for n in nodes]
        )

    slave = structure.GetSubModelPart("Contact_Slave")
    return {
        "slave": heights("Contact_Slave"),
        "master": heights("Contact_Master"),
        "active": sum(1 for n in slave.Nodes if n.Is(ca.ACTIVE)),
        "slave_nodes": slave.NumberOfNodes(),
        "reaction": sum(
            n.GetSolutionStepValue(reaction) for n in structure.GetSubModelPart("Base").Nodes
        ),
    }


@pytest.mark.parametrize(("dimension", "depth"), [(2, 0.1), (2, 0.3), (3, 0.2), (3, 0.5)])
def test_penetrating_slave_block_is_pushed_out(
    tmp_path: Path, dimension: int, depth: float
) -> None:
    for name in ("touching", "inside"):
        (tmp_path / name).mkdir()
    touching = run_case(tmp_path / "touching", 0.0, dimension)
    inside = run_case(tmp_path / "inside", depth, dimension)
    assert inside["active"] == inside["slave_nodes"]
    # Final gap ~ 0 (the ALM leaves about P / penalty: 9e-6 in 2D, 1.4e-5 in 3D, for depths up to
    # 0.5), as from a touching start (within 2 %): the slave block is pushed back by `depth`.
    gap = inside["slave"].mean() - inside["master"].mean()
    touching_gap = touching["slave"].mean() - touching["master"].mean()
    assert abs(gap) < 1e-4
    assert gap == pytest.approx(touching_gap, rel=5e-2)
    # The master surface ends within 2 % of its displacement (~5e-3) of the touching run's: 3D at
    # depth 0.5 differs by 2e-5 at one node (measured), 2D by 1.4e-6.
    np.testing.assert_allclose(inside["master"], touching["master"], rtol=0, atol=1e-4)
    assert inside["reaction"] == pytest.approx(touching["reaction"], rel=1e-6)
    # The load acts on the current (laterally expanded) top: P times its length / area.
    assert inside["reaction"] == pytest.approx(PRESSURE, rel=1e-2)


def test_penetration_beyond_the_search_reach_is_an_input_error(tmp_path: Path) -> None:
    with pytest.raises(
        ca.InputError, match=r"(?s)5 slave node\(s\).*node 16 at depth 0\.45.*search_factor"
    ):
        run_case(tmp_path, 0.45, 2)


def test_cli_reports_the_too_deep_penetration_with_exit_code_2(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = write_case(tmp_path, 0.45, 2)
    assert cli_main(["run", "--quiet", str(path)]) == 2
    error = capsys.readouterr().err
    assert "start behind the master surface" in error
    assert "raise search_factor to at least" in error
