"""3D contact patch test: two stacked boxes, non-matching triangle/quadrilateral interface.

Lower box [0, 1] x [0, 1] x [0, 0.5] (E1 = 1000, nu1 = 0.3), upper box on top of it up to z = 1
(E2 = 3000, nu2 = 0.2); slave = bottom face of the upper box, master = top face of the lower box,
frictionless. Rollers: x = 0 (u_x), y = 0 (u_y) on both boxes, z = 0 (u_z); the faces x = 1 and
y = 1 are free; a uniform pressure p pushes the top (SURFACE_LOAD on SurfaceLoadCondition3D3N/4N).

Exact solution: sigma_zz = -p in both boxes, every other stress component zero; the boxes expand
laterally by nu_i p / E_i and slide against each other:
u = (nu_i p / E_i x, nu_i p / E_i y, u_z) with u_z = -p z / E1 below the interface and
u_z = -p h1 / E1 - p (z - h1) / E2 above it. The contact pressure is p at every slave node.

The contact acts on the nodes' current coordinates. With ``move_mesh_flag`` false those stay the
reference ones and the discrete problem is geometrically linear, which is the setting the exact
solution above belongs to; with the default moving mesh the interface grows by the lateral strain
and the slave face overhangs or not depending on the materials, so the field is exact only to
O(p / E) (measured: 1.5 p / E relative in the pressure at p / E <= 1e-6 with move_mesh_flag true).
Measured here (move_mesh_flag false): pressure 1.4e-12 (i) and 2.1e-12 (ii) relative, displacements
1.6e-13, stresses 1e-13 relative, 6 Newton iterations; tolerance 1e-8 as asked.
"""

from __future__ import annotations

import json
import time
from pathlib import Path

import numpy as np
import pytest
from contact_cases import contact_process, problem_data, roller, static_contact_solver, top_load
from patch_meshes import Mdpa, box, faces_on

import contact_app as ca
from contact_app.analysis import StructuralMechanicsAnalysis
from contact_app.analysis.reporting import Reporter
from contact_app.parameters import Parameters

PRESSURE = 10.0
LOWER = (1000.0, 0.3)  # E, nu
UPPER = (3000.0, 0.2)
HEIGHT_LOWER = 0.5
HEIGHT_UPPER = 0.5
#: In-plane and vertical divisions: the slave face has 4 x 4 cells, the master face 3 x 3.
UPPER_DIVISIONS = (4, 4, 2)
LOWER_DIVISIONS = (3, 3, 2)
RELATIVE_TOLERANCE = 1.0e-8

MORTAR_TYPES = {
    "ALMContactFrictionless": "Frictionless",
    "ALMContactFrictionlessComponents": "FrictionlessComponents",
}


def _write_case(directory: Path, upper_tetrahedra: bool) -> None:
    lower = box(
        (0.0, 0.0, 0.0),
        (1.0, 1.0, HEIGHT_LOWER),
        LOWER_DIVISIONS,
        1,
        1,
        tetrahedra=not upper_tetrahedra,
    )
    upper = box(
        (0.0, 0.0, HEIGHT_LOWER),
        (1.0, 1.0, HEIGHT_UPPER),
        UPPER_DIVISIONS,
        len(lower.nodes) + 1,
        len(lower.elements) + 1,
        tetrahedra=upper_tetrahedra,
    )
    mesh = Mdpa()
    for name, body, tetrahedra in (
        ("Lower", lower, not upper_tetrahedra),
        ("Upper", upper, upper_tetrahedra),
    ):
        element = "SmallDisplacementElement3D4N" if tetrahedra else "SmallDisplacementElement3D8N"
        mesh.add_body(name, element, body, 0)
    load = "SurfaceLoadCondition3D3N" if upper_tetrahedra else "SurfaceLoadCondition3D4N"
    mesh.add_conditions("Top_Load", load, faces_on(upper, 2, -1))
    mesh.add_part("Contact_Slave", upper.where(2, 0))
    mesh.add_part("Contact_Master", lower.where(2, -1))
    mesh.add_part("Roller_X", lower.where(0, 0) + upper.where(0, 0))
    mesh.add_part("Roller_Y", lower.where(1, 0) + upper.where(1, 0))
    mesh.add_part("Roller_Z", lower.where(2, 0))
    mesh.write(directory / "patch_3d.mdpa")
    materials = [
        {
            "model_part_name": f"Structure.{name}",
            "properties_id": index + 1,
            "Material": {
                "constitutive_law": {"name": "LinearElastic3DLaw"},
                "Variables": {"YOUNG_MODULUS": young, "POISSON_RATIO": poisson, "DENSITY": 1.0},
                "Tables": {},
            },
        }
        for index, (name, (young, poisson)) in enumerate((("Lower", LOWER), ("Upper", UPPER)))
    ]
    (directory / "materials.json").write_text(json.dumps({"properties": materials}))


def _parameters(directory: Path, mortar_type: str) -> dict:
    return {
        "problem_data": problem_data("patch_3d", 1.0),
        "solver_settings": static_contact_solver(
            directory,
            "patch_3d",
            3,
            mortar_type,
            move_mesh_flag=False,
            residual_relative_tolerance=1.0e-12,
            residual_absolute_tolerance=1.0e-14,
            displacement_relative_tolerance=1.0e-12,
            displacement_absolute_tolerance=1.0e-14,
            max_iteration=20,
            linear_solver_settings={"solver_type": "skyline_lu_factorization"},
        ),
        "processes": {
            "constraints_process_list": [
                roller("Roller_X", (0,)),
                roller("Roller_Y", (1,)),
                roller("Roller_Z", (2,)),
            ],
            "loads_process_list": [top_load("SURFACE_LOAD", PRESSURE, [0.0, 0.0, -1.0])],
            "contact_process_list": [
                contact_process("alm_contact_process", MORTAR_TYPES[mortar_type])
            ],
        },
        "output_processes": {},
    }


def _exact_displacement(point: np.ndarray, upper: bool) -> np.ndarray:
    young, poisson = UPPER if upper else LOWER
    lateral = poisson * PRESSURE / young
    if upper:
        vertical = (
            -PRESSURE * HEIGHT_LOWER / LOWER[0] - PRESSURE * (point[2] - HEIGHT_LOWER) / young
        )
    else:
        vertical = -PRESSURE * point[2] / young
    return np.array([lateral * point[0], lateral * point[1], vertical])


def _values(node, variables) -> np.ndarray:
    return np.array([node.GetSolutionStepValue(v) for v in variables])


@pytest.mark.parametrize("mortar_type", list(MORTAR_TYPES))
@pytest.mark.parametrize(
    "upper_tetrahedra", [True, False], ids=["tri_slave_on_quad_master", "quad_slave_on_tri_master"]
)
def test_patch_3d_mixed_faces_transmits_uniform_pressure(
    upper_tetrahedra: bool, mortar_type: str, tmp_path: Path
) -> None:
    _write_case(tmp_path, upper_tetrahedra)
    analysis = StructuralMechanicsAnalysis(
        ca.Model(),
        Parameters(json.dumps(_parameters(tmp_path, mortar_type))),
        reporter=Reporter(quiet=True),
    )
    start = time.perf_counter()
    analysis.Run()
    wall = time.perf_counter() - start
    (step,) = analysis.reporter.steps
    assert step.converged

    model = analysis.model
    main = model.GetModelPart("Structure")
    info = main.ProcessInfo
    slave = list(model.GetModelPart("Structure.Contact_Slave").Nodes)
    assert len(slave) == (UPPER_DIVISIONS[0] + 1) * (UPPER_DIVISIONS[1] + 1)
    assert all(node.Is(ca.ACTIVE) for node in slave)

    # Contact pressure at every slave node: the augmented pressure and the multiplier (the
    # multiplier DoF is the pressure divided by SCALE_FACTOR).
    scale = info.GetValue(ca.SCALE_FACTOR)
    augmented = np.array([node.GetValue(ca.AUGMENTED_NORMAL_CONTACT_PRESSURE) for node in slave])
    if mortar_type == "ALMContactFrictionless":
        multiplier = np.array(
            [
                scale * node.GetSolutionStepValue(ca.LAGRANGE_MULTIPLIER_CONTACT_PRESSURE)
                for node in slave
            ]
        )
        multiplier_error = np.abs(multiplier + PRESSURE).max() / PRESSURE
    else:
        # k lambda = -p n: normal part -p, tangential part zero.
        vector = (
            ca.VECTOR_LAGRANGE_MULTIPLIER_X,
            ca.VECTOR_LAGRANGE_MULTIPLIER_Y,
            ca.VECTOR_LAGRANGE_MULTIPLIER_Z,
        )
        normals = ca.NORMAL_X, ca.NORMAL_Y, ca.NORMAL_Z
        multiplier_error = (
            max(
                np.abs(scale * _values(node, vector) + PRESSURE * _values(node, normals)).max()
                for node in slave
            )
            / PRESSURE
        )
    pressure_error = np.abs(augmented + PRESSURE).max() / PRESSURE

    upper_ids = {node.Id for node in model.GetModelPart("Structure.Upper").Nodes}
    displacement = ca.DISPLACEMENT_X, ca.DISPLACEMENT_Y, ca.DISPLACEMENT_Z
    exact = {
        node.Id: _exact_displacement(np.array([node.X0, node.Y0, node.Z0]), node.Id in upper_ids)
        for node in main.Nodes
    }
    largest = max(np.abs(u).max() for u in exact.values())
    displacement_error = (
        max(np.abs(_values(node, displacement) - exact[node.Id]).max() for node in main.Nodes)
        / largest
    )

    expected_stress = np.array([0.0, 0.0, -PRESSURE, 0.0, 0.0, 0.0])
    stress_error = (
        max(
            np.abs(np.asarray(stress) - expected_stress).max()
            for element in main.Elements
            for stress in element.CalculateOnIntegrationPoints(ca.CAUCHY_STRESS_VECTOR, info)
        )
        / PRESSURE
    )
    print(
        f"{mortar_type}, {'tri on quad' if upper_tetrahedra else 'quad on tri'}: "
        f"{step.iterations} Newton iterations, {wall:.2f} s; relative errors: augmented pressure "
        f"{pressure_error:.2e}, multiplier {multiplier_error:.2e}, displacement "
        f"{displacement_error:.2e}, stress {stress_error:.2e}"
    )
    assert pressure_error < RELATIVE_TOLERANCE
    assert multiplier_error < RELATIVE_TOLERANCE
    assert displacement_error < RELATIVE_TOLERANCE
    assert stress_error < RELATIVE_TOLERANCE
