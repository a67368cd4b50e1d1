"""Pairs reused while a slave surface slides (issue 17, "contact pressure spikes").

The search pairs a slave face with every master face within its search radius, also with the ones
it does not overlap yet, and keeps a pair from step to step while one of its slave nodes is active.
Such a pair is ISOLATED (no overlap) at its first explicit pass and overlaps its master once the
face has slid onto it. The flag used to stay set for the life of the pair: the pair added nothing
to NODAL_AREA nor to the residual, a slave node kept only the slivers of the pairs that happened to
overlap when they were made, and its multiplier (force / NODAL_AREA) grew without bound. On the
sliding cylinders of the reference's example collection (horizontal movement 1) NODAL_AREA fell
to 1e-5 of the tributary area and the largest pressure reached 1.6e5 x the median (Kratos: 3).

Model: an elastic block (tetrahedra) pressed onto a longer base (hexahedra) and slid along it by
prescribed displacements of its top, half a master face per step, ALM frictionless and frictionless
components, search "in_radius" (every master face within the radius is paired, also the ones a
face reaches only in a later step). The base covers the block's bottom face at every step, so the
NODAL_AREA of every slave node must be its whole tributary area, sum over its faces of area / 3 in
the current configuration, and the pressure must stay as smooth as in the first step.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from contact_cases import contact_process, hold_displacement, problem_data, static_contact_solver
from patch_meshes import Mdpa, box

import contact_app as ca
from contact_app.analysis import StructuralMechanicsAnalysis
from contact_app.analysis.reporting import Reporter
from contact_app.parameters import Parameters

#: Block on top (slave bottom face, 4 x 4 cells of two triangles), base below (master, 6 x 4 quads).
BLOCK = ((0.5, 0.0, 0.0), (1.0, 1.0, 0.5), (4, 4, 2))
BASE = ((0.0, -0.5, -0.5), (3.0, 2.0, 0.5), (6, 4, 1))
PRESS = 2.0e-3  # top pushed down by this much
SLIDE = 0.25  # top slid along x by this much per step (half a master face)
STEPS = 4

MORTAR_TYPES = {
    "ALMContactFrictionless": "Frictionless",
    "ALMContactFrictionlessComponents": "FrictionlessComponents",
}


def _write_case(directory: Path) -> None:
    base = box(*BASE, first_node=1, first_element=1, tetrahedra=False)
    block = box(
        *BLOCK,
        first_node=len(base.nodes) + 1,
        first_element=len(base.elements) + 1,
        tetrahedra=True,
    )
    mesh = Mdpa()
    mesh.add_body("Base", "SmallDisplacementElement3D8N", base, 0)
    mesh.add_body("Block", "SmallDisplacementElement3D4N", block, 0)
    mesh.add_part("Contact_Slave", block.where(2, 0))
    mesh.add_part("Contact_Master", base.where(2, -1))
    mesh.add_part("Base_Bottom", base.where(2, 0))
    mesh.add_part("Block_Top", block.where(2, -1))
    mesh.write(directory / "sliding.mdpa")
    material = {
        "model_part_name": "Structure",
        "properties_id": 1,
        "Material": {
            "constitutive_law": {"name": "LinearElastic3DLaw"},
            "Variables": {"YOUNG_MODULUS": 1000.0, "POISSON_RATIO": 0.3, "DENSITY": 1.0},
            "Tables": {},
        },
    }
    (directory / "materials.json").write_text(json.dumps({"properties": [material]}))


def _fix(part: str, value: list) -> dict:
    return hold_displacement(part, [True, True, True], value, interval=[0.0, "End"])


def _parameters(directory: Path, mortar_type: str) -> dict:
    return {
        "problem_data": problem_data("sliding", float(STEPS)),
        "solver_settings": static_contact_solver(
            directory, "sliding", 3, mortar_type, max_iteration=20
        ),
        "processes": {
            "constraints_process_list": [
                _fix("Base_Bottom", [0.0, 0.0, 0.0]),
                _fix("Block_Top", [f"{SLIDE} * (t - 1)", 0.0, -PRESS]),
            ],
            "contact_process_list": [
                contact_process(
                    "alm_contact_process",
                    MORTAR_TYPES[mortar_type],
                    # Every master face within the radius, also the ones the face has not
                    # reached yet (the OBB filter keeps only those its box touches).
                    search_parameters={"type_search": "in_radius"},
                )
            ],
        },
        "output_processes": {},
    }


def _tributary_areas(main: ca.ModelPart) -> dict[int, float]:
    """Sum over the slave faces at a node of area / 3, current coordinates."""
    areas: dict[int, float] = {}
    for condition in main.GetSubModelPart("Contact").Conditions:
        face = condition.GetGeometry()
        if face.NumberOfGeometryParts() != 0 or not condition.Is(ca.SLAVE):
            continue
        points = np.array([[face[i].X, face[i].Y, face[i].Z] for i in range(len(face))])
        area = 0.5 * np.linalg.norm(np.cross(points[1] - points[0], points[2] - points[0]))
        for i in range(len(face)):
            areas[face[i].Id] = areas.get(face[i].Id, 0.0) + area / 3.0
    return areas


class _Recording(StructuralMechanicsAnalysis):
    """Keeps, after every step, the slave nodes' state and the pairs' ISOLATED flags."""

    def __init__(self, *args, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.records: list[dict] = []

    def FinalizeSolutionStep(self) -> None:
        super().FinalizeSolutionStep()
        main = self.model.GetModelPart("Structure")
        tributary = _tributary_areas(main)
        nodes = {
            node.Id: (
                node.GetValue(ca.NODAL_AREA),
                tributary[node.Id],
                -node.GetValue(ca.AUGMENTED_NORMAL_CONTACT_PRESSURE),
                node.Is(ca.ACTIVE),
            )
            for node in main.GetSubModelPart("Contact").Nodes
            if node.Is(ca.SLAVE)
        }
        isolated = {
            pair.Id: pair.Is(ca.ISOLATED)
            for pair in main.GetSubModelPart("ComputingContact").Conditions
        }
        self.records.append({"nodes": nodes, "isolated": isolated})


@pytest.mark.parametrize("mortar_type", list(MORTAR_TYPES))
def test_sliding_block_keeps_its_whole_nodal_area(mortar_type: str, tmp_path: Path) -> None:
    _write_case(tmp_path)
    analysis = _Recording(
        ca.Model(),
        Parameters(json.dumps(_parameters(tmp_path, mortar_type))),
        reporter=Reporter(quiet=True),
    )
    analysis.Run()
    assert len(analysis.records) == STEPS
    assert all(step.converged for step in analysis.reporter.steps)

    # The mechanism is exercised: some pair kept from an earlier step was isolated there (made
    # before its faces overlapped) and is not any more (before the fix it stayed isolated).
    first = analysis.records[0]["isolated"]
    last = analysis.records[-1]["isolated"]
    revived = [pair for pair, flag in first.items() if flag and last.get(pair) is False]
    assert revived, "no pair was reused from isolated to overlapping: the case misses the mechanism"

    ratios = []
    for step, record in enumerate(analysis.records, start=1):
        nodes = record["nodes"]
        assert all(active for *_, active in nodes.values()), f"step {step}: inactive slave nodes"
        area_error = max(abs(area - full) / full for area, full, *_ in nodes.values())
        pressure = np.array([p for _, _, p, _ in nodes.values()])
        ratios.append(pressure.max() / np.median(pressure))
        print(
            f"{mortar_type} step {step}: NODAL_AREA vs tributary area {area_error:.1e}, "
            f"pressure max/median {ratios[-1]:.3f}, min/median "
            f"{pressure.min() / np.median(pressure):.3f}, pairs isolated "
            f"{sum(record['isolated'].values())} of {len(record['isolated'])}"
        )
        assert area_error < 1.0e-4, f"step {step}"
        assert pressure.min() > 0.0, f"step {step}"
    # Sliding leaves the pressure field as smooth as pressing did.
    assert max(ratios) < 1.2 * ratios[0]


def test_sliding_block_on_the_mpc_route_keeps_its_whole_nodal_area(tmp_path: Path) -> None:
    """The multipoint-constraint pairs decide ISOLATED afresh too: NODAL_AREA scales their gap."""
    _write_case(tmp_path)
    parameters = _parameters(tmp_path, "ALMContactFrictionless")
    solver = parameters["solver_settings"]
    del solver["contact_settings"]
    solver["mpc_contact_settings"] = {"contact_type": "Frictionless"}
    solver["convergence_criterion"] = "residual_criterion"
    process = parameters["processes"]["contact_process_list"][0]
    process["python_module"] = "mpc_contact_process"
    process["Parameters"]["contact_type"] = "Frictionless"
    analysis = _Recording(
        ca.Model(), Parameters(json.dumps(parameters)), reporter=Reporter(quiet=True)
    )
    analysis.Run()
    assert all(step.converged for step in analysis.reporter.steps)

    first = analysis.records[0]["isolated"]
    last = analysis.records[-1]["isolated"]
    assert [pair for pair, flag in first.items() if flag and last.get(pair) is False]
    for step, record in enumerate(analysis.records, start=1):
        nodes = record["nodes"]
        assert all(active for *_, active in nodes.values()), f"step {step}: inactive slave nodes"
        area_error = max(abs(area - full) / full for area, full, *_ in nodes.values())
        assert area_error < 1.0e-4, f"step {step}: NODAL_AREA vs tributary area {area_error:.1e}"
